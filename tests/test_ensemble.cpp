// Ensembles: several specimens in one Simulation share every kernel launch but
// never interact, so each must follow, bit for bit, the trajectory of its own
// single run. The specimens below overlap in space on purpose: only the
// specimen index keeps them apart.
#include "report_checks.hpp"
#include "rutting_checks.hpp"
#include "scratch.hpp"
#include "shaken_box.hpp"
#include "spaces.hpp"

#include <vrut/app/ranks.hpp>
#include <vrut/app/rutting_report.hpp>
#include <vrut/protocol/rutting.hpp>
#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <random>
#include <type_traits>
#include <vector>

namespace {

// A box of disks of mixed radii with random velocities falling under
// gravity: collisions, friction, list rebuilds, wall loads. `seed` changes the
// radii and velocities, `rows` the disk count (so the specimens differ in size
// and in how they split into the wall-load blocks).
vrut::ParticleSet box_disks(unsigned seed, int rows) {
  vrut::ParticleSet set;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < 40; ++col)
      set.add(0.003 + 0.0025 * col, 0.003 + 0.0025 * row, 0.0008 + 0.0003 * u(rng), 2700.0, (row + col) % 2);
  return set;
}

std::vector<vrut::Vec2> box_velocities(unsigned seed, std::size_t n) {
  std::mt19937 rng(seed + 1000);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<vrut::Vec2> v(n);
  for (auto& x : v) x = {0.5 * (u(rng) - 0.5), 0.5 * (u(rng) - 0.5)};
  return v;
}

struct Box {
  unsigned seed;
  int rows;
};

// Runs the given boxes as one ensemble; returns each box's final positions
// (x, y interleaved) and the impulse its disks gave its bottom wall.
template <class Space>
std::vector<std::vector<double>> run_boxes(const std::vector<Box>& boxes, long steps) {
  using namespace vrut;
  ParticleSet all;
  std::vector<Vec2> velocity;
  for (const Box& b : boxes) {
    const ParticleSet one = box_disks(b.seed, b.rows);
    all.append_specimen(one);
    const auto v = box_velocities(b.seed, one.size());
    velocity.insert(velocity.end(), v.begin(), v.end());
  }
  auto sim = vrut_test::shaken_box_simulation<Space>(all);
  const auto wall_law = vrut_test::shaken_box_wall_law();
  std::vector<int> bottom;
  for (int e = 0; e < static_cast<int>(boxes.size()); ++e) {
    bottom.push_back(sim.add_wall(Wall{{0.0, 0.0}, {0.11, 0.0}, {}}, wall_law, {}, e));
    sim.add_wall(Wall{{0.0, 0.2}, {0.0, 0.0}, {}}, wall_law, {}, e);
    sim.add_wall(Wall{{0.11, 0.0}, {0.11, 0.2}, {}}, wall_law, {}, e);
  }
  auto hv = vrut_test::to_host(sim.particles().velocity);
  for (std::size_t i = 0; i < velocity.size(); ++i) hv(i) = velocity[i];
  Kokkos::deep_copy(sim.particles().velocity, hv);
  // The time step of this box alone (all boxes share the lightest disk size
  // range, so dt is the same whichever boxes run together).
  sim.run(steps, 2.0e-6);
  auto x = vrut_test::to_host(sim.particles().position);
  std::vector<std::vector<double>> out;
  for (int e = 0; e < static_cast<int>(boxes.size()); ++e) {
    std::vector<double> v;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      v.push_back(x(i).x);
      v.push_back(x(i).y);
    }
    const Vec2 impulse = sim.wall_impulse(bottom[e]);
    v.push_back(impulse.x);
    v.push_back(impulse.y);
    out.push_back(v);
  }
  return out;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("each specimen of an ensemble follows its single run bit for bit", "[core][ensemble]",
                        vrut_test::ExecutionSpaces) {
  // Three boxes of 1000, 1200 and 600 disks, all in the same space.
  const std::vector<Box> boxes = {{42, 25}, {7, 30}, {3, 15}};
  const long steps = 10000;
  const auto together = run_boxes<TestType>(boxes, steps);
  REQUIRE(together.size() == boxes.size());
  // The single runs on the default host space (so a host backend's ensemble
  // is also held to that space's bits), except on a GPU: its arithmetic differs from the
  // CPU's in the last bits (nvcc fuses a * b + c into one rounding, the
  // host compiler does not), which the boxes' collisions amplify; seen on an
  // H200 (2026-12-04). There the single runs are the GPU's own.
  using Single = std::conditional_t<
      Kokkos::SpaceAccessibility<Kokkos::HostSpace, typename TestType::memory_space>::accessible,
      Kokkos::DefaultHostExecutionSpace, TestType>;
  for (std::size_t e = 0; e < boxes.size(); ++e) {
    const auto alone = run_boxes<Single>({boxes[e]}, steps).front();
    const auto start = run_boxes<Kokkos::DefaultHostExecutionSpace>({boxes[e]}, 0).front();
    REQUIRE(alone.size() == together[e].size());
    std::size_t differing = 0;
    double moved = 0.0;
    for (std::size_t k = 0; k < alone.size(); ++k) {
      differing += alone[k] != together[e][k];
      if (k + 2 < alone.size()) moved = std::max(moved, std::abs(alone[k] - start[k]));
    }
    INFO("box " << e << ": " << differing << " of " << alone.size() << " values differ; largest displacement "
                << moved << " m; impulse on the bottom wall " << alone.back() << " N s");
    CHECK(moved > 1e-3);                    // the disks did move and collide
    CHECK(alone.back() < 0.0);              // the disks hit their bottom wall (pushing it down)
    CHECK(differing == 0);
  }
}

TEST_CASE("a wall of one specimen does not touch the disks of another", "[core][ensemble]") {
  using namespace vrut;
  // Two single disks at the same place, falling onto a floor that only the
  // first specimen has: the first bounces on it, the second falls through.
  ParticleSet one;
  one.add(0.0, 0.001, 0.001, 2700.0);
  ParticleSet all;
  all.append_specimen(one);
  all.append_specimen(one);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(1e5, 0.0, 0.0));
  SimulationSettings settings;
  settings.thickness = 0.01;
  settings.gravity = {0.0, -9.81};
  Simulation<Linear, Kokkos::DefaultHostExecutionSpace> sim(all, table, settings, {0.0});
  REQUIRE(sim.specimens() == 2);
  sim.add_wall(Wall{{-1.0, 0.0}, {1.0, 0.0}, {}}, linear_params(1e5, 0.0, 0.0), {}, 0);
  const long n = 20000;
  const double dt = 1e-5;
  sim.run(n, dt);  // 0.2 s: free fall would cover 0.196 m
  auto x = vrut_test::to_host(sim.particles().position);
  CHECK(x(0).y > 0.0);      // held by the floor (an elastic bounce never rises above the start)
  CHECK(x(0).y < 0.0011);
  // Free fall from rest under the leapfrog (velocities at half steps, the
  // first half step from v = 0): x_n = x_0 - g dt^2 n (n + 1) / 2, which is
  // the exact 0.5 g t^2 made longer by dt / t = 5e-5. To rounding (n steps
  // of 1e-16 relative each), and 5e-5 from the exact fall.
  const double leapfrog = 0.001 - 9.81 * dt * dt * n * (n + 1) / 2.0, exact = 0.001 - 0.5 * 9.81 * 0.2 * 0.2;
  CHECK(x(1).y == Approx(leapfrog).epsilon(1e-10));
  CHECK((x(1).y - 0.001) / (exact - 0.001) - 1.0 == Approx(dt / 0.2).epsilon(1e-6));
  CHECK(sim.active_contacts() == 0);  // the two coincident disks are not a contact
  CHECK_THROWS_WITH(sim.add_wall(Wall{{-1.0, 0.0}, {1.0, 0.0}, {}}, linear_params(1e5, 0.0, 0.0), {}, 2),
                    Catch::Contains("specimen 2"));
}

TEST_CASE("specimens must be contiguous and in order", "[core][ensemble]") {
  using namespace vrut;
  ParticleSet set;
  set.add(0.0, 0.0, 0.001, 2700.0);
  set.add(0.01, 0.0, 0.001, 2700.0);
  set.specimen = {1, 0};
  AssignmentTable<Linear> table;
  table.set_all(linear_params(1e5, 0.0, 0.0));
  using Sim = Simulation<Linear, Kokkos::DefaultHostExecutionSpace>;
  CHECK_THROWS_WITH(Sim(set, table), Catch::Contains("contiguous"));
  set.specimen = {0};
  CHECK_THROWS_WITH(Sim(set, table), Catch::Contains("wrong length"));
}

namespace {

// The whole rutting protocol over an ensemble of three different specimens
// (two mixes, two seeds) against three single runs: every number each
// reports equal (rutting_checks.hpp), its skeleton's record included, so
// that a specimen e > 0 read with specimen 0's stones or particles fails.
void check_ensemble_against_single_runs(const vrut::RuttingMaterials& materials) {
  std::vector<vrut::Specimen> specimens;
  for (auto [mix, seed] : {std::pair<int, int>{2, 3}, {2, 4}, {3, 3}}) {
    vrut::SpecimenSettings s;
    s.gradation = vrut::builtin_gradation(mix);
    s.placement.width = 60.0;
    s.placement.height = 30.0;
    s.disk_radius = 1.0;
    s.seed = seed;
    specimens.push_back(vrut::generate_specimen(s));
  }
  vrut::WheelTracking wt;
  wt.minutes = 6.0;
  wt.ds_from_minute = 4.0;
  vrut::RuttingNumerics num;
  num.settle_steps = 1000;
  num.samples = 30;
  const auto together = vrut::run_rutting_ensemble<Kokkos::DefaultHostExecutionSpace>(specimens, wt, materials, num);
  REQUIRE(together.size() == specimens.size());
  for (std::size_t e = 0; e < specimens.size(); ++e) {
    const auto alone = vrut::run_rutting<Kokkos::DefaultHostExecutionSpace>(specimens[e], wt, materials, num);
    INFO("specimen " << e << ": rut " << alone.deformation_final * 1e3 << " mm alone, "
                     << together[e].deformation_final * 1e3 << " mm in the ensemble");
    CHECK(alone.deformation_final > 0.1e-3);  // the plate went down
    // Minute 5's load path lies inside these 6 minutes, so it is compared too.
    REQUIRE(alone.skeleton.load_early.measured());
    vrut_test::require_same(together[e], alone);
  }
  vrut_test::check_skeleton_reports(together, wt);
}

}  // namespace

TEST_CASE("an ensemble rutting run gives each specimen its single-run result", "[rutting][ensemble]") {
  check_ensemble_against_single_runs({});
}

// With rigid stones (the default) the bodies of every specimen are numbered
// after the last one's, and each keeps to its own specimen; the method's
// exact stones have no bodies.
TEST_CASE("an ensemble with the method's exact stones gives each specimen its single-run result",
          "[rutting][ensemble]") {
  vrut::RuttingMaterials exact;
  exact.rigid_stones = false;
  check_ensemble_against_single_runs(exact);
}

// vrut-rutting starts MPI only where a launcher started it: each launcher's
// own variable says so, and nothing else does (an empty one, or VRUT_MPI set
// to anything but 1, runs as one process without MPI's start-up).
TEST_CASE("MPI starts under each launcher's variable and only there", "[unit]") {
  using vrut::app::ranks::launched_by_mpi;
  auto with = [](std::string name, std::string value) {
    return [name, value](const char* asked) -> const char* { return name == asked ? value.c_str() : nullptr; };
  };
  CHECK_FALSE(launched_by_mpi([](const char*) -> const char* { return nullptr; }));
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MV2_COMM_WORLD_SIZE"}) {
    INFO(name);
    CHECK(launched_by_mpi(with(name, "2")));
    CHECK_FALSE(launched_by_mpi(with(name, "")));
  }
  CHECK(launched_by_mpi(with("VRUT_MPI", "1")));
  CHECK_FALSE(launched_by_mpi(with("VRUT_MPI", "0")));
  CHECK_FALSE(launched_by_mpi(with("SLURM_PROCID", "0")));  // a scheduler's job, not an MPI launcher's
}
