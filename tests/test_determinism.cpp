// Serial and OpenMP give the same trajectories: contact forces are summed in
// a fixed order on every backend, so the results are the same bits.
#include "openmp_threads.hpp"
#include "shaken_box.hpp"
#include "spaces.hpp"

#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace {

// 1,000 disks of mixed radii with random velocities fall into a box under
// gravity: collisions, friction, list rebuilds, wall loads.
template <class Space>
std::vector<double> shake(long steps) {
  using namespace vrut;
  ParticleSet set;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int row = 0; row < 25; ++row)
    for (int col = 0; col < 40; ++col)
      set.add(0.003 + 0.0025 * col, 0.003 + 0.0025 * row, 0.0008 + 0.0003 * u(rng), 2700.0, (row + col) % 2);
  auto sim = vrut_test::shaken_box_simulation<Space>(set);
  const auto wall_law = vrut_test::shaken_box_wall_law();
  sim.add_wall(Wall{{0.0, 0.0}, {0.11, 0.0}, {}}, wall_law);
  sim.add_wall(Wall{{0.0, 0.2}, {0.0, 0.0}, {}}, wall_law);
  sim.add_wall(Wall{{0.11, 0.0}, {0.11, 0.2}, {}}, wall_law);
  auto ps = sim.particles();
  auto hv = vrut_test::to_host(ps.velocity);
  for (std::size_t i = 0; i < ps.size(); ++i) hv(i) = {0.5 * (u(rng) - 0.5), 0.5 * (u(rng) - 0.5)};
  Kokkos::deep_copy(ps.velocity, hv);
  const double dt = 0.2 * sim.critical_timestep();
  sim.run(steps, dt);
  auto x = vrut_test::to_host(ps.position);
  std::vector<double> out;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    out.push_back(x(i).x);
    out.push_back(x(i).y);
  }
  return out;
}

}  // namespace

#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
TEST_CASE("Serial and OpenMP give the same positions on a 1000-disk run, bit for bit", "[core][backends]") {
  if (!vrut_test::openmp_runs_several_threads()) return;
  const long steps = 3000;
  const auto serial = shake<Kokkos::Serial>(steps);
  const auto openmp = shake<Kokkos::OpenMP>(steps);
  INFO("OpenMP threads: " << Kokkos::OpenMP::concurrency());
  REQUIRE(serial.size() == openmp.size());
  std::size_t differ = 0;
  double moved = 0.0;
  for (std::size_t i = 0; i < serial.size(); ++i) differ += serial[i] != openmp[i];
  const auto start = shake<Kokkos::Serial>(0);
  for (std::size_t i = 0; i < serial.size(); ++i) moved = std::max(moved, std::abs(serial[i] - start[i]));
  INFO(differ << " coordinates differ; largest displacement " << moved << " m");
  CHECK(moved > 1e-3);  // the disks did move and collide
  CHECK(differ == 0);
}
#endif
