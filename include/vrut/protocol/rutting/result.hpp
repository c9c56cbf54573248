#pragma once
/// \file
/// What the rutting test measures: the deformation curve, the snapshots,
/// and the rut depth and dynamic stability worked out from the curve.
#include <vrut/protocol/rutting/skeleton_record.hpp>
#include <vrut/protocol/rutting/test.hpp>
#include <vrut/protocol/rutting/timestep_report.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace vrut {

struct RuttingSample {
  double minutes = 0.0, reduced_time = 0.0, deformation = 0.0 /* m */;
  double plate_pressure = 0.0;  // Pa, mean over the interval since the previous sample
  double plate_speed = 0.0;     // m/s, the plate's into the specimen at the sample
};

struct RuttingSnapshot {
  double fraction = 0.0;             // of the loading time
  std::vector<double> x, y, dx, dy;  // m: positions and displacement since loading began
};

struct RuttingResult {
  std::vector<RuttingSample> samples;
  std::vector<RuttingSnapshot> snapshots;  // at 1/3, 2/3 and the end of the loading
  std::vector<double> vx, vy;              // final velocities
  std::vector<int> group;
  double deformation_at_ds_start = 0.0, deformation_final = 0.0;  // m
  double dynamic_stability = 0.0;          // passes / mm
  /// The smallest deformation change over the DS window that the curve
  /// resolves (m; finish_deformation). Where the change is below it, the DS
  /// is reported as a lower bound, as a laboratory reports a DS past its
  /// gauge: dynamic_stability is then the DS that change would give.
  double deformation_resolution = 0.0;
  bool dynamic_stability_is_lower_bound = false;
  double plate_x0 = 0.0, plate_x1 = 0.0, plate_y_final = 0.0;     // m
  /// The plate's mass (kg): with its speed at two samples and the pressures
  /// between them, its momentum balance (the dead load's impulse less the
  /// contacts', over the interval, is its change of momentum).
  double plate_mass = 0.0;
  std::size_t particles = 0;
  int contacts = 0, bonds = 0;
  /// At the end: the stones holding disks, and the pairs of them that touch
  /// (some disk of one overlaps some disk of the other): the skeleton.
  int stones = 0, stone_pairs_touching = 0;
  SkeletonRecord skeleton;                 // what holds the specimen up (protocol/rutting/skeleton.hpp)
  bool interrupted = false;                // stopped early on request: the samples so far, no DS
  long steps = 0;
  double dt = 0.0, wall_seconds = 0.0;
  TimestepReport time_step;  // which class of contact sets dt (before the safety factor), and the next

  /// Stones touching per stone at the end: each touching pair counts for both.
  double stones_touching_per_stone() const {
    return stones > 0 ? 2.0 * stone_pairs_touching / stones : std::numeric_limits<double>::quiet_NaN();
  }
  /// The share of the final rut that came after the DS window's start (minute
  /// 45 of 60): (d60 - d45) / d60, the curve's late creep.
  double late_creep_share() const {
    return deformation_final > 0.0 ? (deformation_final - deformation_at_ds_start) / deformation_final
                                   : std::numeric_limits<double>::quiet_NaN();
  }
};

/// Deformation at the DS start minute (interpolated), at the end, and the DS
/// (method.md section 1: the passes between the DS start and the end over the
/// deformation between them).
///
/// The resolution: the plate jitters about the curve's trend (its dead load
/// and the disks under it vibrate a little). The DS is a difference of two
/// points of the curve, each off the trend by about s, the residual standard
/// deviation of a least-squares line through the samples in the DS window; so
/// a change below 2 sqrt(2) s (two standard deviations of a difference) is
/// not resolved, and the DS is reported as above the value such a change
/// gives. Fewer than three samples in the window: no resolution is known (0).
inline void finish_deformation(RuttingResult& res, const WheelTracking& wt) {
  auto deformation_at = [&](double minute) {
    for (std::size_t k = 1; k < res.samples.size(); ++k)
      if (res.samples[k].minutes >= minute) {
        const auto& a = res.samples[k - 1];
        const auto& b = res.samples[k];
        return a.deformation + (minute - a.minutes) / (b.minutes - a.minutes) * (b.deformation - a.deformation);
      }
    return res.samples.back().deformation;
  };
  res.dynamic_stability_is_lower_bound = false;
  res.deformation_resolution = 0.0;
  if (res.samples.empty()) {
    res.deformation_at_ds_start = res.deformation_final = 0.0;
    res.dynamic_stability = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  res.deformation_at_ds_start = deformation_at(wt.ds_from_minute);
  res.deformation_final = res.samples.back().deformation;
  // A run stopped before the end of the test has no DS.
  if (res.interrupted) {
    res.dynamic_stability = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  double n = 0.0, st = 0.0, sd = 0.0;
  for (const auto& smp : res.samples)
    if (smp.minutes >= wt.ds_from_minute * (1.0 - 1e-9)) n += 1.0, st += smp.minutes, sd += smp.deformation;
  if (n >= 3.0) {
    const double t_mean = st / n, d_mean = sd / n;
    double stt = 0.0, std_ = 0.0;
    for (const auto& smp : res.samples)
      if (smp.minutes >= wt.ds_from_minute * (1.0 - 1e-9)) {
        stt += (smp.minutes - t_mean) * (smp.minutes - t_mean);
        std_ += (smp.minutes - t_mean) * (smp.deformation - d_mean);
      }
    const double slope = stt > 0.0 ? std_ / stt : 0.0;
    double residuals = 0.0;
    for (const auto& smp : res.samples)
      if (smp.minutes >= wt.ds_from_minute * (1.0 - 1e-9)) {
        const double r = smp.deformation - (d_mean + slope * (smp.minutes - t_mean));
        residuals += r * r;
      }
    res.deformation_resolution = 2.0 * std::sqrt(2.0) * std::sqrt(residuals / (n - 2.0));
  }
  const double passes = wt.ds_window_passes();
  const double dd_mm = (res.deformation_final - res.deformation_at_ds_start) * 1e3;
  const double resolution_mm = res.deformation_resolution * 1e3;
  if (resolution_mm > 0.0 && dd_mm < resolution_mm) {
    res.dynamic_stability_is_lower_bound = true;
    res.dynamic_stability = passes / resolution_mm;
  } else {
    res.dynamic_stability = dd_mm > 0.0 ? passes / dd_mm : std::numeric_limits<double>::infinity();
  }
}

}  // namespace vrut
