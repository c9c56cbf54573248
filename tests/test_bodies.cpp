// Rigid bodies (clumps) against closed forms: free flight and spin, momentum
// and angular momentum through a collision of two bodies, a body resting on
// a wall, and a rigid stone against the same stone of stiffly bonded disks.
#include "spaces.hpp"

#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {

constexpr double r = 0.001, rho = 2700.0, t = 0.05;

// An L of three touching disks (the corner at `corner`), members of `body`:
// no symmetry, so its centre of mass lies off every member.
void add_ell(vrut::ParticleSet& set, vrut::Vec2 corner, int body, int group = 0) {
  set.add(corner.x, corner.y, r, rho, group, body);
  set.add(corner.x + 2.0 * r, corner.y, r, rho, group, body);
  set.add(corner.x, corner.y + 2.0 * r, r, rho, group, body);
}

vrut::SimulationSettings settings(vrut::Vec2 gravity = {}) {
  vrut::SimulationSettings s;
  s.thickness = t;
  s.gravity = gravity;
  return s;
}

struct Momenta {
  vrut::Vec2 linear;
  double angular = 0.0;  // about the origin
};

// Of the bodies, from their own state: sum M V, and sum I w + M X x V.
template <class Sim>
Momenta body_momenta(const Sim& sim) {
  const auto& b = sim.bodies();
  auto X = vrut_test::to_host(b.position);
  auto V = vrut_test::to_host(b.velocity);
  auto M = vrut_test::to_host(b.mass);
  auto I = vrut_test::to_host(b.inertia);
  auto w = vrut_test::to_host(b.angular_velocity);
  Momenta p;
  for (std::size_t k = 0; k < X.extent(0); ++k) {
    p.linear += M(k) * V(k);
    p.angular += I(k) * w(k) + M(k) * vrut::cross(X(k), V(k));
  }
  return p;
}

}  // namespace

// No force: the centre moves at constant velocity and the body turns at a
// constant rate, so after n steps X = X0 + n dt V and theta = n dt w, to
// rounding; the members keep their places in the body (distances to 1e-12
// of a radius) and, touching, are never a contact.
TEMPLATE_LIST_TEST_CASE("a rigid body flies and spins freely", "[bodies][physics]", vrut_test::ExecutionSpaces) {
  using namespace vrut;
  ParticleSet set;
  add_ell(set, {0.0, 0.0}, 0);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(1e6, 0.0, 0.0));
  Simulation<Linear, TestType> sim(set, table, settings(), {0.0});
  REQUIRE(sim.body_count() == 1);
  const double m = rho * M_PI * r * r * t;
  // The centre of mass of the L, and its inertia about it: three disks' own
  // m r^2 / 2 and m d^2 for each.
  const Vec2 X0{2.0 * r / 3.0, 2.0 * r / 3.0};
  const double d2 = dot(Vec2{0, 0} - X0, Vec2{0, 0} - X0) + dot(Vec2{2 * r, 0} - X0, Vec2{2 * r, 0} - X0) +
                    dot(Vec2{0, 2 * r} - X0, Vec2{0, 2 * r} - X0);
  auto M = vrut_test::to_host(sim.bodies().mass);
  auto I = vrut_test::to_host(sim.bodies().inertia);
  auto X = vrut_test::to_host(sim.bodies().position);
  CHECK(M(0) == Approx(3.0 * m).epsilon(1e-14));
  CHECK(I(0) == Approx(1.5 * m * r * r + m * d2).epsilon(1e-14));
  CHECK(X(0).x == Approx(X0.x).epsilon(1e-14));
  const Vec2 V{0.3, -0.1};
  const double w = 25.0;  // rad/s
  sim.set_body_motion(0, V, w);
  const long n = 4000;
  const double dt = 1e-5;
  sim.run(n, dt);
  X = vrut_test::to_host(sim.bodies().position);
  auto theta = vrut_test::to_host(sim.bodies().rotation);
  CHECK(X(0).x == Approx(X0.x + n * dt * V.x).epsilon(1e-12));
  CHECK(X(0).y == Approx(X0.y + n * dt * V.y).epsilon(1e-12));
  CHECK(theta(0) == Approx(n * dt * w).epsilon(1e-12));  // a full turn and more: 1 rad
  auto x = vrut_test::to_host(sim.particles().position);
  auto v = vrut_test::to_host(sim.particles().velocity);
  CHECK(norm(x(1) - x(0)) == Approx(2.0 * r).epsilon(1e-12));
  CHECK(norm(x(2) - x(0)) == Approx(2.0 * r).epsilon(1e-12));
  CHECK(norm(x(2) - x(1)) == Approx(2.0 * std::sqrt(2.0) * r).epsilon(1e-12));
  // The corner member, turned with the body: X + R(theta) (corner - X0).
  const Vec2 corner = X(0) + rotated(Vec2{0, 0} - X0, n * dt * w);
  CHECK(x(0).x == Approx(corner.x).epsilon(1e-12));
  CHECK(x(0).y == Approx(corner.y).epsilon(1e-12));
  // Each member moves with the body's velocity at its centre: V + w perp(x - X).
  const Vec2 at_corner = V + w * perp(x(0) - X(0));
  CHECK(v(0).x == Approx(at_corner.x).epsilon(1e-12));
  CHECK(v(0).y == Approx(at_corner.y).epsilon(1e-12));
  CHECK(sim.active_contacts() == 0);
}

// Two L-shaped bodies meet off centre: the contact turns both. No outside
// force acts, and each contact's forces on its two disks are equal and
// opposite, its moments about the origin cancel (the lever arms add up to
// the distance of the centres), so the bodies' momentum and angular
// momentum, in the leapfrog's own sums, stay as they were to rounding.
TEMPLATE_LIST_TEST_CASE("momentum and angular momentum survive a collision of two bodies", "[bodies][physics]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  ParticleSet set;
  add_ell(set, {0.0, 0.0}, 0);
  add_ell(set, {0.0065, 0.0013}, 1);  // to the right, a little higher: the first hits it off centre
  const double kn = 1e6;
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, 0.5 * kn, 0.5));  // friction and shear too: moments at the contact point
  Simulation<Linear, TestType> sim(set, table, settings(), {0.0});
  sim.set_body_motion(0, {0.5, 0.0}, 0.0);
  sim.set_body_motion(1, {-0.2, 0.05}, 3.0);
  const Momenta before = body_momenta(sim);
  const double dt = 0.05 * sim.critical_timestep();
  double most_overlapped = 0.0;
  for (int s = 0; s < 20000; ++s) {
    sim.step(dt);
    most_overlapped = std::max(most_overlapped, static_cast<double>(sim.active_contacts()));
  }
  const Momenta after = body_momenta(sim);
  auto w = vrut_test::to_host(sim.bodies().angular_velocity);
  auto V = vrut_test::to_host(sim.bodies().velocity);
  INFO("after: V0 (" << V(0).x << ", " << V(0).y << "), w0 " << w(0) << ", V1 (" << V(1).x << ", " << V(1).y
                     << "), w1 " << w(1));
  CHECK(most_overlapped > 0);                  // they met
  CHECK(std::abs(w(0)) > 1.0);                 // and the blow turned the first, which had no spin
  CHECK(std::abs(V(0).x - 0.5) > 0.1);         // and slowed it
  const double p_scale = norm(before.linear) + 1e-30;
  CHECK(std::abs(after.linear.x - before.linear.x) <= 1e-12 * p_scale);
  CHECK(std::abs(after.linear.y - before.linear.y) <= 1e-12 * p_scale);
  CHECK(after.angular == Approx(before.angular).epsilon(1e-11));
}

// A body of seven disks (a hexagon) dropped on a floor, settled by local
// damping: the floor carries its weight, 7 m g, and the body rests level.
TEMPLATE_LIST_TEST_CASE("a rigid body resting on a wall weighs on it with its weight", "[bodies][physics]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  ParticleSet set;
  const double y0 = 0.003;
  set.add(0.0, y0, r, rho, 0, 0);
  for (int k = 0; k < 6; ++k)
    set.add(2.0 * r * std::cos(k * M_PI / 3.0), y0 + 2.0 * r * std::sin(k * M_PI / 3.0), r, rho, 0, 0);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(1e6, 0.0, 0.0));
  Simulation<Linear, TestType> sim(set, table, settings({0.0, -9.81}), {0.7});
  const int floor = sim.add_wall(Wall{{-0.01, 0.0}, {0.01, 0.0}, {}}, linear_params(1e6, 0.0, 0.0));
  sim.run(40000, 0.1 * sim.critical_timestep());
  const double weight = 7.0 * rho * M_PI * r * r * t * 9.81;
  const WallLoad load = sim.wall_load(floor);
  CHECK(load.force.y == Approx(-weight).epsilon(1e-6));
  CHECK(std::abs(load.force.x) <= 1e-9 * weight);
  // Two members rest on the floor (the hexagon's lowest pair), equally loaded.
  CHECK(load.contacts == 2.0);
  auto theta = vrut_test::to_host(sim.bodies().rotation);
  CHECK(std::abs(std::remainder(theta(0), M_PI / 3.0)) < 1e-6);
}

namespace {

// A stone of seven disks (a hexagon, two of them lowest) thrown at a soft wall: as one rigid
// body, or as seven free disks bonded on springs of stiffness k_bond. Returns
// the centre of mass's velocity after the bounce.
template <bool rigid, class Space>
vrut::Vec2 bounce(double k_wall, double k_bond) {
  using namespace vrut;
  ParticleSet set;
  const int body = rigid ? 0 : -1;
  set.add(0.0, 0.004, r, rho, 0, body);
  for (int k = 0; k < 6; ++k)
    set.add(2.0 * r * std::cos(k * M_PI / 3.0), 0.004 + 2.0 * r * std::sin(k * M_PI / 3.0), r, rho, 0, body);
  AssignmentTable<LinearBonded> table;
  table.set_all(linear_bonded_params(k_bond, 0.4 * k_bond, 0.5, 1e30, 1e30));
  Simulation<LinearBonded, Space> sim(set, table, settings(), {0.0});
  if (!rigid) sim.bond_touching_contacts(1e-12);
  // A frictionless floor, met obliquely: the stone comes down at 1 m/s and along it at 0.5 m/s.
  sim.add_wall(Wall{{-0.05, 0.0}, {0.05, 0.0}, {}}, linear_params(k_wall, 0.0, 0.0));
  const Vec2 v0{0.5, -1.0};
  if (rigid) {
    sim.set_body_motion(0, v0, 0.0);
  } else {
    auto v = vrut_test::to_host(sim.particles().velocity);
    for (std::size_t i = 0; i < v.extent(0); ++i) v(i) = v0;
    Kokkos::deep_copy(sim.particles().velocity, v);
  }
  const double m = rho * M_PI * r * r * t, contact_time = M_PI * std::sqrt(7.0 * m / k_wall);
  const double dt = 0.1 * std::sqrt(m / k_bond);  // the bonded stone's own step; the rigid one takes it too
  sim.run(static_cast<long>((0.002 / 1.0 + 3.0 * contact_time) / dt), dt);
  auto v = vrut_test::to_host(sim.particles().velocity);
  Vec2 mean;
  for (std::size_t i = 0; i < v.extent(0); ++i) mean += (1.0 / 7.0) * v(i);
  return mean;
}

}  // namespace

// The rigid stone is the limit of the bonded-disk stone as the bonds grow
// stiff against what loads it. The bonded stone's rebound differs by the
// vibration its bonds take up where the wall's force sets in with a kink
// (the force's rate jumps from 0 to k_wall v): relative to the impact
// speed, of order (omega_wall / omega_bond)^3, that is (k_wall /
// k_bond)^(3/2) (the masses of the two modes, the stone's and one disk's,
// are within a factor 7). So at k_wall / k_bond = 1e-2 and 1e-3 the
// difference is at most (k_wall / k_bond)^(3/2) of the impact speed, and
// ten times stiffer bonds bring it 10^(3/2) = 32 times closer (asked: 20).
TEMPLATE_LIST_TEST_CASE("a rigid stone is the stiff limit of its bonded-disk stone", "[bodies][physics]",
                        vrut_test::ExecutionSpaces) {
  const double k_wall = 1e5;
  const vrut::Vec2 rigid = bounce<true, TestType>(k_wall, 1e8);
  // The rigid bounce itself: a frictionless elastic floor gives the normal
  // speed back and leaves the tangential one.
  CHECK(rigid.y == Approx(1.0).epsilon(1e-3));
  CHECK(rigid.x == Approx(0.5).epsilon(1e-9));
  double previous = 0.0;
  for (double k_bond : {1e7, 1e8}) {
    const vrut::Vec2 bonded = bounce<false, TestType>(k_wall, k_bond);
    const double difference = vrut::norm(bonded - rigid) / 1.0;  // of the impact speed, 1 m/s
    INFO("k_wall / k_bond " << k_wall / k_bond << ": bonded stone rebounds at (" << bonded.x << ", " << bonded.y
                            << ") m/s, rigid at (" << rigid.x << ", " << rigid.y << "), difference " << difference);
    CHECK(difference <= std::pow(k_wall / k_bond, 1.5));
    if (previous > 0.0) CHECK(difference <= previous / 20.0);
    previous = difference;
  }
}
