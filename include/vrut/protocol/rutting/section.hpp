#pragma once
// The rutting test's 2D setup (driver.hpp): sections of disks of thickness
// t = the wheel's width d in a mould of a floor and two sides, the plate a
// segment of the contact length l at mid-span (or the wheel's width across
// the travel: test.hpp, transverse), carrying the wheel's pressure. Where
// stones meet through a film, each stone's disks get its colour's group.
#include <vrut/core/simulation.hpp>
#include <vrut/protocol/rutting/depth_band.hpp>
#include <vrut/protocol/rutting/loading.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/test.hpp>
#include <vrut/servo/servo.hpp>
#include <vrut/specimen/colouring.hpp>
#include <vrut/specimen/specimen.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

// What check_inside_moulds (checks.hpp) says of a 2D specimen's particles.
inline double mould_particle_radius_mm(const Specimen& s) { return s.disks.radius; }
inline const char* mould_particle_word(const Specimen&) { return "disk"; }
inline std::string mould_position_text(const Vec2& p) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.4g, %.4g)", p.x * 1e3, p.y * 1e3);
  return text;
}

struct SectionSetup {
  using dimension = Dim2;
  using vector = Vec2;
  using specimen_type = Specimen;
  using result_type = RuttingResult;
  static constexpr bool snapshots = true;  // the pictures of the rut forming

  const std::vector<Specimen>& specimens;
  const WheelTracking& wt;
  const RuttingMaterials& mat;
  double t = 0.0;  // the disks' thickness, m
  AssignmentTable<RuttingLaw> table{1};
  SimulationSettings settings;
  ParticleSet particles;
  std::vector<std::pair<int, int>> bonds;

  SectionSetup(const std::vector<Specimen>& s, const WheelTracking& w, const RuttingMaterials& m,
               const RuttingNumerics& num)
      : specimens(s), wt(w), mat(m), t(w.wheel_width) {
    if (specimens.empty()) throw std::invalid_argument("an ensemble needs at least one specimen");
    num.validate();
    if (wt.patch) throw std::invalid_argument("a patch plate is 3D's; a 2D section's plate spans its thickness");
    const int count = static_cast<int>(specimens.size());
    for (const Specimen& sp : specimens) wt.validate(sp.width * 1e-3);
    // Where stones meet through a film, each stone's disks get its colour's
    // group; the margin (two disk diameters) covers how far neighbours close in.
    std::vector<std::vector<int>> colours(count);
    int stone_colours = 1;
    const bool films = mat.films();
    if (films)
      for (int e = 0; e < count; ++e) {
        colours[e] = colour_aggregates(specimens[e].placement, 4.0 * specimens[e].disks.radius);
        for (int c : colours[e]) stone_colours = std::max(stone_colours, c + 1);
      }
    for (const Specimen& sp : specimens)
      if (sp.disks.radius != specimens[0].disks.radius)
        throw std::invalid_argument("an ensemble's specimens must share one disk size");
    table = rutting_table(mat, t, num.shift, stone_colours, 2e-3 * specimens[0].disks.radius);
    settings.thickness = t;
    settings.gravity = {0.0, -wt.gravity};
    for (int e = 0; e < count; ++e) {
      const Specimen& sp = specimens[e];
      const int offset = static_cast<int>(particles.size());
      ParticleSet set = to_particle_set(sp, mat.mastic_density, mat.aggregate_density);
      if (films) set.group = rutting_groups(sp, mat, colours[e]);
      if (mat.rigid_stones) set.body = stone_bodies(sp);
      particles.append_specimen(set);
      for (const auto& [i, j] : sp.disks.bonds) bonds.emplace_back(i + offset, j + offset);
    }
  }

  static RuttingResult& base(RuttingResult& r) { return r; }
  void begin(RuttingResult&, int) const {}
  std::size_t particle_count(int e) const { return specimens[e].disks.centers.size(); }
  static double radius_mm(const Specimen& s) { return s.disks.radius; }
  static const std::vector<int>& stone_of(const Specimen& s) { return s.disks.aggregate; }
  static std::size_t stone_count(const Specimen& s) { return s.placement.aggregates.size(); }

  // Each mould: bottom and both sides, linear and (by default) frictionless.
  RuttingWallLaw::params_type wall_law() const { return rutting_wall_params(mat, t); }
  template <class Sim>
  void add_mould(Sim& sim, const RuttingWallLaw::params_type& law, int e) const {
    const double width = specimens[e].width * 1e-3, height = specimens[e].height * 1e-3;
    sim.add_wall(Wall{{0.0, 0.0}, {width, 0.0}, {}}, law, {}, e);
    sim.add_wall(Wall{{0.0, 2.0 * height}, {0.0, 0.0}, {}}, law, {}, e);
    sim.add_wall(Wall{{width, 0.0}, {width, 2.0 * height}, {}}, law, {}, e);
  }

  // The plate of specimen e at height `top`, from x0 to x1 at mid-span; its
  // point, the segment's start. Its mass is numerical: ten times the least
  // that keeps it stable on stiff contacts with every disk under it
  // (k N dt^2 / 4), so that its inertia hardly shows in the measured pressure.
  Wall plate(int e, double top) const {
    const double width = specimens[e].width * 1e-3, l = wt.plate_length();
    return Wall{{0.5 * (width + l), top}, {0.5 * (width - l), top}, {}};
  }
  static Vec2 plate_point(const Wall& w) { return w.start; }
  double plate_mass(double k_wall, double dt, int e) const {
    const double r = specimens[e].disks.radius * 1e-3;
    return 10.0 * k_wall * (wt.plate_length() / (2.0 * r)) * dt * dt / 4.0;
  }
  double plate_area() const { return wt.plate_length() * t; }
  // A section has no depth: the plate spans it (depth_band.hpp).
  static DepthBand plate_band() { return {}; }
  // The dead load at `fraction` of the wheel's: its pressure, either section.
  LoadControl::params_type plate_load(double fraction, double mass) const {
    const double stress = wt.plate_force() * fraction / (wt.contact_length() * t);
    return LoadControl::for_stress(stress, wt.plate_length(), t, mass, 0.0);
  }

  // Each specimen's disks where they are and how far they moved since the loading began.
  template <class Sim, class Start>
  void snapshot(const Sim& sim, const Start& start, double fraction, std::vector<RuttingResult>& out) const {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
    auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), start);
    for (int e = 0; e < static_cast<int>(out.size()); ++e) {
      RuttingSnapshot s;
      s.fraction = fraction;
      const auto [first, last] = sim.specimen_range(e);
      for (int i = first; i < last; ++i) {
        s.x.push_back(x(i).x);
        s.y.push_back(x(i).y);
        s.dx.push_back(x(i).x - x0(i).x);
        s.dy.push_back(x(i).y - x0(i).y);
      }
      out[e].snapshots.push_back(std::move(s));
    }
  }
  // A disk at the end: its velocity.
  static void record_particle(RuttingResult& res, Vec2, Vec2, Vec2 v) {
    res.vx.push_back(v.x);
    res.vy.push_back(v.y);
  }
};

}  // namespace vrut
