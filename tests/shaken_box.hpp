#pragma once
// The materials of the shaken box that the determinism and ensemble tests
// share: two groups of linear frictional contacts, gravity, light damping.
#include <vrut/vrut.hpp>

namespace vrut_test {

template <class Space>
vrut::Simulation<vrut::Linear, Space> shaken_box_simulation(const vrut::ParticleSet& set) {
  using namespace vrut;
  AssignmentTable<Linear> table(2);
  table.set(0, 0, linear_params(1e6, 5e5, 0.5));
  table.set(1, 1, linear_params(2e6, 1e6, 0.3));
  table.set(0, 1, linear_params(1.5e6, 7e5, 0.4));
  SimulationSettings settings;
  settings.thickness = 0.05;
  settings.gravity = {0.0, -9.81};
  CentralDifference::params_type integrator;
  integrator.damping = 0.1;
  return Simulation<Linear, Space>(set, table, settings, integrator);
}

inline vrut::Linear::params_type shaken_box_wall_law() { return vrut::linear_params(2e6, 1e6, 0.5); }

}  // namespace vrut_test
