#pragma once
// The rutting test's 3D setup (driver.hpp; docs/specimen.md): a 3D
// specimen (specimen/specimen3.hpp) in a mould of a floor and two end plates,
// periodic along its depth, loaded by a plate of the contact length l, as
// deep as the specimen, carrying p l depth as a dead load. The same test
// definition (test.hpp), materials (materials.hpp) and measurements
// (result.hpp) as in 2D, with:
//   - the mastic's Burger's contacts by the FCC lattice's rule
//     (MicroConversion::fcc_lattice; the sphere diameter d where 2D takes
//     the disk width t), scaled by mastic_aggregate_factor between mastic
//     and stone, as in 2D;
//   - rigid stones only (each stone's spheres one body), meeting on the
//     rigid stones' spring, stone_contact_ratio times the mastic's normal
//     spring E1 d / c, with its dashpot; with the film per contact, first
//     through the mastic film between their surfaces (specimen/
//     stone_reach3.hpp), as in 2D. A rigid stone's spheres never touch
//     each other, so every contact between stone spheres is one between
//     two stones: 3D needs no stone colours (2D has them for the method's
//     bonded stones, specimen/colouring.hpp);
//   - the mould and the plate on the same spring, frictionless by default;
//   - with WheelTracking::transverse, the strip across the travel: the plate
//     the wheel's width d along the box's span, still across the whole
//     periodic depth, which now runs along the travel. Averaged over the
//     passes the wheel loads its whole path, so the mix is held along the
//     travel and flows out sideways towards the heave beside the track, as
//     2D's transverse section has it; the end plates stand for the mould's
//     sides;
//   - with WheelTracking::patch, a plate the tyre's patch (l by the wheel's
//     width d, at mid-depth) in place of the strip across the depth: across
//     the periodic depth, a row of wheels a box's depth apart. The walls see
//     a sphere's continuous path, not its image, so the box must be at
//     least twice the wheel's width deep: a sphere would have to travel
//     about (depth - d) / 2 across the depth (less half a stone, for a
//     stone placed across the periodic face) to come under the patch's
//     image, which the plate does not hold; the run checks at every sample
//     that none has (checks.hpp, check_clear_of_plate_images).
#include <vrut/core/simulation.hpp>
#include <vrut/protocol/rutting/depth_band.hpp>
#include <vrut/protocol/rutting/loading.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/test.hpp>
#include <vrut/servo/servo.hpp>
#include <vrut/specimen/specimen3.hpp>
#include <vrut/specimen/stone_reach3.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

// The length that stands for the 2D disk width in the 3D laws: d / c, so
// that E t becomes the FCC rule's E d / c (docs/burgers.md).
inline double fcc_law_length(const RuttingMaterials& m, double diameter) {
  const double beta = 1.0 / (2.0 * (1.0 + m.mastic_nu));
  return diameter / MicroConversion::fcc_lattice_modulus_factor(beta);
}

// The 3D contact table, the 2D one's (rutting_table_with) on spheres of
// `diameter` (m): group 0 the mastic, the stones (one group per reach bin,
// with the film per contact). Two spheres of one stone move as one body and
// never touch, so the stones' laws act only between two stones.
inline AssignmentTable<RuttingLaw> rutting_table3(const RuttingMaterials& m, double diameter, double shift) {
  if (!m.rigid_stones)
    throw std::invalid_argument("the 3D rutting test has rigid stones only (the method's bonded stone spheres would "
                                "need a time step thousands of times smaller)");
  if (m.stone_film == StoneFilm::mean)
    throw std::invalid_argument("the mean film's thickness (0.40 diameters) was measured between the stones of 2D "
                                "sections; in 3D two stones meet through the film per contact, or through none");
  validate_poisson(m.mastic_nu);
  RuttingTableScales scales;
  scales.conversion = MicroConversion::fcc_lattice(m.mastic_nu);
  scales.mastic_length = diameter;
  scales.stone_length = fcc_law_length(m, diameter);
  scales.diameter = diameter;
  return rutting_table_with(m, shift, scales, 1, true);
}

// The least depth (mm) a box under a patch plate may have: twice the wheel's
// width, rounded up to whole FCC cells of spheres of radius_mm (the depth
// the specimen is given, fcc_cells_deep).
inline double least_patch_depth_mm(double wheel_width_mm, double radius_mm) {
  const double cell = fcc_cell(radius_mm);
  return std::ceil(2.0 * wheel_width_mm / cell - 1e-9) * cell;
}

// Refuses a box too shallow for a patch plate: the mix must flow out past
// the wheel's edges. depth_mm is the specimen's depth (whole FCC cells);
// lead names what asked for the patch ("--plate patch" from the CLI).
inline void check_patch_depth(const char* lead, double depth_mm, double wheel_width_mm, double radius_mm) {
  const double least_depth = 2.0 * wheel_width_mm;
  if (depth_mm >= least_depth * (1.0 - 1e-9)) return;
  char text[320];
  std::snprintf(text, sizeof text, "%s needs a box at least %g mm deep (twice as deep as the wheel's %g mm width), "
                "so the mix can flow out past the wheel's edges: this one is %.2f mm (whole FCC cells of %.3f mm); "
                "give --depth-mm %.2f",
                lead, least_depth, wheel_width_mm, depth_mm, fcc_cell(radius_mm),
                least_patch_depth_mm(wheel_width_mm, radius_mm));
  throw std::invalid_argument(text);
}

// Each stone that holds a sphere is one body, numbered in the stones'
// order; mastic spheres are free (-1).
inline std::vector<int> stone_bodies3(const Specimen3& sp) {
  std::vector<int> body_of(sp.placement.stones.size(), -1), body(sp.spheres.stone.size(), -1);
  int bodies = 0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    const int s = sp.spheres.stone[i];
    if (s < 0) continue;
    if (body_of[s] < 0) body_of[s] = bodies++;
    body[i] = body_of[s];
  }
  return body;
}

// Each sphere's group in the contact table: the mastic's, or, with the film
// per contact, the bin of its reach (stone_reach3), as rutting_groups does
// in 2D with one colour.
inline std::vector<int> rutting_groups3(const Specimen3& sp, const RuttingMaterials& m) {
  const std::size_t n = sp.spheres.centers.size();
  const std::vector<double> reach = m.film_per_contact() ? stone_reach3(sp) : std::vector<double>(n, 0.0);
  std::vector<int> group(n, mastic_group);
  for (std::size_t i = 0; i < n; ++i)
    if (sp.spheres.stone[i] >= 0) group[i] = stone_group(m, 0, reach[i]);
  return group;
}

// What a 3D run gives beside RuttingResult's curve and DS: the spheres'
// places at the end (mm), for the pictures and the VTK file.
struct RuttingResult3 {
  RuttingResult result;
  std::vector<Point3> final_positions, displacement;  // mm
  double depth = 0.0;                                 // mm, the specimen's
};

// What check_inside_moulds (checks.hpp) says of a 3D specimen's spheres.
inline double mould_particle_radius_mm(const Specimen3& s) { return s.spheres.radius; }
inline const char* mould_particle_word(const Specimen3&) { return "sphere"; }
inline std::string mould_position_text(const Vec3& p) {
  char text[120];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x * 1e3, p.y * 1e3, p.z * 1e3);
  return text;
}

// The specimens of an ensemble share one box (width, height, depth), sphere
// size and time step, the smallest any of them needs (its lightest stone
// sets it), so a specimen goes as its own single run would at that step.
struct BoxSetup {
  using dimension = Dim3;
  using vector = Vec3;
  using specimen_type = Specimen3;
  using result_type = RuttingResult3;
  static constexpr bool snapshots = false;  // the pictures come from the final places

  const std::vector<Specimen3>& specimens;
  const WheelTracking& wt;
  const RuttingMaterials& mat;
  double width = 0.0, height = 0.0, depth = 0.0, d = 0.0;  // m; d the spheres' diameter
  double endless = 0.0;  // the plates' half-length along the periodic depth, far beyond it
  Vec3 mid;
  AssignmentTable<RuttingLaw> table{1};
  SimulationSettings3 settings;
  ParticleSet particles;
  std::vector<std::pair<int, int>> bonds;

  BoxSetup(const std::vector<Specimen3>& s, const WheelTracking& w, const RuttingMaterials& m,
           const RuttingNumerics& num)
      : specimens(s), wt(w), mat(m) {
    if (specimens.empty()) throw std::invalid_argument("an ensemble needs at least one specimen");
    num.validate();
    if (wt.transverse && wt.patch)
      throw std::invalid_argument("a plate is either the strip across the travel or the tyre's patch, not both");
    const Specimen3& first = specimens.front();
    for (const Specimen3& sp : specimens) {
      wt.validate(sp.width * 1e-3);
      if (sp.spheres.radius != first.spheres.radius || sp.width != first.width || sp.height != first.height ||
          sp.depth != first.depth)
        throw std::invalid_argument("a 3D ensemble's specimens must share one box and one sphere size");
    }
    width = first.width * 1e-3, height = first.height * 1e-3, depth = first.depth * 1e-3;
    if (wt.patch) check_patch_depth("a patch plate", first.depth, wt.wheel_width * 1e3, first.spheres.radius);
    const double r = first.spheres.radius * 1e-3;
    d = 2.0 * r;
    endless = 50.0 * depth;
    mid = {0.5 * width, height, 0.5 * depth};
    table = rutting_table3(mat, d, num.shift);
    settings.gravity = {0.0, -wt.gravity, 0.0};
    settings.box.high = {width, 2.0 * height, depth};
    settings.box.periodic[2] = true;
    for (const Specimen3& sp : specimens) {
      const int offset = static_cast<int>(particles.size());
      ParticleSet set = to_particle_set(sp, mat.mastic_density, mat.aggregate_density);
      set.body = stone_bodies3(sp);
      set.group = rutting_groups3(sp, mat);
      particles.append_specimen(set);
      for (const auto& [i, j] : sp.spheres.bonds) bonds.emplace_back(i + offset, j + offset);
    }
  }

  static RuttingResult& base(RuttingResult3& r) { return r.result; }
  void begin(RuttingResult3& r, int e) const { r.depth = specimens[e].depth; }
  std::size_t particle_count(int e) const { return specimens[e].spheres.centers.size(); }
  static double radius_mm(const Specimen3& s) { return s.spheres.radius; }
  static const std::vector<int>& stone_of(const Specimen3& s) { return s.spheres.stone; }
  static std::size_t stone_count(const Specimen3& s) { return s.placement.stones.size(); }

  // Each mould: the floor and the two ends, endless along the periodic depth
  // (plates far deeper than the specimen, which spheres may cross unwrapped).
  RuttingWallLaw::params_type wall_law() const { return rutting_wall_params(mat, fcc_law_length(mat, d)); }
  template <class Sim>
  void add_mould(Sim& sim, const RuttingWallLaw::params_type& law, int e) const {
    sim.add_wall(Wall3{{mid.x, 0.0, mid.z}, {0.0, 0.0, endless}, {0.5 * width, 0.0, 0.0}, {}}, law, {}, e);
    sim.add_wall(Wall3{{0.0, mid.y, mid.z}, {0.0, height, 0.0}, {0.0, 0.0, endless}, {}}, law, {}, e);
    sim.add_wall(Wall3{{width, mid.y, mid.z}, {0.0, 0.0, endless}, {0.0, height, 0.0}, {}}, law, {}, e);
  }

  // The plate's extent across the depth: the depth (a strip) or the wheel's width (a patch).
  double plate_depth() const { return wt.patch ? wt.wheel_width : depth; }
  // Where the plate lies across the depth (the skeleton's cut and the plate's first height look only there).
  DepthBand plate_band() const { return wt.patch ? DepthBand{mid.z, 0.5 * wt.wheel_width, depth} : DepthBand{}; }

  // The plate at height `top`, its length in the section (l, or the wheel's
  // width d across the travel) at mid-span and endless along the depth, or
  // the patch's width at mid-depth (its pressure is its force over its
  // length times its depth); its point, the centre. Its mass ten times the least
  // that keeps it stable on stiff contacts with every sphere of the top
  // layer under it (one per d^2).
  Wall3 plate(int, double top) const {
    return Wall3{{mid.x, top, mid.z}, {0.5 * wt.plate_length(), 0.0, 0.0},
                 {0.0, 0.0, wt.patch ? 0.5 * wt.wheel_width : endless}, {}};
  }
  static Vec3 plate_point(const Wall3& w) { return w.centre; }
  double plate_mass(double k_wall, double dt, int) const {
    const double l = wt.plate_length();
    return 10.0 * k_wall * (l * plate_depth() / (d * d)) * dt * dt / 4.0;
  }
  double plate_area() const { return wt.plate_length() * plate_depth(); }
  LoadControl::params_type plate_load(double fraction, double mass) const {
    return LoadControl::for_stress(wt.pressure * fraction, wt.plate_length(), plate_depth(), mass, 0.0);
  }

  // A sphere at the end: where it is and how far it moved while loaded (mm).
  static void record_particle(RuttingResult3& out, Vec3 x, Vec3 x0, Vec3) {
    out.final_positions.push_back(1e3 * Point3(x.x, x.y, x.z));
    const Vec3 u = x - x0;
    out.displacement.push_back(1e3 * Point3(u.x, u.y, u.z));
  }
};

}  // namespace vrut
