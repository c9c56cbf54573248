#pragma once
// Energy created by the integration: the sign of an unstable run that has not
// (yet) thrown any disk far. Host-only.
//
// Every contact law of vrut stores energy (springs, bonds) or dissipates it
// (dashpots, friction, damping); none makes it. So the kinetic energy of a
// specimen can never exceed what was put in: the work of gravity
// (m g . displacement, summed), and what the caller knows of (the work of
// moving walls, a kinetic energy given at the start).
// A kinetic energy above twice that is energy the time stepping made,
// which a step too large for the stiffest contact does long before a disk
// jumps a diameter. The allowance (the whole specimen dropping one disk
// radius) lets a specimen at rest, with no work done yet, pass.
#include <vrut/core/simulation.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace vrut {

// A spin's square: about the out-of-plane axis in 2D, a vector's in 3D.
inline double spin_squared(double w) { return w * w; }
inline double spin_squared(Vec3 w) { return dot(w, w); }

struct SpecimenEnergy {
  double kinetic = 0.0;       // J, translation and rotation
  double gravity_work = 0.0;  // J, since the reference positions
  double allowance = 0.0;     // J, the specimen dropping one disk radius
};

// Per specimen of sim: kinetic energy, and gravity's work since `reference`
// (positions as a host array, one per disk).
template <class Sim, class HostPositions>
std::vector<SpecimenEnergy> specimen_energies(Sim& sim, const HostPositions& reference) {
  const auto& ps = sim.particles();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.position);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.velocity);
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.angular_velocity);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.mass);
  auto inertia = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.inertia);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.radius);
  const auto g = sim.settings().gravity;  // Vec2 or Vec3
  std::vector<SpecimenEnergy> out(sim.specimens());
  for (int s = 0; s < sim.specimens(); ++s) {
    const auto [first, last] = sim.specimen_range(s);
    for (int i = first; i < last; ++i) {
      out[s].kinetic += 0.5 * m(i) * dot(v(i), v(i)) + 0.5 * inertia(i) * spin_squared(w(i));
      out[s].gravity_work += m(i) * dot(g, x(i) - reference(i));
      out[s].allowance += m(i) * norm(g) * r(i);
    }
  }
  return out;
}

// Throws SimulationUnstable when a specimen has more kinetic energy than
// twice the energy put in plus the allowance. energy_in: per specimen, the
// energy put in since the reference other than by gravity (J); empty for none.
template <class Sim, class HostPositions>
void check_energy(Sim& sim, const HostPositions& reference, const std::vector<double>& energy_in, long step,
                  double dt) {
  const std::vector<SpecimenEnergy> e = specimen_energies(sim, reference);
  for (int s = 0; s < static_cast<int>(e.size()); ++s) {
    const double work = e[s].gravity_work + (energy_in.empty() ? 0.0 : energy_in[s]);
    if (e[s].kinetic <= 2.0 * std::fmax(work, 0.0) + e[s].allowance) continue;
    char text[512];
    std::snprintf(text, sizeof text,
                  "vrut: the simulation became unstable by step %ld: specimen %d has %.4g J of kinetic energy, more "
                  "than the %.4g J put in by gravity and the loads (twice that plus %.3g J allowed); "
                  "the time stepping is making energy. The time step %.4g s is %.3g of sqrt(m_min / k_max); dense "
                  "packings need 0.1 to 0.3 of it.",
                  step, s, e[s].kinetic, work, e[s].allowance, dt, dt / sim.critical_timestep());
    throw SimulationUnstable(text, step);
  }
}

// Where the particles are now, as a host copy to measure gravity's work
// from: on a host backend create_mirror_view_and_copy would hand back the
// positions themselves, and the work would always read 0.
template <class Sim>
Kokkos::View<typename Sim::vector*, Kokkos::HostSpace> host_positions_copy(const Sim& sim) {
  Kokkos::View<typename Sim::vector*, Kokkos::HostSpace> out("energy_reference", sim.particles().size());
  Kokkos::deep_copy(out, sim.particles().position);
  return out;
}

// Runs `steps` steps, checking the energy against `reference` every 500;
// after each 500 (and the last), each(steps done, steps) where given.
template <class Sim, class HostPositions>
void run_checking_energy(Sim& sim, long steps, double dt, const HostPositions& reference,
                         const std::function<void(long, long)>& each = {}) {
  constexpr long every = 500;
  for (long done = 0; done < steps; done += every) {
    sim.run(std::min(every, steps - done), dt);
    check_energy(sim, reference, {}, sim.steps(), dt);
    if (each) each(std::min(done + every, steps), steps);
  }
}

}  // namespace vrut
