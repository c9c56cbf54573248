// Drops two disks on a wall through the installed package and checks they settle.
#include <vrut/vrut.hpp>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  vrut::ParticleSet set;
  set.add(0.0, 0.0011, 0.001, 2700.0);
  set.add(0.0, 0.0035, 0.001, 2700.0);
  vrut::AssignmentTable<vrut::Linear> table;
  table.set_all(vrut::linear_params(1e5, 5e4, 0.5));
  vrut::SimulationSettings settings;
  settings.thickness = 0.05;
  settings.gravity = {0.0, -9.81};
  vrut::Simulation<vrut::Linear> sim(set, table, settings, {0.7});
  sim.add_wall(vrut::Wall{{-1.0, 0.0}, {1.0, 0.0}, {}}, vrut::linear_params(1e5, 5e4, 0.5));
  const double dt = 0.2 * sim.critical_timestep();
  sim.run(20000, dt);
  // At rest, the wall carries the weight of both disks.
  const double weight = 2.0 * 2700.0 * M_PI * 1e-6 * 0.05 * 9.81;
  const double carried = -sim.wall_load(0).force.y;
  std::printf("wall carries %.6g N of %.6g N weight\n", carried, weight);
  return std::abs(carried / weight - 1.0) < 1e-3 ? 0 : 1;
}
