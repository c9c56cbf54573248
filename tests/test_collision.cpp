// Two disks colliding head-on on a linear spring: the contact lasts
// pi sqrt(m_eff / k_n) and, without damping, the kinetic energy comes back.
#include "contact_timing.hpp"
#include "spaces.hpp"

#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace {

struct CollisionResult {
  double duration, energy_before, energy_after, m_eff, kn;
};

constexpr double r = 0.5, rho = 1000.0, kn = 1.0e5, v0 = 0.1;

// Two disks 0.01 apart on a linear spring k_n, coming together head-on at v0 each.
template <class Space>
struct HeadOn {
  vrut::Simulation<vrut::Linear, Space> sim{disks(), springs()};
  HeadOn() {
    auto hv = vrut_test::to_host(sim.particles().velocity);
    hv(0) = {v0, 0.0};
    hv(1) = {-v0, 0.0};
    Kokkos::deep_copy(sim.particles().velocity, hv);
  }
  static vrut::ParticleSet disks() {
    vrut::ParticleSet set;
    set.add(0.0, 0.0, r, rho);
    set.add(2.0 * r + 0.01, 0.0, r, rho);
    return set;
  }
  static vrut::AssignmentTable<vrut::Linear> springs() {
    vrut::AssignmentTable<vrut::Linear> table;
    table.set_all(vrut::linear_params(kn, 0.0, 0.0));
    return table;
  }
};

template <class Space>
CollisionResult collide() {
  using namespace vrut;
  HeadOn<Space> head_on;
  auto& sim = head_on.sim;
  auto ps = sim.particles();
  const double m = vrut_test::to_host(ps.mass)(0);
  const double m_eff = 0.5 * m;
  const double expected = M_PI * std::sqrt(m_eff / kn);
  const double dt = expected / 2000.0;

  auto kinetic = [&] {
    auto v = vrut_test::to_host(ps.velocity);
    return 0.5 * m * (dot(v(0), v(0)) + dot(v(1), v(1)));
  };
  auto overlap = [&] {
    auto x = vrut_test::to_host(ps.position);
    return 2.0 * r - norm(x(1) - x(0));
  };
  const double e0 = kinetic();
  const double duration = vrut_test::contact_duration(sim, dt, overlap);
  sim.run(100, dt);
  return {duration, e0, kinetic(), m_eff, kn};
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("linear collision lasts pi sqrt(m/k) and keeps energy", "[core][physics]",
                        vrut_test::ExecutionSpaces) {
  const CollisionResult res = collide<TestType>();
  const double expected = M_PI * std::sqrt(res.m_eff / res.kn);
  INFO("duration " << res.duration << " expected " << expected);
  CHECK(std::abs(res.duration / expected - 1.0) < 0.005);
  INFO("energy before " << res.energy_before << " after " << res.energy_after);
  CHECK(std::abs(res.energy_after / res.energy_before - 1.0) < 1e-6);
}

// A pair's slot in the contact list holds its load while it touches (the
// spring's k_n overlap) and a zero load from the first step it is apart, not
// only from the next rebuild: the skeleton's load path (protocol/rutting/
// skeleton.hpp) reads every slot's load and counts a nonzero one as acting.
TEMPLATE_LIST_TEST_CASE("a pair that comes apart leaves no load behind, before any rebuild", "[core][physics]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  HeadOn<TestType> head_on;
  auto& sim = head_on.sim;
  auto ps = sim.particles();
  auto overlap = [&] {
    auto x = vrut_test::to_host(ps.position);
    return 2.0 * r - norm(x(1) - x(0));
  };
  const double dt = M_PI * std::sqrt(0.5 * vrut_test::to_host(ps.mass)(0) / kn) / 2000.0;
  sim.step(dt);
  const long builds = sim.contacts().builds;
  bool touched = false;
  for (int s = 0; s < 100000; ++s) {
    const double before = overlap();  // the force pass sees the positions at the step's start
    sim.step(dt);
    const auto load = vrut_test::to_host(sim.contacts().load);
    const auto force = vrut_test::to_host(ps.force);
    REQUIRE(vrut_test::to_host(sim.contacts().count)(0) == 1);
    if (before > 0.0) {
      touched = true;
      CHECK(load(0, 0).force.x == Approx(kn * before).epsilon(1e-12));  // on disk 1, pushed along +x
      CHECK(force(1).x == Approx(kn * before).epsilon(1e-12));
    } else if (touched) {  // the first step apart
      REQUIRE(sim.contacts().builds == builds);  // no rebuild cleared the list meanwhile
      CHECK(load(0, 0).force.x == 0.0);
      CHECK(load(0, 0).force.y == 0.0);
      CHECK(force(0).x == 0.0);
      CHECK(force(1).x == 0.0);
      break;
    }
  }
  CHECK(touched);
}
