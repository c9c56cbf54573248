#pragma once
// The virtual wheel-tracking test in 3D (SPEC.md section 10): a 3D specimen
// (specimen/specimen3.hpp) in a mould of a floor and two end plates,
// periodic along its depth, settled under gravity, then loaded by a plate
// of the contact length l, as deep as the specimen, carrying p l depth as a
// dead load, for the cumulative time under the wheel reduced by alpha_T.
// The same test definition (rutting/test.hpp), materials (rutting/
// materials.hpp) and measurements (rutting/result.hpp) as in 2D, with:
//   - the mastic's Burger's contacts by the FCC lattice's rule
//     (MicroConversion::fcc_lattice; the sphere diameter d where 2D takes
//     the disk width t), scaled by mastic_aggregate_factor between mastic
//     and stone, as in 2D;
//   - rigid stones only (each stone's spheres one body), meeting on the
//     rigid stones' spring, stone_contact_ratio times the mastic's normal
//     spring E1 d / c, with its dashpot; no film between stones yet;
//   - the mould and the plate on the same spring, frictionless by default.
// One specimen a run (no ensembles, no checkpoints yet).
#include <vrut/core/simulation.hpp>
#include <vrut/protocol/energy_check.hpp>
#include <vrut/rutting/materials.hpp>
#include <vrut/rutting/result.hpp>
#include <vrut/rutting/run.hpp>
#include <vrut/rutting/test.hpp>
#include <vrut/servo/servo.hpp>
#include <vrut/specimen/specimen3.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

// The length that stands for the 2D disk width in the 3D laws: d / c, so
// that E t becomes the FCC rule's E d / c (docs/burgers.md).
inline double fcc_law_length(const RuttingMaterials& m, double diameter) {
  const double beta = 1.0 / (2.0 * (1.0 + m.mastic_nu));
  return diameter / MicroConversion::fcc_lattice_modulus_factor(beta);
}

// The 3D contact table: group 0 the mastic, 1 the stones. Two spheres of one
// stone move as one body, so the stone law acts only between stones.
inline AssignmentTable<RuttingLaw> rutting_table3(const RuttingMaterials& m, double diameter, double shift) {
  if (!m.rigid_stones)
    throw std::invalid_argument("the 3D rutting test has rigid stones only (the method's bonded stone spheres would "
                                "need a time step thousands of times smaller)");
  if (m.films())
    throw std::invalid_argument("the 3D rutting test has no film between stones yet: give the stone film 'none'");
  validate_poisson(m.mastic_nu);
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(shift));
  const MicroConversion conv = MicroConversion::fcc_lattice(m.mastic_nu);
  const double stone_friction = m.stone_friction < 0.0 ? m.friction : m.stone_friction;
  AssignmentTable<RuttingLaw> table(2);
  table.set(mastic_group, mastic_group,
            RuttingLaw::make_first(film_params(mastic_params(reduced, diameter, m.mastic_nu, conv, 1.0, m.friction))));
  table.set(mastic_group, aggregate_group,
            RuttingLaw::make_first(film_params(
                mastic_params(reduced, diameter, m.mastic_nu, conv, m.mastic_aggregate_factor, m.friction))));
  table.set(aggregate_group, aggregate_group,
            RuttingLaw::make_second(stone_law_params(m, fcc_law_length(m, diameter), stone_friction)));
  return table;
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

// What a 3D run gives beside RuttingResult's curve and DS: the spheres'
// places at the end (mm), for the pictures and the VTK file.
struct RuttingResult3 {
  RuttingResult result;
  std::vector<Point3> final_positions, displacement;  // mm
  double depth = 0.0;                                 // mm, the specimen's
};

template <class Space>
RuttingResult3 run_rutting3(const Specimen3& sp, const WheelTracking& wt, const RuttingMaterials& mat,
                            const RuttingNumerics& num, const Space& space = Space(),
                            const std::function<void(double, long)>& progress = {}) {
  if (!(num.timestep_safety > 0.0 && num.timestep_safety <= 1.0))
    throw std::invalid_argument("time-step safety must lie in (0, 1]");
  if (num.samples < 10) throw std::invalid_argument("at least 10 samples");
  wt.validate(sp.width * 1e-3);
  const double width = sp.width * 1e-3, height = sp.height * 1e-3, depth = sp.depth * 1e-3;
  const double r = sp.spheres.radius * 1e-3, d = 2.0 * r;
  const auto table = rutting_table3(mat, d, num.shift);
  SimulationSettings3 settings;
  settings.gravity = {0.0, -wt.gravity, 0.0};
  settings.box.high = {width, 2.0 * height, depth};
  settings.box.periodic[2] = true;
  CentralDifference::params_type integrator;
  integrator.damping = num.settle_damping;
  ParticleSet set = to_particle_set(sp, mat.mastic_density, mat.aggregate_density);
  set.body = stone_bodies3(sp);
  Simulation3<RuttingLaw, Space, CentralDifference, LoadControl, RuttingWallLaw> sim(set, table, settings, integrator,
                                                                                     space);
  RuttingResult3 out;
  out.depth = sp.depth;
  RuttingResult& res = out.result;
  res.particles = set.size();
  sim.bond_pairs(sp.spheres.bonds);
  res.bonds = sim.intact_bonds(0);

  // The mould: the floor and the two ends, endless along the periodic depth
  // (plates far deeper than the specimen, which spheres may cross unwrapped).
  const auto wall_law = rutting_wall_params(mat, fcc_law_length(mat, d));
  const double k_wall = wall_law.normal.stiffness, endless = 50.0 * depth;
  const Vec3 mid{0.5 * width, height, 0.5 * depth};
  sim.add_wall(Wall3{{mid.x, 0.0, mid.z}, {0.0, 0.0, endless}, {0.5 * width, 0.0, 0.0}, {}}, wall_law);
  sim.add_wall(Wall3{{0.0, mid.y, mid.z}, {0.0, height, 0.0}, {0.0, 0.0, endless}, {}}, wall_law);
  sim.add_wall(Wall3{{width, mid.y, mid.z}, {0.0, 0.0, endless}, {0.0, height, 0.0}, {}}, wall_law);
  const double dt = num.timestep_safety * sim.critical_timestep();
  res.dt = dt;

  const auto energy_reference = host_positions_copy(sim);
  run_checking_energy(sim, num.settle_steps, dt, energy_reference);

  // The plate on the highest sphere under it, as deep as the specimen (its
  // pressure is its force over l times the depth), endless along it.
  const double l = wt.contact_length();
  const double t_load = wt.loading_time() / num.shift;
  const long steps = static_cast<long>(std::ceil(t_load / dt));
  const long ramp_steps = std::max(1L, static_cast<long>(num.ramp_fraction * steps));
  res.plate_x0 = 0.5 * (width - l);
  res.plate_x1 = 0.5 * (width + l);
  double top = 0.0;
  {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
    for (std::size_t i = 0; i < set.size(); ++i)
      if (x(i).x + r > res.plate_x0 && x(i).x - r < res.plate_x1) top = std::max(top, x(i).y + r);
  }
  // A dead load, as in 2D (run.hpp says why not a servo); its mass ten times
  // the least that keeps it stable on stiff contacts with every sphere of
  // the top layer under it (one per d^2).
  const double plate_mass = 10.0 * k_wall * (l * depth / (d * d)) * dt * dt / 4.0;
  const int plate = sim.add_wall(Wall3{{0.5 * width, top, mid.z}, {0.5 * l, 0.0, 0.0}, {0.0, 0.0, endless}, {}},
                                 wall_law, LoadControl::for_stress(0.0, l, depth, plate_mass, 0.0));
  auto ramp_to = [&](double fraction) {
    sim.set_controller(plate, LoadControl::for_stress(wt.pressure * fraction, l, depth, plate_mass, 0.0));
  };
  CentralDifference::params_type loading;
  loading.damping = num.damping;
  sim.set_integrator(loading);

  auto start = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  std::vector<Vec3> start_positions(start.data(), start.data() + start.extent(0));  // a copy, not the view
  const double to_minutes = wt.minutes / t_load;
  const auto begin = std::chrono::steady_clock::now();
  int next_sample = 1;
  Vec3 last_impulse{}, last_plate_position = sim.wall(plate).centre;
  double last_time = 0.0;
  std::vector<double> plate_work(1, 0.0);
  for (long s = 1; s <= steps; ++s) {
    if (s <= ramp_steps && (s % 50 == 1 || s == ramp_steps)) ramp_to(std::min(1.0, static_cast<double>(s) / ramp_steps));
    sim.step(dt);
    const double time = s * dt;
    if (next_sample <= num.samples && (time >= t_load * next_sample / num.samples - 0.5 * dt || s == steps)) {
      auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
      for (std::size_t i = 0; i < set.size(); ++i) {
        const Vec3 p = x(i);
        if (p.x > -r && p.x < width + r && p.y > -r && p.y < 2.0 * height) continue;
        {
          char text[600];
          std::snprintf(text, sizeof text,
                        "vrut: the 3D rutting run became unstable by loading step %ld: sphere %zu is at (%.4g, %.4g, "
                        "%.4g) mm, outside its %g x %g mm mould. The time step is %.3g of sqrt(m_min / k_max); lower "
                        "the time-step safety (RuttingNumerics::timestep_safety, 0.3 by default).",
                        s, i, p.x * 1e3, p.y * 1e3, p.z * 1e3, sp.width, sp.height, dt / sim.critical_timestep());
          throw SimulationUnstable(text, s);
        }
      }
      const Wall3 w = sim.wall(plate);
      const Vec3 impulse = sim.wall_impulse(plate);
      RuttingSample smp;
      smp.reduced_time = time;
      smp.minutes = time * to_minutes;
      smp.deformation = top - w.centre.y;
      smp.plate_pressure = -dot(impulse - last_impulse, inward_normal(w)) / (time - last_time) / (l * depth);
      plate_work[0] -= dot(impulse - last_impulse, w.centre - last_plate_position) / (time - last_time);
      last_plate_position = w.centre;
      last_impulse = impulse;
      res.samples.push_back(smp);
      check_energy(sim, energy_reference, plate_work, s, dt);
      last_time = time;
      ++next_sample;
      if (progress) progress(time / t_load, s);
    }
  }
  Kokkos::fence();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  res.steps = steps;
  res.contacts = sim.active_contacts(0);
  res.plate_y_final = sim.wall(plate).centre.y;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().group);
  for (std::size_t i = 0; i < set.size(); ++i) {
    out.final_positions.push_back(1e3 * Point3(x(i).x, x(i).y, x(i).z));
    const Vec3 u = x(i) - start_positions[i];
    out.displacement.push_back(1e3 * Point3(u.x, u.y, u.z));
    res.group.push_back(g(i));
  }
  finish_deformation(res, wt);
  return out;
}

}  // namespace vrut
