#pragma once
// A bonded hex-packed block between a fixed bottom wall and a servo plate,
// shared by the servo and modulus tests.
#include <vrut/vrut.hpp>

#include <cmath>
#include <vector>

namespace vrut_test {

struct BlockSpec {
  int columns = 30, rows = 30;
  double radius = 0.5e-3, density = 2700.0, thickness = 0.05;
  double kn = 1.0e7, ks = 1.0e7 / 2.7;  // k_s = k_n / (2 (1 + 0.35))
  double stress = 2.0e5;                // target, Pa
  double damping = 0.7;
};

template <class Space>
using BlockSimulation = vrut::Simulation<vrut::LinearBonded, Space, vrut::CentralDifference, vrut::ServoControl>;

template <class Space>
BlockSimulation<Space> make_block(const BlockSpec& b) {
  using namespace vrut;
  const ParticleSet set = hex_packing(b.columns, b.rows, b.radius, b.density);
  AssignmentTable<LinearBonded> table;
  table.set_all(linear_bonded_params(b.kn, b.ks, 0.5, 1e30, 1e30));
  SimulationSettings settings;
  settings.thickness = b.thickness;
  CentralDifference::params_type integrator;
  integrator.damping = b.damping;
  BlockSimulation<Space> sim(set, table, settings, integrator);
  sim.bond_touching_contacts(1e-9 * b.radius);
  const double width = 2.0 * b.radius * b.columns;
  const double top = b.radius * (2.0 + std::sqrt(3.0) * (b.rows - 1));
  // Frictionless walls, so the block is free to widen (uniaxial stress).
  const auto wall_law = linear_params(b.kn, 0.0, 0.0);
  sim.add_wall(Wall{{-width, 0.0}, {2.0 * width, 0.0}, {}}, wall_law);
  sim.add_wall(Wall{{2.0 * width, top}, {-width, top}, {}}, wall_law,
               ServoControl::for_stress(b.stress, width, b.thickness, b.kn, 0.2, 0.05));
  return sim;
}

// Mean height of the top row of disk centres over the bottom row's.
template <class Sim>
double row_span(const Sim& sim, const BlockSpec& b) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  double bottom = 0.0, top = 0.0;
  const int n = b.columns * b.rows;
  for (int c = 0; c < b.columns; ++c) {
    bottom += x(c).y;
    top += x(n - b.columns + c).y;
  }
  return (top - bottom) / b.columns;
}

}  // namespace vrut_test
