// A time step far above the critical one makes a run blow up; the engine must
// say so, naming the step, within a few steps of the first disk that jumps
// more than a diameter in one step or goes non-finite (here the speeds reach
// 1e29 m/s and the bonds break long before any value overflows).
#include "block.hpp"
#include "spaces.hpp"

#include <vrut/core/energy_check.hpp>

#include <catch2/catch.hpp>

#include <cmath>

TEST_CASE("a blown-up run is reported with its step", "[core][instability]") {
  using Space = Kokkos::DefaultHostExecutionSpace;
  vrut_test::BlockSpec spec;
  spec.columns = spec.rows = 10;
  spec.damping = 0.0;
  // A block at rest is at equilibrium, where even an unstable scheme stays
  // put: kick every disk, the same way in both runs below.
  auto kicked = [&] {
    auto sim = vrut_test::make_block<Space>(spec);
    auto v = vrut_test::to_host(sim.particles().velocity);
    for (std::size_t i = 0; i < v.extent(0); ++i) v(i) = {1e-3 * std::sin(1.0 + i), 1e-3 * std::cos(2.0 * i)};
    Kokkos::deep_copy(sim.particles().velocity, v);
    return sim;
  };
  auto watched = kicked();
  const double dt = 3.0 * watched.critical_timestep();  // central differences need dt < 2 sqrt(m/k) on one spring
  // The step of the first such jump, found independently: one step at a
  // time, every position compared on the host with the one before.
  const double diameter = 2.0 * spec.radius;
  long first_jump = -1;
  // A copy of its own: on the host, to_host returns the engine's own view.
  Kokkos::View<vrut::Vec2*, Kokkos::HostSpace> before("before", watched.particles().size());
  Kokkos::deep_copy(before, watched.particles().position);
  for (long s = 1; s <= 20000 && first_jump < 0; ++s) {
    try {
      watched.step(dt);
    } catch (const vrut::SimulationUnstable&) {
      FAIL("the engine reported an instability before any disk had jumped a diameter");
    }
    auto x = vrut_test::to_host(watched.particles().position);
    for (std::size_t i = 0; i < x.extent(0); ++i)
      if (!(std::hypot(x(i).x - before(i).x, x(i).y - before(i).y) <= diameter)) first_jump = s;
    Kokkos::deep_copy(before, x);
  }
  REQUIRE(first_jump > 0);  // it did blow up
  auto sim = kicked();
  long reported = -1;
  std::string message;
  try {
    sim.run(first_jump + 1000, dt);
  } catch (const vrut::SimulationUnstable& e) {
    reported = e.step();
    message = e.what();
  }
  INFO("first jump of a diameter in step " << first_jump << "; reported: " << message);
  CHECK(reported >= first_jump);
  CHECK(reported <= first_jump + 100);
  CHECK_THAT(message, Catch::Contains("step " + std::to_string(reported)) && Catch::Contains("disk") &&
                          Catch::Contains("of sqrt(m_min / k_max)"));
  // A stable run is never reported: the same block at a fifth of the critical step.
  auto calm = kicked();
  CHECK_NOTHROW(calm.run(3000, 0.2 * calm.critical_timestep()));
}

// The energy check (core/energy_check.hpp): a kicked, bonded block with
// no gravity and no walls keeps at most the kinetic energy of the kick,
// however its springs trade it; an unstable time step makes more, and the
// check sees it before any disk has jumped a diameter.
TEST_CASE("energy made by an unstable time step is reported before any disk jumps", "[core][instability]") {
  using Space = Kokkos::DefaultHostExecutionSpace;
  using Sim = vrut::Simulation<vrut::LinearBonded, Space>;
  const vrut_test::BlockSpec spec;
  vrut::AssignmentTable<vrut::LinearBonded> table;
  table.set_all(vrut::linear_bonded_params(spec.kn, spec.ks, 0.5, 1e30, 1e30));
  vrut::SimulationSettings settings;
  settings.thickness = spec.thickness;
  const vrut::ParticleSet set = vrut::hex_packing(10, 10, spec.radius, spec.density);
  auto free_block = [&] {
    Sim sim(set, table, settings);
    sim.bond_touching_contacts(1e-9 * spec.radius);
    return sim;
  };
  auto sim = free_block();
  auto v = vrut_test::to_host(sim.particles().velocity);
  auto m = vrut_test::to_host(sim.particles().mass);
  double kick = 0.0;  // J, worked out here from the masses and speeds given
  for (std::size_t i = 0; i < v.extent(0); ++i) {
    v(i) = {1e-3 * std::sin(1.0 + i), 1e-3 * std::cos(2.0 * i)};
    kick += 0.5 * m(i) * (v(i).x * v(i).x + v(i).y * v(i).y);
  }
  Kokkos::deep_copy(sim.particles().velocity, v);
  Kokkos::View<vrut::Vec2*, Kokkos::HostSpace> reference("reference", sim.particles().size());
  Kokkos::deep_copy(reference, sim.particles().position);
  const std::vector<double> energy_in{kick};
  const auto start = vrut::specimen_energies(sim, reference);
  CHECK(start[0].kinetic == Approx(kick).epsilon(1e-12));
  CHECK(start[0].gravity_work == 0.0);

  SECTION("a stable step keeps the energy of the kick") {
    auto calm = free_block();
    Kokkos::deep_copy(calm.particles().velocity, v);
    const double dt = 0.2 * calm.critical_timestep();
    for (int chunk = 0; chunk < 30; ++chunk) {
      calm.run(100, dt);
      REQUIRE_NOTHROW(vrut::check_energy(calm, reference, energy_in, calm.steps(), dt));
    }
  }
  SECTION("an unstable step is caught by its energy first") {
    const double dt = 3.0 * sim.critical_timestep();
    std::string message;
    long caught = -1;
    for (long s = 1; s <= 20000 && caught < 0; ++s) {
      sim.step(dt);  // throws (failing the test) if a disk jumps a diameter first
      try {
        vrut::check_energy(sim, reference, energy_in, s, dt);
      } catch (const vrut::SimulationUnstable& e) {
        caught = e.step();
        message = e.what();
      }
    }
    REQUIRE(caught > 0);
    CHECK_THAT(message, Catch::Contains("kinetic energy") && Catch::Contains("specimen 0") &&
                            Catch::Contains("step " + std::to_string(caught)));
  }
}
