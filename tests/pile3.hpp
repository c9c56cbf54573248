#pragma once
// A pile of 216 spheres on a jittered lattice, and a clump of three on top,
// dropped onto a floor plate in a box periodic along x and y, with the
// damped linear law, friction and local damping: every kernel of the 3D
// engine, contacts through the faces and a rigid body included. Shared by
// the backend and checkpoint tests.
#include <vrut/vrut.hpp>

#include <Kokkos_Core.hpp>

#include <vector>

namespace vrut_test {

template <class Space>
using PileSimulation =
    vrut::Simulation3<vrut::DampedLinear, Space, vrut::CentralDifference, vrut::VelocityControl, vrut::DampedLinear>;

template <class Space>
PileSimulation<Space> make_pile() {
  using namespace vrut;
  const double r = 0.002, rho = 2500.0, kn = 1e5, side = 0.024;
  ParticleSet set;
  unsigned seed = 12345;
  auto jitter = [&] {
    seed = seed * 1103515245u + 12345u;
    return 0.1 * r * (static_cast<double>((seed >> 16) & 0x7fff) / 32767.0 - 0.5);
  };
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i)
        set.add_sphere((i + 0.5) * side / 6 + jitter(), (j + 0.5) * side / 6 + jitter(), r * (1.1 + 2.05 * k) + jitter(),
                       r * (0.8 + 0.1 * ((i + j + k) % 3)), rho);
  for (int m = -1; m <= 1; ++m)  // a rod of three touching spheres, tilted
    set.add_sphere(0.5 * side + 1.6 * r * m, 0.5 * side, r * (13.8 + 0.5 * m), 0.8 * r, rho, 0, 0);
  AssignmentTable<DampedLinear> table;
  table.set_all(damped_linear_params(kn, 0.5 * kn, 0.5, 0.1));
  SimulationSettings3 settings;
  settings.gravity = {0.0, 0.0, -9.81};
  settings.box.high = {side, side, 1.0};
  settings.box.periodic[0] = settings.box.periodic[1] = true;
  PileSimulation<Space> sim(set, table, settings, CentralDifference::params_type{0.3});
  sim.add_wall(Wall3{{0.5 * side, 0.5 * side, 0.0}, {side, 0.0, 0.0}, {0.0, side, 0.0}, {}},
               damped_linear_params(kn, 0.5 * kn, 0.5, 0.1));
  return sim;
}

// Every sphere's position, velocity and spin, and the clump's angular
// momentum, as one list of numbers.
template <class Sim>
std::vector<double> pile_motion(const Sim& sim) {
  std::vector<double> out;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().velocity);
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().angular_velocity);
  for (std::size_t i = 0; i < x.extent(0); ++i)
    for (const vrut::Vec3& q : {x(i), v(i), w(i)}) out.insert(out.end(), {q.x, q.y, q.z});
  auto l = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.bodies().angular_momentum);
  for (std::size_t b = 0; b < l.extent(0); ++b) out.insert(out.end(), {l(b).x, l(b).y, l(b).z});
  return out;
}

}  // namespace vrut_test
