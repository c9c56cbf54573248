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

template <class Space>
CollisionResult collide() {
  using namespace vrut;
  const double r = 0.5, rho = 1000.0, kn = 1.0e5, v0 = 0.1;
  ParticleSet set;
  set.add(0.0, 0.0, r, rho);
  set.add(2.0 * r + 0.01, 0.0, r, rho);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, 0.0, 0.0));
  Simulation<Linear, Space> sim(set, table);
  auto ps = sim.particles();
  auto hv = vrut_test::to_host(ps.velocity);
  hv(0) = {v0, 0.0};
  hv(1) = {-v0, 0.0};
  Kokkos::deep_copy(ps.velocity, hv);
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
