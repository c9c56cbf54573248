#pragma once
// The virtual wheel-tracking test in 3D (SPEC.md section 10): a 3D specimen
// (specimen/specimen3.hpp) in a mould of a floor and two end plates,
// periodic along its depth, settled under gravity, then loaded by a plate
// of the contact length l, as deep as the specimen, carrying p l depth as a
// dead load, for the cumulative time under the wheel reduced by alpha_T.
// The same test definition (protocol/rutting/test.hpp), materials (rutting/
// materials.hpp) and measurements (protocol/rutting/result.hpp) as in 2D, with:
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
//   - the mould and the plate on the same spring, frictionless by default.
// An ensemble runs side by side in one Simulation, with checkpoints and a
// stop, as in 2D (run.hpp).
#include <vrut/core/simulation.hpp>
#include <vrut/core/energy_check.hpp>
#include <vrut/protocol/rutting/loading.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/run.hpp>
#include <vrut/protocol/rutting/skeleton.hpp>
#include <vrut/protocol/rutting/test.hpp>
#include <vrut/protocol/rutting/timestep_report.hpp>
#include <vrut/servo/servo.hpp>
#include <vrut/specimen/specimen3.hpp>
#include <vrut/specimen/stone_reach3.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
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

// check_inside_moulds (run.hpp) on a 3D specimen's spheres.
inline double mould_particle_radius_mm(const Specimen3& s) { return s.spheres.radius; }
inline const char* mould_particle_word(const Specimen3&) { return "sphere"; }
inline std::string mould_position_text(const Vec3& p) {
  char text[120];
  std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x * 1e3, p.y * 1e3, p.z * 1e3);
  return text;
}

// Runs the 3D test on every specimen of an ensemble side by side in one
// Simulation; the specimens share one box (width, height, depth), sphere
// size and time step, the smallest any of them needs (its lightest stone
// sets it), so a specimen goes as its own single run would at that step.
// progress, stop, checkpoints and settling as in run_rutting_ensemble
// (run.hpp).
template <class Space, class Checkpoints = NoCheckpoints>
std::vector<RuttingResult3> run_rutting_ensemble3(const std::vector<Specimen3>& specimens, const WheelTracking& wt,
                                                  const RuttingMaterials& mat, const RuttingNumerics& num,
                                                  const Space& space = Space(),
                                                  const std::function<void(double, long)>& progress = {},
                                                  const std::function<bool()>& stop = {},
                                                  Checkpoints* checkpoints = nullptr,
                                                  const std::function<void(long, long)>& settling = {}) {
  const bool resuming = checkpoints != nullptr && checkpoints->resuming();
  if (specimens.empty()) throw std::invalid_argument("an ensemble needs at least one specimen");
  num.validate();
  const int count = static_cast<int>(specimens.size());
  const Specimen3& first_specimen = specimens.front();
  for (const Specimen3& sp : specimens) {
    wt.validate(sp.width * 1e-3);
    if (sp.spheres.radius != first_specimen.spheres.radius || sp.width != first_specimen.width ||
        sp.height != first_specimen.height || sp.depth != first_specimen.depth)
      throw std::invalid_argument("a 3D ensemble's specimens must share one box and one sphere size");
  }
  const double width = first_specimen.width * 1e-3, height = first_specimen.height * 1e-3;
  const double depth = first_specimen.depth * 1e-3;
  const double r = first_specimen.spheres.radius * 1e-3, d = 2.0 * r;
  const auto table = rutting_table3(mat, d, num.shift);
  SimulationSettings3 settings;
  settings.gravity = {0.0, -wt.gravity, 0.0};
  settings.box.high = {width, 2.0 * height, depth};
  settings.box.periodic[2] = true;
  CentralDifference::params_type integrator;
  integrator.damping = num.settle_damping;
  ParticleSet all;
  std::vector<std::pair<int, int>> bonds;
  for (int e = 0; e < count; ++e) {
    const Specimen3& sp = specimens[e];
    const int offset = static_cast<int>(all.size());
    ParticleSet set = to_particle_set(sp, mat.mastic_density, mat.aggregate_density);
    set.body = stone_bodies3(sp);
    set.group = rutting_groups3(sp, mat);
    all.append_specimen(set);
    for (const auto& [i, j] : sp.spheres.bonds) bonds.emplace_back(i + offset, j + offset);
  }
  Simulation3<RuttingLaw, Space, CentralDifference, LoadControl, RuttingWallLaw> sim(all, table, settings, integrator,
                                                                                     space);
  std::vector<RuttingResult3> out(count);
  sim.bond_pairs(bonds);
  for (int e = 0; e < count; ++e) {
    out[e].depth = specimens[e].depth;
    out[e].result.bonds = sim.intact_bonds(e);
    out[e].result.particles = specimens[e].spheres.centers.size();
  }

  // Each mould: the floor and the two ends, endless along the periodic depth
  // (plates far deeper than the specimen, which spheres may cross unwrapped).
  const auto wall_law = rutting_wall_params(mat, fcc_law_length(mat, d));
  const double k_wall = wall_law.normal.stiffness, endless = 50.0 * depth;
  const Vec3 mid{0.5 * width, height, 0.5 * depth};
  for (int e = 0; e < count; ++e) {
    sim.add_wall(Wall3{{mid.x, 0.0, mid.z}, {0.0, 0.0, endless}, {0.5 * width, 0.0, 0.0}, {}}, wall_law, {}, e);
    sim.add_wall(Wall3{{0.0, mid.y, mid.z}, {0.0, height, 0.0}, {0.0, 0.0, endless}, {}}, wall_law, {}, e);
    sim.add_wall(Wall3{{width, mid.y, mid.z}, {0.0, 0.0, endless}, {0.0, height, 0.0}, {}}, wall_law, {}, e);
  }
  const double dt = num.timestep_safety * sim.critical_timestep();
  for (auto& o : out) o.result.time_step = timestep_report(sim, table);

  // Settling (a resumed run reads where it had got to instead); the energy
  // check counts the loads' work from here.
  auto energy_reference = host_positions_copy(sim);
  LoadingState<Vec3> state(count, dt);
  std::vector<double>& top = state.top;
  if (!resuming) run_checking_energy(sim, num.settle_steps, dt, energy_reference, settling);

  // The plates, each on the highest sphere under it, as deep as the specimen
  // (its pressure is its force over l times the depth), endless along it.
  const double l = wt.contact_length();
  const LoadingPlan plan = loading_plan(wt, num, dt);
  const double t_load = plan.t_load;
  const long steps = plan.steps;
  const double plate_x0 = 0.5 * (width - l), plate_x1 = 0.5 * (width + l);
  // A dead load, as in 2D (run.hpp says why not a servo); its mass ten times
  // the least that keeps it stable on stiff contacts with every sphere of
  // the top layer under it (one per d^2).
  const double plate_mass = 10.0 * k_wall * (l * depth / (d * d)) * dt * dt / 4.0;
  std::vector<int> plate(count);
  {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
    for (int e = 0; e < count; ++e) {
      RuttingResult& res = out[e].result;
      res.dt = dt;
      res.plate_x0 = plate_x0;
      res.plate_x1 = plate_x1;
      const auto [first, last] = sim.specimen_range(e);
      for (int i = first; i < last; ++i)
        if (x(i).x + r > plate_x0 && x(i).x - r < plate_x1) top[e] = std::max(top[e], x(i).y + r);
      plate[e] = sim.add_wall(Wall3{{mid.x, top[e], mid.z}, {0.5 * l, 0.0, 0.0}, {0.0, 0.0, endless}, {}}, wall_law,
                              LoadControl::for_stress(0.0, l, depth, plate_mass, 0.0), e);
    }
  }
  // The skeleton (protocol/rutting/skeleton.hpp): cut half way between the floor and
  // the plate where it is now, under the plate (run.hpp).
  auto skeleton = [&](int e) {
    SkeletonCut cut;
    cut.height = 0.5 * sim.wall(plate[e]).centre.y;
    cut.x0 = plate_x0;
    cut.x1 = plate_x1;
    cut.diameter = d;
    return skeleton_snapshot(sim, table, e, cut, specimens[e].spheres.stone);
  };
  for (int e = 0; e < count; ++e) out[e].result.skeleton.films_start = skeleton(e).films;
  auto ramp_to = [&](double fraction) {
    for (int e = 0; e < count; ++e)
      sim.set_controller(plate[e], LoadControl::for_stress(wt.pressure * fraction, l, depth, plate_mass, 0.0));
  };
  CentralDifference::params_type loading;
  loading.damping = num.damping;
  sim.set_integrator(loading);

  Kokkos::View<Vec3*, typename Space::memory_space> start("loading_start", all.size());
  Kokkos::deep_copy(start, sim.particles().position);
  const double to_minutes = wt.minutes / t_load;
  for (int e = 0; e < count; ++e) state.last_plate_position[e] = sim.wall(plate[e]).centre;
  // The whole state of the run between two steps (Simulation::visit_state).
  auto visit = [&](auto& archive) {
    sim.visit_state(archive);
    archive.view("loading_start", start);
    state.visit(archive);
    archive.view("energy_reference", energy_reference);
    for (int e = 0; e < count; ++e) {
      const std::string id = "specimen_" + std::to_string(e) + "_";
      archive.vector(id + "samples", out[e].result.samples);
      out[e].result.skeleton.visit(archive, id);
    }
  };
  state.begin = std::chrono::steady_clock::now();
  if (resuming) {
    checkpoints->load(visit);
    state.resumed(dt);
  }
  auto take_sample = [&](long s, double time) {
    check_inside_moulds(sim, specimens, s, dt);
    for (int e = 0; e < count; ++e) {
      const Wall3 w = sim.wall(plate[e]);
      RuttingSample smp;
      smp.reduced_time = time;
      smp.minutes = time * to_minutes;
      smp.deformation = top[e] - w.centre.y;
      smp.plate_pressure = state.plate_sample(e, sim.wall_impulse(plate[e]), w.centre, inward_normal(w), time, l * depth);
      out[e].result.samples.push_back(smp);
      LoadPath& early = out[e].result.skeleton.load_early;
      if (!early.measured() && smp.minutes >= SkeletonRecord::early_minute) {
        early = skeleton(e).load;
        early.minutes = smp.minutes;
      }
    }
    check_energy(sim, energy_reference, state.plate_work, s, dt);
  };
  const long done = run_loading(sim, plan, state, ramp_to, [](long) {}, take_sample, progress, stop, checkpoints, visit);
  if (done < steps)
    for (auto& o : out) o.result.interrupted = true;
  Kokkos::fence();
  const double seconds = state.seconds();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), start);
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().group);
  for (int e = 0; e < count; ++e) {
    RuttingResult& res = out[e].result;
    res.wall_seconds = seconds;
    res.steps = done;
    res.contacts = sim.active_contacts(e);
    std::tie(res.stones, res.stone_pairs_touching) =
        touching_stones(sim, specimens[e].spheres.stone, specimens[e].placement.stones.size(), e);
    res.plate_y_final = sim.wall(plate[e]).centre.y;
    const SkeletonSnapshot end = skeleton(e);
    res.skeleton.films_end = end.films;
    res.skeleton.load_end = end.load;
    res.skeleton.load_end.minutes = res.samples.empty() ? 0.0 : res.samples.back().minutes;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      out[e].final_positions.push_back(1e3 * Point3(x(i).x, x(i).y, x(i).z));
      const Vec3 u = x(i) - x0(i);
      out[e].displacement.push_back(1e3 * Point3(u.x, u.y, u.z));
      res.group.push_back(g(i) == mastic_group ? mastic_group : aggregate_group);  // reach bins are stones
    }
    finish_deformation(res, wt);
  }
  return out;
}

template <class Space, class Checkpoints = NoCheckpoints>
RuttingResult3 run_rutting3(const Specimen3& sp, const WheelTracking& wt, const RuttingMaterials& mat,
                            const RuttingNumerics& num, const Space& space = Space(),
                            const std::function<void(double, long)>& progress = {},
                            const std::function<bool()>& stop = {}, Checkpoints* checkpoints = nullptr) {
  return run_rutting_ensemble3(std::vector<Specimen3>{sp}, wt, mat, num, space, progress, stop, checkpoints).front();
}

}  // namespace vrut
