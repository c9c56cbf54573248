#pragma once
// Every number a rutting run reports, compared bit for bit: the curve, the
// snapshots, the final velocities and groups, the skeleton's record (films
// and load paths), the time step's report, and every scalar of the result
// but the wall time.
#include <vrut/protocol/rutting.hpp>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace vrut_test {

// The small section the pinned rutting test runs on: 60 x 30 mm of 1 mm
// disks of mix 2#, seed 3 (test_rutting.cpp), and its pinned rut depth at
// every default (a regression pin, renewed only on purpose).
inline vrut::SpecimenSettings small_section(std::uint64_t seed = 3) {
  vrut::SpecimenSettings s;
  s.placement.width = 60.0;
  s.placement.height = 30.0;
  s.disk_radius = 1.0;
  s.seed = seed;
  return s;
}
constexpr double pinned_small_rut_mm = 7.2958540768346163;  // renewed 2026-12-02: the film per contact, factor 4

// Equal bits (so NaN equals NaN, where == would not).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline void require_same(const vrut::LoadPath& a, const vrut::LoadPath& b) {
  REQUIRE(same_bits(a.minutes, b.minutes));
  REQUIRE(same_bits(a.stone_spring, b.stone_spring));
  REQUIRE(same_bits(a.stone_film, b.stone_film));
  REQUIRE(same_bits(a.mastic, b.mastic));
}

inline void require_same(const vrut::SkeletonRecord& a, const vrut::SkeletonRecord& b) {
  REQUIRE(a.films_start.contacts == b.films_start.contacts);
  REQUIRE(a.films_start.bearing == b.films_start.bearing);
  REQUIRE(a.films_end.contacts == b.films_end.contacts);
  REQUIRE(a.films_end.bearing == b.films_end.bearing);
  {
    INFO("the load path at minute " << vrut::SkeletonRecord::early_minute);
    require_same(a.load_early, b.load_early);
  }
  INFO("the load path at the end");
  require_same(a.load_end, b.load_end);
}

inline void require_same(const vrut::RuttingResult& a, const vrut::RuttingResult& b) {
  REQUIRE(a.samples.size() == b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    INFO("sample " << k);
    REQUIRE(same_bits(a.samples[k].deformation, b.samples[k].deformation));
    REQUIRE(same_bits(a.samples[k].plate_pressure, b.samples[k].plate_pressure));
    REQUIRE(same_bits(a.samples[k].minutes, b.samples[k].minutes));
    REQUIRE(same_bits(a.samples[k].reduced_time, b.samples[k].reduced_time));
    REQUIRE(same_bits(a.samples[k].plate_speed, b.samples[k].plate_speed));
  }
  REQUIRE(same_bits(a.plate_mass, b.plate_mass));
  REQUIRE(a.snapshots.size() == b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) {
    REQUIRE(a.snapshots[k].fraction == b.snapshots[k].fraction);
    REQUIRE(a.snapshots[k].x == b.snapshots[k].x);
    REQUIRE(a.snapshots[k].y == b.snapshots[k].y);
    REQUIRE(a.snapshots[k].dx == b.snapshots[k].dx);
    REQUIRE(a.snapshots[k].dy == b.snapshots[k].dy);
  }
  REQUIRE(a.vx == b.vx);
  REQUIRE(a.vy == b.vy);
  REQUIRE(a.group == b.group);
  REQUIRE(a.steps == b.steps);
  REQUIRE(a.contacts == b.contacts);
  REQUIRE(a.bonds == b.bonds);
  REQUIRE(a.particles == b.particles);
  REQUIRE(a.interrupted == b.interrupted);
  REQUIRE(same_bits(a.dt, b.dt));
  REQUIRE(same_bits(a.plate_x0, b.plate_x0));
  REQUIRE(same_bits(a.plate_x1, b.plate_x1));
  REQUIRE(same_bits(a.plate_y_final, b.plate_y_final));
  REQUIRE(same_bits(a.deformation_at_ds_start, b.deformation_at_ds_start));
  REQUIRE(same_bits(a.deformation_final, b.deformation_final));
  REQUIRE(same_bits(a.dynamic_stability, b.dynamic_stability));
  REQUIRE(same_bits(a.deformation_resolution, b.deformation_resolution));
  REQUIRE(a.dynamic_stability_is_lower_bound == b.dynamic_stability_is_lower_bound);
  REQUIRE(a.stones == b.stones);
  REQUIRE(a.stone_pairs_touching == b.stone_pairs_touching);
  require_same(a.skeleton, b.skeleton);
  REQUIRE(a.time_step.set_by == b.time_step.set_by);
  REQUIRE(a.time_step.next == b.time_step.next);
  REQUIRE(same_bits(a.time_step.step, b.time_step.step));
  REQUIRE(same_bits(a.time_step.next_step, b.time_step.next_step));
}

// A regression pin: what a run gave when its model was frozen, renewed only
// on purpose (a deliberate recalibration or a new order of summation, said in
// the commit and in the docs). Runs are deterministic (every sum in a fixed
// order, on any backend and thread count), so each number is compared bit
// for bit: the rut, the rut at the DS window's start, the DS, and the curve
// at a few samples (index, deformation in mm).
struct RuttingPin {
  double rut_mm, at_ds_start_mm, ds;
  std::vector<std::pair<std::size_t, double>> curve_mm;
};

// Every digit a double needs to be read back as the same bits.
inline std::string exact_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

inline void check_pinned(const vrut::RuttingResult& res, const RuttingPin& pin) {
  // Printed whole, so that a deliberate renewal copies them from the log.
  std::string curve;
  for (const auto& [k, mm] : pin.curve_mm)
    curve += " {" + std::to_string(k) + ", " +
             (k < res.samples.size() ? exact_text(res.samples[k].deformation * 1e3) : std::string("none")) + "}";
  std::printf("pinned run: rut %s mm, at the DS window's start %s mm, DS %s, curve%s\n",
              exact_text(res.deformation_final * 1e3).c_str(), exact_text(res.deformation_at_ds_start * 1e3).c_str(),
              exact_text(res.dynamic_stability).c_str(), curve.c_str());
  INFO("rut " << exact_text(res.deformation_final * 1e3) << " mm against the pin's " << exact_text(pin.rut_mm));
  CHECK(same_bits(res.deformation_final * 1e3, pin.rut_mm));
  CHECK(same_bits(res.deformation_at_ds_start * 1e3, pin.at_ds_start_mm));
  CHECK(same_bits(res.dynamic_stability, pin.ds));
  for (const auto& [k, mm] : pin.curve_mm) {
    INFO("sample " << k << " of " << res.samples.size());
    REQUIRE(k < res.samples.size());
    INFO("deformation " << exact_text(res.samples[k].deformation * 1e3) << " mm against the pin's " << exact_text(mm));
    CHECK(same_bits(res.samples[k].deformation * 1e3, mm));
  }
}

// The plate's momentum balance from the samples taken after `from_minute`
// (the load's ramp done): between the sample before them and the last, the
// dead load's impulse F T, less the contacts' (each sample's pressure times
// the plate's area and its interval), is the plate's change of momentum
// m (v_last - v_before). F and the area are the caller's, worked by hand, so
// a plate of another size or load, a pressure over another area, or an
// impulse counted over another interval breaks it. The plate is moved by
// exactly this balance each step (servo/servo.hpp, LoadControl), so the sums
// agree to their rounding: thousands of steps' impulses summed in doubles,
// well inside 1e-9 of F T. Returns the mean pressure's departure from F /
// area that the momentum accounts for, m (v_last - v_before) / (area T).
inline double check_plate_momentum(const vrut::RuttingResult& res, double force, double area, double from_minute) {
  std::size_t before = 0;
  while (before + 1 < res.samples.size() && res.samples[before + 1].minutes <= from_minute) ++before;
  REQUIRE(before + 2 < res.samples.size());
  const auto& first = res.samples[before];
  const auto& last = res.samples.back();
  double contacts = 0.0;
  for (std::size_t k = before + 1; k < res.samples.size(); ++k)
    contacts += res.samples[k].plate_pressure * area * (res.samples[k].reduced_time - res.samples[k - 1].reduced_time);
  const double span = last.reduced_time - first.reduced_time;
  const double momentum = res.plate_mass * (last.plate_speed - first.plate_speed);
  INFO("dead load's impulse " << force * span << " N s, contacts' " << contacts << ", plate's change of momentum "
                              << momentum);
  REQUIRE(res.plate_mass > 0.0);
  CHECK(force * span - contacts == Approx(momentum).margin(1e-9 * force * span));
  return momentum / (area * span);
}

}  // namespace vrut_test
