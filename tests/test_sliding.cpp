// A disk thrown along a wall with no spin: friction at mu*F_n decelerates it
// and spins it up until it rolls. Coulomb's law gives, for I = m r^2 / 2,
//   final speed 2/3 v0, sliding time v0 / (3 mu g), slip distance v0^2 / (6 mu g).
#include "spaces.hpp"

#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace {

struct SlideResult {
  double final_speed, slip, max_ratio, min_ratio_while_slipping;
};

template <class Space>
SlideResult slide(double v0, double mu, double g) {
  using namespace vrut;
  const double r = 0.01, rho = 2500.0, t = 0.05, kn = 1.0e7;
  ParticleSet set;
  const double m = rho * M_PI * r * r * t;
  set.add(0.0, r - m * g / kn, r, rho);  // resting at its static overlap
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, kn, mu));
  SimulationSettings settings;
  settings.thickness = t;
  settings.gravity = {0.0, -g};
  Simulation<Linear, Space, CentralDifference, VelocityControl> sim(set, table, settings);
  sim.add_wall(Wall{{-10.0, 0.0}, {10.0, 0.0}, {}}, linear_params(kn, kn, mu));
  auto ps = sim.particles();
  auto hv = vrut_test::to_host(ps.velocity);
  hv(0) = {v0, 0.0};
  Kokkos::deep_copy(ps.velocity, hv);

  const double dt = 0.02 * std::sqrt(m / kn);
  const double t_slide = v0 / (3.0 * mu * g);
  const long steps = static_cast<long>(1.5 * t_slide / dt);
  SlideResult res{0.0, 0.0, 0.0, 1e300};
  for (long s = 0; s < steps; ++s) {
    // Slip velocity of the contact point (centre velocity + omega x (-r n)).
    auto v = vrut_test::to_host(ps.velocity);
    auto w = vrut_test::to_host(ps.angular_velocity);
    const double slip_speed = v(0).x + w(0) * r;
    res.slip += slip_speed * dt;
    sim.step(dt);
    const WallLoad load = sim.wall_load(0);
    const double ratio = std::abs(load.force.x) / std::abs(load.force.y);
    res.max_ratio = std::max(res.max_ratio, ratio);
    if (sim.time() < 0.9 * t_slide && sim.time() > 0.05 * t_slide)
      res.min_ratio_while_slipping = std::min(res.min_ratio_while_slipping, ratio);
  }
  res.final_speed = vrut_test::to_host(ps.velocity)(0).x;
  return res;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("a disk sliding on a wall obeys Coulomb friction", "[core][physics]",
                        vrut_test::ExecutionSpaces) {
  const double v0 = 0.5, mu = 0.4, g = 9.81;
  const SlideResult res = slide<TestType>(v0, mu, g);
  INFO("max |F_s|/F_n " << res.max_ratio << ", min while slipping " << res.min_ratio_while_slipping);
  CHECK(res.max_ratio <= mu * (1.0 + 1e-9));                   // never above the cap
  CHECK(res.min_ratio_while_slipping >= mu * (1.0 - 1e-9));    // at the cap while it slides
  INFO("final speed " << res.final_speed << " expected " << 2.0 / 3.0 * v0);
  CHECK(std::abs(res.final_speed / (2.0 / 3.0 * v0) - 1.0) < 0.005);
  // The elastic stick phase of the shear spring adds mu m g / k_s, far below 1 %.
  const double expected_slip = v0 * v0 / (6.0 * mu * g);
  INFO("slip " << res.slip << " expected " << expected_slip);
  CHECK(std::abs(res.slip / expected_slip - 1.0) < 0.01);
}
