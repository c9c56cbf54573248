#pragma once
// vrut-rutting's report of a run or an ensemble, in 2D and 3D alike: the
// curve (deformation.csv and .png), each specimen's numbers (seeds.csv), the
// ensemble's part of summary.json, and the line printed at the end.
#include "ranks.hpp"
#include "seeds.hpp"
#include "rutting_outputs.hpp"
#include "skeleton_report.hpp"

#include <vrut/analysis/rutting_ensemble.hpp>
#include <vrut/analysis/seeds_csv.hpp>
#include <vrut/analysis/standard_ds.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/plot.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/test.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace vrut::app {

// The runs' numbers as the report gives them: the ensemble's statistics,
// each DS as the standard reports it, their median with the censored ones
// counted as censored (Kaplan-Meier), and the 95 % intervals.
struct RuttingReport {
  vrut::RuttingEnsembleSummary summary;
  std::vector<vrut::ReportedDS> reported;
  vrut::ReportedDS mean_curve, median;
  vrut::MedianInterval median_ci;
  vrut::DSInterval mean_curve_ci;
  bool intervals = false;  // an ensemble of at least two, run to the end
};

inline RuttingReport report_runs(const std::vector<vrut::RuttingResult>& runs, const vrut::WheelTracking& wt, bool ensemble,
                          bool interrupted) {
  RuttingReport r;
  r.summary = vrut::summarize_rutting(runs, wt);
  for (const auto& run : runs)
    r.reported.push_back(interrupted ? vrut::ReportedDS{0.0, true}
                                     : vrut::report_ds(run.dynamic_stability, run.dynamic_stability_is_lower_bound));
  r.mean_curve = interrupted ? vrut::ReportedDS{0.0, true}
                             : vrut::report_ds(r.summary.mean_curve.dynamic_stability,
                                               r.summary.mean_curve.dynamic_stability_is_lower_bound);
  r.median = vrut::censored_median(r.reported);
  // The median's interval from the order statistics, the mean curve's from
  // the mean window deformation (analysis/standard_ds.hpp).
  r.median_ci = vrut::median_interval(r.reported);
  std::vector<double> window_mm;
  for (const auto& run : runs) window_mm.push_back((run.deformation_final - run.deformation_at_ds_start) * 1e3);
  r.intervals = ensemble && !interrupted && runs.size() >= 2;
  if (r.intervals) r.mean_curve_ci = vrut::mean_curve_ds_interval(window_mm, wt.ds_window_passes());
  return r;
}

// deformation.csv and .png: one specimen's curve, or the ensemble's mean,
// interval and every specimen's curve. title: "Virtual wheel-tracking test, ..."
inline void write_deformation(vrut::OutputDir& output, const std::vector<vrut::RuttingResult>& runs,
                       const RuttingReport& report, const std::vector<std::uint64_t>& seeds, bool ensemble,
                       const std::string& title) {
  const auto& summary = report.summary;
  std::ostringstream csv;
  csv.precision(17);  // every double as it is: files compared bit for bit (resume, MPI) must differ where the runs do
  csv << "minutes,reduced_time_s,deformation_mm,plate_pressure_mpa";
  if (ensemble) {
    csv << ",sd_mm,ci95_low_mm,ci95_high_mm";
    for (auto seed : seeds) csv << ",seed_" << seed << "_mm";
  }
  csv << '\n';
  // The plots start at the origin: the plate is set on the highest particle
  // under it, so the deformation is 0 when the loading starts (and a run
  // stopped after one sample still draws a line, not an empty range).
  std::vector<double> minutes{0.0}, deformation{0.0}, low{0.0}, high{0.0};
  const auto& mean = summary.mean_curve.samples;
  for (std::size_t k = 0; k < mean.size(); ++k) {
    csv << mean[k].minutes << ',' << mean[k].reduced_time << ',' << mean[k].deformation * 1e3 << ','
        << mean[k].plate_pressure * 1e-6;
    if (ensemble) {
      csv << ',' << summary.deformation_sd[k] * 1e3 << ',' << summary.deformation_ci_low[k] * 1e3 << ','
          << summary.deformation_ci_high[k] * 1e3;
      for (const auto& r : runs) csv << ',' << r.samples[k].deformation * 1e3;
    }
    csv << '\n';
    minutes.push_back(mean[k].minutes);
    deformation.push_back(mean[k].deformation * 1e3);
    low.push_back(summary.deformation_ci_low[k] * 1e3);
    high.push_back(summary.deformation_ci_high[k] * 1e3);
  }
  output.write_text("deformation.csv", csv.str());
  vrut::PlotSpec spec;
  spec.xlabel = "test time (min)";
  spec.ylabel = "deformation (mm)";
  std::vector<vrut::PlotSeries> series;
  if (ensemble) {
    spec.title = title + ", " + cli::specimens_text(runs.size());
    vrut::PlotSeries band{"95 % interval of the mean", minutes, low, "filledcurves fs transparent solid 0.3 lc rgb '#4477aa'"};
    band.y2 = high;
    series.push_back(band);
    for (std::size_t e = 0; e < runs.size(); ++e) {
      vrut::PlotSeries one{e == 0 ? "each specimen" : "", {0.0}, {0.0}, "lines lw 1 lc rgb '#bbbbbb'"};
      for (const auto& smp : runs[e].samples) {
        one.x.push_back(smp.minutes);
        one.y.push_back(smp.deformation * 1e3);
      }
      series.push_back(one);
    }
    series.push_back({"mean", minutes, deformation, "lines lw 3 lc rgb '#223388'"});
  } else {
    spec.title = title;
    series.push_back({"rut depth under the plate", minutes, deformation});
  }
  vrut::write_plot_png(output.file("deformation.png").string(), spec, series);
}

// seeds.csv: each specimen's numbers, its skeleton's (skeleton_report.hpp) after them. facts_columns names the particles'
// and stones' columns ("disks,aggregates,aggregate_area_fraction" in 2D);
// images, where given, add the image each specimen came from.
inline void write_seeds_csv(vrut::OutputDir& output, const std::vector<vrut::RuttingResult>& runs, const RuttingReport& report,
                     const std::vector<std::uint64_t>& seeds, const std::vector<ranks::SpecimenFacts>& facts,
                     const std::string& facts_columns, bool interrupted, const std::vector<std::string>& images = {}) {
  std::ostringstream per_seed;
  per_seed.precision(17);
  per_seed << "seed," << facts_columns << ',' << vrut::seeds_csv_result_columns << ',' << skeleton_csv_columns
           << (images.empty() ? "\n" : ",image\n");
  for (std::size_t e = 0; e < runs.size(); ++e) {
    per_seed << seeds[e] << ',' << runs[e].particles << ',' << facts[e].aggregates << ','
             << facts[e].aggregate_area_fraction << ',' << runs[e].deformation_final * 1e3 << ','
             << runs[e].deformation_at_ds_start * 1e3 << ',' << runs[e].deformation_final * 1e3 << ','
             << runs[e].dynamic_stability << ',' << (runs[e].dynamic_stability_is_lower_bound ? 1 : 0) << ','
             << runs[e].deformation_resolution * 1e3 << ',' << runs[e].stones << ','
             << runs[e].stone_pairs_touching << ',' << runs[e].steps << ',';
    if (interrupted)
      per_seed << "nan,nan";  // a run stopped before its end has no DS
    else
      per_seed << report.reported[e].value << ',' << (report.reported[e].censored ? 1 : 0);
    per_seed << ',' << skeleton_csv_cells(runs[e]);
    if (!images.empty()) per_seed << ',' << images[seeds[e] - 1];
    per_seed << '\n';
  }
  output.write_text("seeds.csv", per_seed.str());
}

// summary.json's "ensemble": the statistics over the specimens, the
// standard's DS values with their intervals, and each seed's numbers.
// particles: what each specimen's particles are called ("disks", "spheres").
inline nlohmann::json ensemble_json(const std::vector<vrut::RuttingResult>& runs, const RuttingReport& report,
                             const std::vector<std::uint64_t>& seeds, const std::vector<ranks::SpecimenFacts>& facts,
                             bool interrupted, const std::string& particles) {
  const auto& summary = report.summary;
  nlohmann::json e;
  e["seeds"] = seeds;
  e["specimens"] = runs.size();
  e["rut_depth_mm"] = statistics_json(summary.rut_depth);
  e["deformation_45min_mm"] = statistics_json(summary.deformation_at_ds_start);
  e["deformation_60min_mm"] = statistics_json(summary.deformation_final);
  e["dynamic_stability_passes_per_mm"] = statistics_json(summary.dynamic_stability);
  e["dynamic_stability_of_mean_curve"] = summary.mean_curve.dynamic_stability;
  e["dynamic_stability_lower_bounds"] = summary.dynamic_stability_lower_bounds;
  e["dynamic_stability_median_is_lower_bound"] = summary.dynamic_stability_median_is_lower_bound;
  // The standard's values: the median with capped and unresolved DS
  // as censored (Kaplan-Meier), and the mean curve's DS.
  if (!interrupted) {
    e["dynamic_stability_standard_median"] = standard_ds_json(report.median);
    e["dynamic_stability_standard_of_mean_curve"] = standard_ds_json(report.mean_curve);
    if (report.intervals && report.median_ci.defined)
      e["dynamic_stability_standard_median_ci95"] = {{"low", standard_ds_json(report.median_ci.low)},
                                                     {"high", standard_ds_json(report.median_ci.high)},
                                                     {"coverage", report.median_ci.coverage}};
    if (report.intervals)
      e["dynamic_stability_standard_of_mean_curve_ci95"] = {{"low", standard_ds_json(report.mean_curve_ci.low)},
                                                            {"high", standard_ds_json(report.mean_curve_ci.high)}};
  }
  nlohmann::json per = nlohmann::json::array();
  for (std::size_t k = 0; k < runs.size(); ++k)
    per.push_back({{"seed", seeds[k]},
                   {particles, runs[k].particles},
                   {"rut_depth_mm", runs[k].deformation_final * 1e3},
                   {"deformation_45min_mm", runs[k].deformation_at_ds_start * 1e3},
                   {"dynamic_stability_passes_per_mm", runs[k].dynamic_stability},
                   {"dynamic_stability_is_lower_bound", runs[k].dynamic_stability_is_lower_bound},
                   {"dynamic_stability_standard", standard_ds_json(report.reported[k])},
                   {"rank", facts[k].rank}});  // the MPI rank that ran it
  e["per_seed"] = per;
  return e;
}

// summary.json's keys that the 2D and the 3D run share: the skeleton at the
// end, of the first specimen (stones, the pairs of them touching, touching
// neighbours per stone: 2 pairs / stones); the steps; the means over the
// specimens (the DS: of the mean curve); whether the run was stopped.
template <class RunFacts>
void add_shared_summary(nlohmann::json& j, const RunFacts& res, const RuttingReport& report, bool interrupted,
                        double minutes_done) {
  j["bonds"] = res.bonds;
  j["contacts"] = res.contacts;
  j["stones"] = res.stones;
  j["stone_pairs_touching"] = res.stone_pairs_touching;
  j["stone_neighbours_per_stone"] = res.stones > 0 ? 2.0 * res.stone_pairs_touching / res.stones : 0.0;
  j["steps"] = res.steps;
  j["reduced_dt_s"] = res.dt;
  // Which class of contact sets the step, and how far the next trails it
  // (their sqrt(m / k), before the safety factor; protocol/rutting/timestep_report.hpp).
  if (res.time_step.known())
    j["time_step"] = {{"set_by", res.time_step.set_by},
                      {"sqrt_m_over_k_s", res.time_step.step},
                      {"next", res.time_step.next.empty() ? nlohmann::json(nullptr) : nlohmann::json(res.time_step.next)},
                      {"next_over_set", res.time_step.next.empty() ? nlohmann::json(nullptr)
                                                                   : nlohmann::json(res.time_step.next_step / res.time_step.step)}};
  const auto& summary = report.summary;
  j["deformation_45min_mm"] = summary.deformation_at_ds_start.mean;
  j["deformation_60min_mm"] = summary.deformation_final.mean;
  j["rut_depth_mm"] = summary.rut_depth.mean;
  j["dynamic_stability_passes_per_mm"] = summary.mean_curve.dynamic_stability;
  // Where the 45-60 min deformation is below what the curve resolves, the DS
  // is a lower bound: "above" the value given.
  j["dynamic_stability_is_lower_bound"] = summary.mean_curve.dynamic_stability_is_lower_bound;
  j["deformation_resolution_mm"] = summary.mean_curve.deformation_resolution * 1e3;
  // As JTG E20 T0719 writes it: capped at 6000 ("> 6000").
  if (!interrupted) j["dynamic_stability_standard"] = standard_ds_json(report.mean_curve);
  j["interrupted"] = interrupted;
  j["minutes_done"] = minutes_done;
}

// The line printed at the end of a run that went to its end: what was run,
// the rut depth and DS (an ensemble's statistics and intervals), and how
// fast (`speed`: particles, steps, seconds).
inline void print_result(const std::string& what_was_run, const std::vector<vrut::RuttingResult>& runs,
                  const RuttingReport& report, const vrut::WheelTracking& wt, bool ensemble, const std::string& speed,
                  const std::string& out, const std::string& note = "") {
  // A DS that is only a lower bound reads "above N", as a laboratory writes it.
  auto ds_text = [](double ds, bool lower_bound) {
    char text[64];
    std::snprintf(text, sizeof text, "%s%.0f", lower_bound ? "above " : "", ds);
    return std::string(text);
  };
  const auto& standard_text = vrut::reported_ds_text;  // "> 6000" past the cap, ours "above N"
  const auto& summary = report.summary;
  const vrut::RuttingResult& res = runs.front();
  if (ensemble) {
    const auto& r = summary.rut_depth;
    const auto& d = summary.dynamic_stability;
    const bool any_bound = summary.dynamic_stability_lower_bounds > 0;
    // One seed (--seeds 4, to be pooled with other runs by vrut-pool) has
    // no spread: say so rather than print nan.
    const bool spread = r.n > 1;
    char rut_spread[96] = "one specimen, no interval";
    if (spread) std::snprintf(rut_spread, sizeof rut_spread, "sd %.2f, 95 %% CI %.2f to %.2f", r.sd, r.ci_low, r.ci_high);
    // The DS is positive and spreads by factors: its interval is the
    // geometric mean's, taken in the logarithms (analysis/statistics.hpp),
    // which stays above zero where the arithmetic mean's need not.
    const auto& g = summary.dynamic_stability_geometric;
    const std::string ds_mean =
        !spread     ? ds_text(d.mean, any_bound) + " (no interval)"
        : any_bound ? ds_text(d.mean, true) + " (95 % CI not known)"
                    : ds_text(d.mean, false) + ", geometric mean " + ds_text(g.mean, false) + " (95 % CI " +
                          ds_text(g.ci_low, false) + " to " + ds_text(g.ci_high, false) + ")";
    std::printf("%s, %s: rut depth %.2f mm at %.0f min (%s), "
                "dynamic stability: mean %s, median %s, of the mean curve %s passes/mm",
                what_was_run.c_str(), cli::specimens_text(r.n).c_str(), r.mean, wt.minutes, rut_spread,
                ds_mean.c_str(),
                ds_text(d.median, summary.dynamic_stability_median_is_lower_bound).c_str(),
                ds_text(summary.mean_curve.dynamic_stability, summary.mean_curve.dynamic_stability_is_lower_bound).c_str());
    if (any_bound)
      std::printf("; %d of %d specimens deform less from minute %.0f to %.0f than their curves resolve, so their DS "
                  "are lower bounds (seeds.csv)",
                  summary.dynamic_stability_lower_bounds, r.n, wt.ds_from_minute, wt.minutes);
    auto interval_text = [&](const vrut::ReportedDS& low, const vrut::ReportedDS& high) {
      return " (95 % interval " + standard_text(low) + " to " + standard_text(high) + ")";
    };
    std::printf("; as the standard reports it (capped at %.0f): median %s%s (censored values counted as such), of "
                "the mean curve %s%s passes/mm",
                vrut::standard_ds_cap, standard_text(report.median).c_str(),
                report.median_ci.defined ? interval_text(report.median_ci.low, report.median_ci.high).c_str() : "",
                standard_text(report.mean_curve).c_str(),
                report.intervals ? interval_text(report.mean_curve_ci.low, report.mean_curve_ci.high).c_str() : "");
  } else {
    std::printf("%s: rut depth %.2f mm at %.0f min, dynamic stability %s passes/mm", what_was_run.c_str(),
                res.deformation_final * 1e3, wt.minutes,
                ds_text(res.dynamic_stability, res.dynamic_stability_is_lower_bound).c_str());
    if (res.dynamic_stability_is_lower_bound)
      std::printf(" (from minute %.0f to %.0f the plate sank %.4f mm, less than the %.4f mm its curve resolves)",
                  wt.ds_from_minute, wt.minutes, (res.deformation_final - res.deformation_at_ds_start) * 1e3,
                  res.deformation_resolution * 1e3);
    std::printf(", as the standard reports it %s", standard_text(report.mean_curve).c_str());
  }
  std::printf(" (%s%s)\n", speed.c_str(), note.c_str());
  if (res.time_step.known()) {
    std::printf("time step %.3g s (reduced), set by the %s contacts", res.dt, res.time_step.set_by.c_str());
    if (!res.time_step.next.empty())
      std::printf("; the next, %s, would allow %.2f times as long", res.time_step.next.c_str(),
                  res.time_step.next_step / res.time_step.step);
    std::printf("\n");
  }
  std::printf("results in %s\n", out.c_str());
}

}  // namespace vrut::app
