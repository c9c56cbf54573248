// A bonded pair pulled apart (and sheared): the bond carries the load up to
// its strength, and breaks at the first step past it, never below.
#include "spaces.hpp"

#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace {

struct PullResult {
  double max_carried = 0.0;          // largest load carried while bonded
  double load_at_break = 0.0;        // the load that broke it
  bool broke = false;
  bool broke_below_strength = false;
  bool force_after_break = false;    // any force once apart
  int bonds_after_rebuild = 0;
};

// direction {1,0}: pull along the line of centres; {0,1}: shear across it.
template <class Space>
PullResult pull(vrut::Vec2 direction, double strength, double speed) {
  using namespace vrut;
  const double r = 0.001, kn = 1.0e6, ks = 5.0e5;
  ParticleSet set;
  set.add(0.0, 0.0, r, 2700.0);
  set.add(2.0 * r, 0.0, r, 2700.0);
  AssignmentTable<LinearBonded> table;
  table.set_all(linear_bonded_params(kn, ks, 0.5, strength, strength));
  SimulationSettings settings;
  settings.thickness = 0.05;
  Simulation<LinearBonded, Space> sim(set, table, settings);
  PullResult res;
  REQUIRE(sim.bond_touching_contacts(1e-12) == 1);
  // A rebuild must keep the bond (state is matched by partner).
  sim.rebuild_contacts();
  res.bonds_after_rebuild = sim.intact_bonds();
  auto ps = sim.particles();
  auto hf = vrut_test::to_host(ps.fixity);
  hf(0) = hf(1) = prescribed_velocity | no_rotation;
  Kokkos::deep_copy(ps.fixity, hf);
  auto hv = vrut_test::to_host(ps.velocity);
  hv(0) = -0.5 * speed * direction;
  hv(1) = 0.5 * speed * direction;
  Kokkos::deep_copy(ps.velocity, hv);

  const double dt = 1e-6;
  double shear = 0.0;
  for (int s = 0; s < 100000 && !res.broke; ++s) {
    // Load the step will see: from the positions it starts from.
    auto x = vrut_test::to_host(ps.position);
    const Vec2 d = x(1) - x(0);
    const double dist = norm(d);
    const double tension = kn * (dist - 2.0 * r);
    // Shear: the incremental spring, k_s times the slip along the current
    // tangent, summed step by step (the disks do not rotate).
    shear -= ks * dot(hv(1) - hv(0), perp(d * (1.0 / dist))) * dt;
    const double load = direction.x > 0.5 ? tension : std::abs(shear);
    sim.step(dt);
    if (sim.intact_bonds() == 1) {
      res.max_carried = std::max(res.max_carried, load);
    } else {
      res.broke = true;
      res.load_at_break = load;
      res.broke_below_strength = load <= strength;
    }
  }
  sim.run(10, dt);
  auto f = vrut_test::to_host(ps.force);
  res.force_after_break = norm(f(1)) > 0.0 && direction.x > 0.5;
  return res;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("a bonded pair carries tension up to its strength and then breaks", "[core][physics]",
                        vrut_test::ExecutionSpaces) {
  const double strength = 2.0, speed = 0.01;
  const PullResult res = pull<TestType>({1.0, 0.0}, strength, speed);
  const double increment = 1.0e6 * speed * 1e-6;  // tension added per step
  INFO("max carried " << res.max_carried << ", broke at " << res.load_at_break);
  CHECK(res.bonds_after_rebuild == 1);
  REQUIRE(res.broke);
  CHECK_FALSE(res.broke_below_strength);
  CHECK(res.load_at_break <= strength + increment * 1.0001);
  CHECK(res.max_carried >= strength - increment * 1.0001);
  CHECK(res.max_carried <= strength);
  CHECK_FALSE(res.force_after_break);
}

TEMPLATE_LIST_TEST_CASE("a bonded pair carries shear up to its strength and then breaks", "[core][physics]",
                        vrut_test::ExecutionSpaces) {
  const double strength = 1.0, speed = 0.01;
  const PullResult res = pull<TestType>({0.0, 1.0}, strength, speed);
  INFO("max carried " << res.max_carried << ", broke at " << res.load_at_break);
  REQUIRE(res.broke);
  CHECK_FALSE(res.broke_below_strength);
  const double increment = 5.0e5 * speed * 1e-6;  // shear added per step
  CHECK(res.load_at_break <= strength + increment * 1.0001);
  CHECK(res.max_carried >= strength - increment * 1.0001);
  CHECK(res.max_carried <= strength);
}

TEST_CASE("bond slot decides by strength in both directions", "[core][unit]") {
  vrut::ContactBond::params_type p{3.0, 2.0};
  CHECK(vrut::ContactBond::holds(p, -3.0, 0.0));
  CHECK_FALSE(vrut::ContactBond::holds(p, -3.0000001, 0.0));
  CHECK(vrut::ContactBond::holds(p, 100.0, 2.0));
  CHECK(vrut::ContactBond::holds(p, 100.0, -2.0));
  CHECK_FALSE(vrut::ContactBond::holds(p, 100.0, -2.0000001));
}
