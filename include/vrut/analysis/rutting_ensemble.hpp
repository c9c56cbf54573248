#pragma once
// What an ensemble of rutting runs says about a mix: statistics over the
// specimens of the rut depth, the deformations at the DS window's ends and the
// DS, and the mean deformation curve with its own DS (robust where single
// specimens barely deform in the DS window). Host-only.
#include <vrut/analysis/statistics.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/test.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vrut {

struct RuttingEnsembleSummary {
  SampleStatistics rut_depth, deformation_at_ds_start, deformation_final, dynamic_stability;  // mm, passes/mm
  // The DS's geometric mean and its interval, which stays positive where the
  // arithmetic mean's Student-t interval can reach below zero.
  GeometricStatistics dynamic_stability_geometric;
  RuttingResult mean_curve;  // samples: mean deformation and pressure; its DS from that curve
  std::vector<double> deformation_sd;  // m, standard deviation at each sample (0 for one specimen)
  std::vector<double> deformation_ci_low, deformation_ci_high;  // m, of the mean at each sample
  // Specimens whose DS is only a lower bound (RuttingResult). With any, the
  // mean and its interval are lower bounds too; the median is one where a
  // bound sorts at or below the middle (median_is_lower_bound).
  int dynamic_stability_lower_bounds = 0;
  bool dynamic_stability_median_is_lower_bound = false;
};

// Whether the median of DS values, each (value, only a lower bound), is only
// a lower bound: where a bound sorts at or below the middle (the upper of
// the two middle values for an even count), since its true value may lie
// above the middle and lift the median. A bound above the middle cannot.
inline bool median_is_lower_bound(std::vector<std::pair<double, bool>> values) {
  if (values.empty()) throw std::invalid_argument("the median of no values");
  std::sort(values.begin(), values.end());
  for (std::size_t i = 0; i <= values.size() / 2; ++i)
    if (values[i].second) return true;
  return false;
}

inline RuttingEnsembleSummary summarize_rutting(const std::vector<RuttingResult>& runs, const WheelTracking& wt,
                                                double confidence = 0.95) {
  if (runs.empty()) throw std::invalid_argument("an ensemble summary needs at least one run");
  const std::size_t samples = runs.front().samples.size();
  for (const auto& r : runs)
    if (r.samples.size() != samples) throw std::invalid_argument("the runs of an ensemble have different sample counts");
  RuttingEnsembleSummary out;
  std::vector<double> rut, d45, d60, ds;
  for (const auto& r : runs) {
    rut.push_back(r.deformation_final * 1e3);
    d45.push_back(r.deformation_at_ds_start * 1e3);
    d60.push_back(r.deformation_final * 1e3);
    ds.push_back(r.dynamic_stability);
  }
  out.rut_depth = describe(rut, confidence);
  out.deformation_at_ds_start = describe(d45, confidence);
  out.deformation_final = describe(d60, confidence);
  out.dynamic_stability = describe(ds, confidence);
  out.dynamic_stability_geometric = describe_geometric(ds, confidence);
  std::vector<std::pair<double, bool>> values;
  for (const auto& r : runs) {
    values.emplace_back(r.dynamic_stability, r.dynamic_stability_is_lower_bound);
    out.dynamic_stability_lower_bounds += r.dynamic_stability_is_lower_bound ? 1 : 0;
  }
  out.dynamic_stability_median_is_lower_bound = median_is_lower_bound(values);
  out.mean_curve.samples = runs.front().samples;
  out.mean_curve.interrupted = runs.front().interrupted;
  for (std::size_t k = 0; k < samples; ++k) {
    std::vector<double> d;
    double pressure = 0.0;
    for (const auto& r : runs) {
      d.push_back(r.samples[k].deformation);
      pressure += r.samples[k].plate_pressure / runs.size();
    }
    const SampleStatistics s = describe(d, confidence);
    out.mean_curve.samples[k].deformation = s.mean;
    out.mean_curve.samples[k].plate_pressure = pressure;
    out.deformation_sd.push_back(runs.size() > 1 ? s.sd : 0.0);
    out.deformation_ci_low.push_back(runs.size() > 1 ? s.ci_low : s.mean);
    out.deformation_ci_high.push_back(runs.size() > 1 ? s.ci_high : s.mean);
  }
  finish_deformation(out.mean_curve, wt);
  return out;
}

}  // namespace vrut
