#pragma once
// Every number a rutting run reports, compared bit for bit: the curve, the
// snapshots, the final velocities and groups, and every scalar of the result
// but the wall time.
#include <vrut/protocol/rutting.hpp>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>

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

inline void require_same(const vrut::RuttingResult& a, const vrut::RuttingResult& b) {
  REQUIRE(a.samples.size() == b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    INFO("sample " << k);
    REQUIRE(same_bits(a.samples[k].deformation, b.samples[k].deformation));
    REQUIRE(same_bits(a.samples[k].plate_pressure, b.samples[k].plate_pressure));
    REQUIRE(same_bits(a.samples[k].minutes, b.samples[k].minutes));
    REQUIRE(same_bits(a.samples[k].reduced_time, b.samples[k].reduced_time));
  }
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
}

}  // namespace vrut_test
