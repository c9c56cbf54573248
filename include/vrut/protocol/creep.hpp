#pragma once
// Virtual uniaxial creep test: a hex-packed, fully bonded, all-mastic block
// between a fixed bottom wall and a top plate held at a constant stress by a
// dead load, both frictionless (the sides are free). The strain is measured
// between the bottom and top rows of disk centres, so the compliance of the
// wall contacts does not enter. Time runs reduced by the shift factor; the
// samples carry both times.
#include <vrut/contact/composite.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/core/simulation.hpp>
#include <vrut/material/burgers_parameters.hpp>
#include <vrut/servo/servo.hpp>

#include <Kokkos_Core.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace vrut {

struct CreepSettings {
  int columns = 20, rows = 10;
  double radius = 0.5e-3;      // m
  double thickness = 0.05;     // m, disk width t
  double density = 2400.0;     // kg/m^3, mastic
  double stress = 0.7e6;       // Pa
  double duration = 342.2;     // s, real (unshifted) loading time
  double shift = 1e4;          // alpha_T
  BurgersMacro macro;
  double nu = 0.35;
  MicroConversion conversion = MicroConversion::seed();
  double damping = 0.3;        // local damping (disks and plate)
  double timestep_safety = 0.2;
  int points = 100;            // samples written

  void validate() const {
    macro.validate();
    validate_poisson(nu);
    TimeShift{shift};
    auto positive = [](double v, const char* what) {
      if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be positive");
    };
    positive(radius, "disk radius");
    positive(thickness, "thickness");
    positive(density, "density");
    positive(stress, "stress");
    positive(duration, "duration");
    positive(timestep_safety, "time-step safety factor");
    if (columns < 2 || rows < 2) throw std::invalid_argument("the creep block needs at least 2 x 2 disks");
    if (points < 2) throw std::invalid_argument("at least 2 points");
    if (!(damping >= 0.0 && damping < 1.0)) throw std::invalid_argument("damping must lie in [0, 1)");
  }
};

struct CreepSample {
  double time = 0.0, reduced_time = 0.0, strain_virtual = 0.0, strain_analytic = 0.0;
  double plate_stress = 0.0;  // Pa, measured
};

struct CreepResult {
  std::vector<CreepSample> samples;
  std::size_t particles = 0;
  long steps = 0;
  double dt = 0.0;  // reduced time step
  double wall_seconds = 0.0;
};

// progress(done_steps, total_steps) is called now and then.
template <class Space>
CreepResult run_creep(const CreepSettings& cs, const Space& space = Space(),
                      const std::function<void(long, long)>& progress = {}) {
  cs.validate();
  const TimeShift shift(cs.shift);
  const BurgersMacro reduced = cs.macro.shifted(shift);
  AssignmentTable<BurgersBonded> table;
  table.set_all(mastic_params(reduced, cs.thickness, cs.nu, cs.conversion));
  SimulationSettings settings;
  settings.thickness = cs.thickness;
  CentralDifference::params_type integrator;
  integrator.damping = cs.damping;
  Simulation<BurgersBonded, Space, CentralDifference, LoadControl> sim(
      hex_packing(cs.columns, cs.rows, cs.radius, cs.density), table, settings, integrator, space);
  sim.bond_touching_contacts(1e-9 * cs.radius);

  const double r = cs.radius;
  const double width = 2.0 * r * cs.columns + r;
  const double top = r * (2.0 + std::sqrt(3.0) * (cs.rows - 1));
  const double k_wall = table(0, 0).normal.maxwell_stiffness;
  const auto wall_law = linear_params(k_wall, 0.0, 0.0);
  sim.add_wall(Wall{{-width, 0.0}, {2.0 * width, 0.0}, {}}, wall_law);
  // The plate carries a dead load, as in a creep frame; it weighs as much as a row of disks.
  const double row_mass = cs.columns * cs.density * 3.14159265358979323846 * r * r * cs.thickness;
  const int plate = sim.add_wall(Wall{{2.0 * width, top}, {-width, top}, {}}, wall_law,
                                 LoadControl::for_stress(cs.stress, 2.0 * r * cs.columns, cs.thickness, row_mass, cs.damping));
  const double dt = cs.timestep_safety * sim.critical_timestep();

  const double t_end = shift.reduced_time(cs.duration);
  const long steps = static_cast<long>(std::ceil(t_end / dt));
  const int n = static_cast<int>(sim.particles().size());
  auto span = [&] {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
    double bottom = 0.0, upper = 0.0;
    for (int c = 0; c < cs.columns; ++c) {
      bottom += x(c).y;
      upper += x(n - cs.columns + c).y;
    }
    return (upper - bottom) / cs.columns;
  };
  const double span0 = span();

  CreepResult res;
  res.particles = sim.particles().size();
  res.steps = steps;
  res.dt = dt;
  const auto start = std::chrono::steady_clock::now();
  int next = 1;
  for (long s = 1; s <= steps; ++s) {
    sim.step(dt);
    const double t = s * dt;
    if (next <= cs.points && (t >= t_end * next / cs.points - 0.5 * dt || s == steps)) {
      CreepSample sample;
      sample.reduced_time = t;
      sample.time = shift.real_time(t);
      sample.strain_virtual = 1.0 - span() / span0;
      sample.strain_analytic = cs.macro.creep_strain(cs.stress, sample.time);
      sample.plate_stress = ServoControl::compressive_force(sim.wall(plate), sim.wall_load(plate)) /
                            (2.0 * r * cs.columns * cs.thickness);
      res.samples.push_back(sample);
      ++next;
      if (progress) progress(s, steps);
    }
  }
  Kokkos::fence();
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace vrut
