// The engine in 3D (Simulation3: spheres, plates, periodic axes) against
// closed forms, on every backend: a head-on and an oblique collision, a
// sphere sliding on a plate until it rolls, and a pair that touches across
// a periodic face.
#include "contact_timing.hpp"
#include "openmp_threads.hpp"
#include "pile3.hpp"
#include "spaces.hpp"
#include "../examples/custom_law/soft_contact.hpp"
#include "../examples/custom_law/stiffening_both.hpp"

#include <vrut/material/burgers_parameters.hpp>
#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace {

using vrut::Vec3;

template <class Law, class Space>
using Sim3 = vrut::Simulation3<Law, Space, vrut::CentralDifference, vrut::VelocityControl>;

struct Pair {
  Vec3 v[2], w[2];
  double duration;
};

// Two equal spheres along the unit axis e, approaching at vn each, sphere 0
// also moving at vt along the unit t (normal to e); Linear with kn = ks
// and friction mu, touching after a gap of 1e-4 r each, centre to centre
// along e. The contact's duration from the crossings of zero
// overlap, interpolated between steps, and the motion after it.
template <class Space>
Pair collide(Vec3 e, Vec3 t, double vn, double vt, double mu, double kn, double& mass, double& inertia) {
  using namespace vrut;
  const double r = 0.5, rho = 1000.0;
  ParticleSet set;
  // Sphere 0 starts behind by its tangential travel until they touch, so
  // that they meet centre to centre along e.
  const Vec3 a = -(1.0001 * r) * e - (vt * 0.0001 * r / vn) * t, b = (1.0001 * r) * e;
  set.add_sphere(a.x, a.y, a.z, r, rho);
  set.add_sphere(b.x, b.y, b.z, r, rho);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, kn, mu));
  Sim3<Linear, Space> sim(set, table);
  auto ps = sim.particles();
  auto hv = vrut_test::to_host(ps.velocity);
  hv(0) = vn * e + vt * t;
  hv(1) = -vn * e;
  Kokkos::deep_copy(ps.velocity, hv);
  mass = vrut_test::to_host(ps.mass)(0);
  inertia = vrut_test::to_host(ps.inertia)(0);
  const double expected = M_PI * std::sqrt(0.5 * mass / kn);
  const double dt = expected / 2000.0;
  auto overlap = [&] {
    auto x = vrut_test::to_host(ps.position);
    return 2.0 * r - norm(x(1) - x(0));
  };
  const double duration = vrut_test::contact_duration(sim, dt, overlap);
  sim.run(100, dt);
  auto v = vrut_test::to_host(ps.velocity);
  auto w = vrut_test::to_host(ps.angular_velocity);
  return {{v(0), v(1)}, {w(0), w(1)}, duration};
}

const Vec3 oblique_axis{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
const Vec3 across_it{2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0};  // normal to it

}  // namespace

// Head-on on a linear spring, along an axis oblique to every coordinate:
// the contact lasts pi sqrt(m_eff / k_n), the spheres swap their velocities
// (equal masses, no loss), and nothing turns or moves sideways.
TEMPLATE_LIST_TEST_CASE("3D: a head-on collision lasts pi sqrt(m/k) and swaps the velocities", "[engine3][physics]",
                        vrut_test::ExecutionSpaces) {
  double m = 0.0, inertia = 0.0;
  const double vn = 0.1, kn = 1e5;
  const Pair p = collide<TestType>(oblique_axis, across_it, vn, 0.0, 0.5, kn, m, inertia);
  const double expected = M_PI * std::sqrt(0.5 * m / kn);
  INFO("duration " << p.duration << " expected " << expected);
  CHECK(std::abs(p.duration / expected - 1.0) < 0.005);  // as the 2D test: the crossings interpolated
  // Leapfrog on a linear spring keeps the energy to O(dt^2): 1e-6 at 2000 steps a contact.
  CHECK(vrut::norm(p.v[0] - (-vn) * oblique_axis) < 1e-6 * vn);
  CHECK(vrut::norm(p.v[1] - vn * oblique_axis) < 1e-6 * vn);
  CHECK(vrut::norm(p.w[0]) == 0.0);
  CHECK(vrut::norm(p.w[1]) == 0.0);
}

// Oblique, sliding throughout (the tangential speed 5 times the normal, so
// the shear spring is at its cap from the first steps and the slip never
// stops: it falls by 7 mu J_n / m = 1.4 vn of its 5 vn). Coulomb's law gives
// the impulses in closed form: J_n = 2 m_eff (2 vn) = 2 m vn from the elastic
// rebound, J_t = mu J_n against the slip, and each sphere spins up by
// r J_t / I about e x t, negatively. The closed form holds the normal fixed;
// here it turns by about theta = vt t_c / 2r = 8e-5 rad while the spheres
// touch (stiff springs keep t_c short). That tilts the normal impulse into
// the tangent by theta / 2, 0.04 % of J_t, and moves vt theta of the
// tangential speed into the normal, 2e-4 of the normal speed: within the
// 1 % and 0.1 % allowed. The lever is r less half the overlap, 2e-5 r.
// Momentum is kept to rounding.
TEMPLATE_LIST_TEST_CASE("3D: an oblique collision that slides takes mu J_n of tangential impulse",
                        "[engine3][physics]", vrut_test::ExecutionSpaces) {
  double m = 0.0, inertia = 0.0;
  const double vn = 0.1, vt = 0.5, mu = 0.1, r = 0.5;
  const Pair p = collide<TestType>(oblique_axis, across_it, vn, vt, mu, 1e11, m, inertia);
  const double jn = 2.0 * m * vn, jt = mu * jn;
  const Vec3 total_before = vt * across_it, total_after = p.v[0] + p.v[1];
  CHECK(vrut::norm(total_after - total_before) < 1e-12 * vt);
  // Normal: an elastic rebound; tangential: mu J_n taken from sphere 0, given to 1.
  CHECK(vrut::dot(p.v[0], oblique_axis) == Approx(-vn).epsilon(1e-3));
  CHECK(vt - vrut::dot(p.v[0], across_it) == Approx(jt / m).epsilon(0.01));
  CHECK(vrut::dot(p.v[1], across_it) == Approx(jt / m).epsilon(0.01));
  const Vec3 spin_axis = vrut::cross(oblique_axis, across_it);
  for (int k = 0; k < 2; ++k) {
    CHECK(vrut::dot(p.w[k], spin_axis) == Approx(-r * jt / inertia).epsilon(0.01));
    CHECK(vrut::norm(p.w[k] - vrut::dot(p.w[k], spin_axis) * spin_axis) < 1e-9 * r * jt / inertia);
  }
}

namespace {

struct Slide3 {
  double final_speed, final_spin, max_ratio, min_ratio_while_slipping, sideways;
};

// A sphere thrown along a floor plate with no spin, in x: friction at
// mu F_n decelerates it and spins it up until it rolls.
template <class Space>
Slide3 slide3(double v0, double mu, double g) {
  using namespace vrut;
  const double r = 0.01, rho = 2500.0, kn = 1.0e7;
  const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
  ParticleSet set;
  set.add_sphere(0.0, 0.0, r - m * g / kn, r, rho);  // resting at its static overlap
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, kn, mu));
  SimulationSettings3 settings;
  settings.gravity = {0.0, 0.0, -g};
  Sim3<Linear, Space> sim(set, table, settings);
  sim.add_wall(Wall3{{0.0, 0.0, 0.0}, {10.0, 0.0, 0.0}, {0.0, 10.0, 0.0}, {}}, linear_params(kn, kn, mu));
  auto ps = sim.particles();
  auto hv = vrut_test::to_host(ps.velocity);
  hv(0) = {v0, 0.0, 0.0};
  Kokkos::deep_copy(ps.velocity, hv);
  const double dt = 0.02 * std::sqrt(m / kn);
  const double t_slide = 2.0 * v0 / (7.0 * mu * g);
  const long steps = static_cast<long>(1.5 * t_slide / dt);
  Slide3 res{0.0, 0.0, 0.0, 1e300, 0.0};
  for (long s = 0; s < steps; ++s) {
    sim.step(dt);
    const auto load = sim.wall_load(0);
    const double ratio = std::hypot(load.force.x, load.force.y) / std::abs(load.force.z);
    res.max_ratio = std::max(res.max_ratio, ratio);
    if (sim.time() < 0.9 * t_slide && sim.time() > 0.05 * t_slide)
      res.min_ratio_while_slipping = std::min(res.min_ratio_while_slipping, ratio);
  }
  const Vec3 v = vrut_test::to_host(ps.velocity)(0), w = vrut_test::to_host(ps.angular_velocity)(0);
  res.final_speed = v.x;
  res.final_spin = w.y;
  res.sideways = std::abs(v.y) + std::abs(w.x) * r + std::abs(w.z) * r;
  return res;
}

}  // namespace

// I = 2/5 m r^2: rolling starts at 5/7 v0 after 2 v0 / (7 mu g), spinning
// at v / r about y. The shear force never exceeds mu F_n, and sits at it
// while the sphere slides; nothing moves sideways.
TEMPLATE_LIST_TEST_CASE("3D: a sphere sliding on a plate rolls at 5/7 of its speed", "[engine3][physics]",
                        vrut_test::ExecutionSpaces) {
  const double v0 = 0.5, mu = 0.4, g = 9.81, r = 0.01;
  const Slide3 res = slide3<TestType>(v0, mu, g);
  INFO("max |F_s|/F_n " << res.max_ratio << ", min while slipping " << res.min_ratio_while_slipping);
  CHECK(res.max_ratio <= mu * (1.0 + 1e-9));
  CHECK(res.min_ratio_while_slipping >= mu * (1.0 - 1e-9));
  INFO("final speed " << res.final_speed << " expected " << 5.0 / 7.0 * v0);
  CHECK(std::abs(res.final_speed / (5.0 / 7.0 * v0) - 1.0) < 0.005);  // as the 2D test
  CHECK(std::abs(res.final_spin * r / res.final_speed - 1.0) < 0.005);
  CHECK(res.sideways == 0.0);
}

// Two spheres 0.1 r from the two x faces of a periodic box see each other
// through the face: on the first step each is pushed away from the other,
// out through its own face, by k_n times the overlap through the face.
TEMPLATE_LIST_TEST_CASE("3D: a pair touches across a periodic face", "[engine3][periodic]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  const double r = 0.01, rho = 2500.0, kn = 1.0e6, length = 0.1;
  ParticleSet set;
  set.add_sphere(0.1 * r, 0.05, 0.05, r, rho);
  set.add_sphere(length - 0.1 * r, 0.05, 0.05, r, rho);
  set.add_sphere(0.05, 0.05, 0.05, r, rho);  // a bystander in the middle, touching nothing
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, kn, 0.5));
  SimulationSettings3 settings;
  settings.box.low = {0.0, 0.0, 0.0};
  settings.box.high = {length, length, length};
  settings.box.periodic[0] = true;
  Sim3<Linear, TestType> sim(set, table, settings);
  sim.step(1e-7);
  auto f = vrut_test::to_host(sim.particles().force);
  const double overlap = 2.0 * r - 0.2 * r;
  CHECK(f(0).x == Approx(kn * overlap).epsilon(1e-12));
  CHECK(f(1).x == Approx(-kn * overlap).epsilon(1e-12));
  CHECK(f(0).y == 0.0);
  CHECK(f(0).z == 0.0);
  CHECK(f(2).x == 0.0);
  CHECK(sim.active_contacts() == 1);
  // Without the periodic axis they are 0.08 m apart and do not touch.
  settings.box.periodic[0] = false;
  Sim3<Linear, TestType> open(set, table, settings);
  open.step(1e-7);
  CHECK(vrut_test::to_host(open.particles().force)(0).x == 0.0);
  CHECK(open.active_contacts() == 0);
}

// A periodic axis shorter than three contact reaches cannot hold a cell
// list that sees each neighbour cell once: the engine says so.
TEST_CASE("3D: a periodic axis too short for the cell list is refused", "[engine3][periodic]") {
  using namespace vrut;
  ParticleSet set;
  set.add_sphere(0.01, 0.01, 0.01, 0.01, 2500.0);
  set.add_sphere(0.03, 0.01, 0.01, 0.01, 2500.0);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(1e6, 1e6, 0.5));
  SimulationSettings3 settings;
  settings.box.high = {0.05, 1.0, 1.0};
  settings.box.periodic[0] = true;
  Sim3<Linear, Kokkos::DefaultHostExecutionSpace> sim(set, table, settings);
  CHECK_THROWS_WITH(sim.step(1e-7), Catch::Contains("periodic axis"));
}

// The 3D forms of the laws against their 2D forms: a shear slip along a
// fixed direction e of the tangent plane gives the 2D scalar force times e,
// for the linear spring, Burger's element and the film (with its stones
// bearing), through the composed law and its Coulomb cap.
TEST_CASE("3D laws: a slip along one direction gives the 2D force along it", "[engine3][laws]") {
  using namespace vrut;
  using Law2 = BurgersFilmBonded;
  using Law3 = in_dimension_t<Law2, Dim3>;
  static_assert(std::is_same_v<Law3::params_type, Law2::params_type>);
  static_assert(std::is_same_v<law_dimension_t<Law3>, Dim3>);
  BurgersBonded::params_type mastic;
  mastic.normal = {1e6, 1e3, 2e5, 5e2};
  mastic.shear = {5e5, 8e2, 1e5, 3e2};
  mastic.bond = {50.0, 40.0};
  mastic.friction = 0.5;
  const Law2::params_type p = film_params(mastic, 1e-5, 3e6, 1.5e6);
  const Vec3 e{2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0};
  Law2::state_type s2{};
  Law3::state_type s3{};
  make_bonded<Law2>(s2);
  make_bonded<Law3>(s3);
  const double dt = 1e-4;
  double scale = 0.0;  // the largest shear force so far: the rounding of the vector form is relative to it
  for (int k = 0; k < 400; ++k) {
    // Loading, then holding: the overlap passes the film thickness, the bond breaks in shear.
    const double du = k < 200 ? 1e-7 : 0.0, slip = k < 300 ? 2e-7 : -1e-7;
    ContactGeometry g2;
    g2.overlap = 1e-7 * (k < 200 ? k + 1 : 200);
    g2.normal_increment = du;
    g2.shear_increment = slip;
    g2.dt = dt;
    ContactGeometry3 g3;
    g3.normal = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
    g3.overlap = g2.overlap;
    g3.normal_increment = du;
    g3.shear_increment = slip * e;
    g3.dt = dt;
    const ContactForce f2 = Law2::force(p, s2, g2);
    const ContactForceIn<Dim3> f3 = Law3::force(p, s3, g3);
    CHECK(f3.normal == f2.normal);
    scale = std::max(scale, std::abs(f2.shear));
    CHECK(norm(f3.shear - f2.shear * e) <= 1e-12 * scale);
    CHECK(is_bonded<Law3>(s3) == is_bonded<Law2>(s2));
  }
  CHECK_FALSE(is_bonded<Law2>(s2));  // the path does break the bond, so the cap is checked too
}

namespace {

template <class Space>
std::vector<double> drop_pile(int steps) {
  auto sim = vrut_test::make_pile<Space>();
  sim.run(steps, 0.2 * sim.critical_timestep());
  return vrut_test::pile_motion(sim);
}

}  // namespace

#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
// Every sum in a fixed order: the same bits on one thread and on several.
// The pile (pile3.hpp) has settled into contact with the floor and across
// the faces by then (checked, so that the comparison covers those paths).
TEST_CASE("3D: Serial and OpenMP give the same bits on a settling pile", "[engine3][backends]") {
  if (!vrut_test::openmp_runs_several_threads()) return;
  const int steps = 3000;
  const std::vector<double> serial = drop_pile<Kokkos::Serial>(steps);
  const std::vector<double> openmp = drop_pile<Kokkos::OpenMP>(steps);
  REQUIRE(serial.size() == openmp.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < serial.size(); ++k) differ += serial[k] != openmp[k];
  CHECK(differ == 0);
  double lowest = 1e300, spin = 0.0;
  for (std::size_t i = 0; i + 9 <= serial.size(); i += 9) {
    lowest = std::min(lowest, serial[i + 2]);
    spin = std::max(spin, std::abs(serial[i + 6]) + std::abs(serial[i + 7]) + std::abs(serial[i + 8]));
  }
  CHECK(lowest < 0.002);  // the lowest layer is down on the floor
  CHECK(spin > 0.0);      // friction has turned spheres
}
#endif

namespace {

// A clump of five equal spheres, touching in a row of three with one more
// on the first along y and one along z: its three principal moments differ.
void add_clump(vrut::ParticleSet& set, Vec3 at, double r, double rho, int body) {
  const Vec3 offsets[5] = {{0.0, 0.0, 0.0}, {2.0 * r, 0.0, 0.0}, {4.0 * r, 0.0, 0.0}, {0.0, 2.0 * r, 0.0},
                           {0.0, 0.0, 2.0 * r}};
  for (const Vec3& o : offsets) set.add_sphere(at.x + o.x, at.y + o.y, at.z + o.z, r, rho, 0, body);
}

template <class Space>
using BodySim = vrut::Simulation3<vrut::Linear, Space, vrut::CentralDifference, vrut::VelocityControl>;

}  // namespace

// A clump alone, moving and spinning about one of its principal axes: the
// centre flies straight at its velocity, the spin stays as it was (a
// torque-free spin about a principal axis is steady; the splitting turns
// the body about that axis exactly, step by step), and each member turns
// about the centre by omega t. The smallest and the largest moment's axes,
// both stable. Tolerances are rounding over the steps.
TEMPLATE_LIST_TEST_CASE("3D bodies: free flight and a torque-free spin about a principal axis", "[engine3][bodies]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  const double r = 0.002, rho = 2500.0, rate = 30.0, dt = 1e-5;
  const long steps = 2000;
  for (int axis : {0, 2}) {
    ParticleSet set;
    add_clump(set, {0.01, 0.02, 0.03}, r, rho, 0);
    AssignmentTable<Linear> table;
    table.set_all(linear_params(1e5, 1e5, 0.5));
    BodySim<TestType> sim(set, table);
    const Quaternion q = vrut_test::to_host(sim.bodies().rotation)(0);
    const Vec3 X0 = vrut_test::to_host(sim.bodies().position)(0);
    Vec3 unit{};
    component(unit, axis) = 1.0;
    const Vec3 principal = rotate(q, unit), w = rate * principal, V{0.1, -0.2, 0.05};
    const Vec3 member0 = vrut_test::to_host(sim.particles().position)(0);
    sim.set_body_motion(0, V, w);
    sim.run(steps, dt);
    const double t = steps * dt;
    const Vec3 X = vrut_test::to_host(sim.bodies().position)(0);
    CHECK(norm(X - (X0 + t * V)) < 1e-12);
    CHECK(norm(vrut_test::to_host(sim.bodies().angular_velocity)(0) - w) < 1e-12 * rate);
    const Vec3 expected = X0 + t * V + rotate(axis_angle(principal, rate * t), member0 - X0);
    CHECK(norm(vrut_test::to_host(sim.particles().position)(0) - expected) < 1e-12);
    CHECK(norm(vrut_test::to_host(sim.particles().velocity)(0) - (V + cross(w, expected - X))) < 1e-9);
  }
}

// Two clumps collide off centre, with friction, and part: the total
// momentum and angular momentum (about the origin: each centre's X x M V
// plus the body's own L) are what they were, to rounding. Every contact
// puts equal and opposite forces through one point, and the leapfrog keeps
// both sums exactly but for rounding: a strong test of the members'
// moments, their sum into the body, and the body's turn.
TEMPLATE_LIST_TEST_CASE("3D bodies: a collision keeps momentum and angular momentum", "[engine3][bodies]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  const double r = 0.002, rho = 2500.0, kn = 1e5;
  ParticleSet set;
  add_clump(set, {0.0, 0.0, 0.0}, r, rho, 0);
  add_clump(set, {0.0, 0.016, 0.003}, r, rho, 1);
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, 0.5 * kn, 0.4));
  BodySim<TestType> sim(set, table);
  sim.set_body_motion(0, {0.05, 0.3, 0.0}, {0.0, 0.0, 20.0});
  sim.set_body_motion(1, {0.0, -0.3, 0.02}, {5.0, 0.0, 0.0});
  auto totals = [&](Vec3& momentum, Vec3& angular) {
    auto X = vrut_test::to_host(sim.bodies().position);
    auto V = vrut_test::to_host(sim.bodies().velocity);
    auto M = vrut_test::to_host(sim.bodies().mass);
    auto L = vrut_test::to_host(sim.bodies().angular_momentum);
    momentum = angular = Vec3{};
    for (int b = 0; b < 2; ++b) {
      momentum += M(b) * V(b);
      angular += cross(X(b), M(b) * V(b)) + L(b);
    }
  };
  Vec3 p0, l0, p1, l1;
  totals(p0, l0);
  const Vec3 v_before = vrut_test::to_host(sim.bodies().velocity)(0);
  const double dt = 0.1 * sim.critical_timestep();
  int touched = 0;
  for (int s = 0; s < 20000; ++s) {
    sim.step(dt);
    if (s % 50 == 0) touched = std::max(touched, sim.active_contacts());
  }
  CHECK(sim.active_contacts() == 0);  // they have parted
  REQUIRE(touched > 0);
  totals(p1, l1);
  const Vec3 v_after = vrut_test::to_host(sim.bodies().velocity)(0);
  CHECK(norm(v_after - v_before) > 0.05 * norm(v_before));  // a real collision
  CHECK(norm(p1 - p0) < 1e-12 * norm(p0));
  CHECK(norm(l1 - l0) < 1e-10 * norm(l0));
}

// The step of a stone made of two spheres 2 sqrt(6) r apart (two lattice
// sites inside one thin stone): a contact's normal force acts through a
// member's centre, so it turns the pair about a transverse axis, never
// about the pair's own axis. The step is sqrt(M_felt / k), M_felt =
// m / (1/2 + 6/12.8) (the dumbbell of test_rigid_rotation.cpp), not
// sqrt(m / 8k) from the weakest moment, which cost 3D specimens up to
// 2.8 times the steps.
TEMPLATE_LIST_TEST_CASE("3D bodies: a thin stone's time step is its mass felt through a member's centre",
                        "[engine3][bodies]", vrut_test::ExecutionSpaces) {
  using namespace vrut;
  const double r = 0.001, rho = 2700.0, kn = 1e6, a = std::sqrt(6.0) * r;
  const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
  const Vec3 u{2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0}, middle{0.01, 0.02, 0.005};
  ParticleSet set;
  for (double side : {-1.0, 1.0}) {
    const Vec3 x = middle + side * a * u;
    set.add_sphere(x.x, x.y, x.z, r, rho, 0, 0);
  }
  AssignmentTable<Linear> table;
  table.set_all(linear_params(kn, 0.5 * kn, 0.4));
  BodySim<TestType> sim(set, table);
  CHECK(sim.critical_timestep() == Approx(std::sqrt(m / (0.5 + 6.0 / 12.8) / kn)).epsilon(1e-12));
}

// A bonded FCC block, its cube axes along x, y, z, periodic in x and y (so
// that it cannot widen) and held by its bottom and top (001) layers: the
// top layer moves down and the block takes a uniaxial strain eps. Lattice
// theory for springs k_n along and k_s across each of the 12 bonds of a
// sphere (an FCC lattice with inversion symmetry deforms affinely, without
// turning its spheres) gives
//   C_11 = (1 / 2 V) sum_bonds d^2 [k_n n_z^4 + k_s (n_z^2 - n_z^4)] = sqrt(2) (k_n + k_s) / d,
// with V = d^3 / sqrt(2) per sphere (8 of the 12 bonds have n_z^2 = 1/2).
// The interior is given the affine velocity too, so it follows the lattice
// exactly; the top layer then carries C_11 eps times the box's cross
// section. At eps = 1e-4 the geometric nonlinearity is of order eps: 0.1 %
// is allowed.
TEMPLATE_LIST_TEST_CASE("3D: a bonded FCC block has the lattice's C11 and C12", "[engine3][physics]",
                        vrut_test::ExecutionSpaces) {
  using namespace vrut;
  const double r = 0.001, d = 2.0 * r, a = d * std::sqrt(2.0), kn = 1e6, ks = 0.4 * kn, rho = 2500.0;
  const int cells = 4, layers = 12;
  ParticleSet set;
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < 2 * cells; ++j)
      for (int i = 0; i < 2 * cells; ++i)
        if ((i + j + k) % 2 == 0) set.add_sphere(0.5 * a * (i + 0.5), 0.5 * a * (j + 0.5), 0.5 * a * k, r, rho);
  AssignmentTable<LinearBonded> table;
  table.set_all(linear_bonded_params(kn, ks, 0.5, 1e30, 1e30));
  SimulationSettings3 settings;
  settings.box.high = {cells * a, cells * a, 1.0};
  settings.box.periodic[0] = settings.box.periodic[1] = true;
  Simulation3<LinearBonded, TestType, CentralDifference, VelocityControl> sim(set, table, settings);
  REQUIRE(sim.bond_touching_contacts(1e-9 * r) == static_cast<int>(set.size()) * 6 - 4 * cells * cells * 2);
  const double height = 0.5 * a * (layers - 1), eps = 1e-4, speed = 1e-3;
  auto ps = sim.particles();
  auto fix = vrut_test::to_host(ps.fixity);
  auto v = vrut_test::to_host(ps.velocity);
  auto x = vrut_test::to_host(ps.position);
  for (std::size_t i = 0; i < set.size(); ++i) {
    const bool held = x(i).z < 0.1 * a || x(i).z > height - 0.1 * a;
    fix(i) = held ? (prescribed_velocity | no_rotation) : free_motion;
    v(i) = {0.0, 0.0, -speed * x(i).z / height};
  }
  Kokkos::deep_copy(ps.fixity, fix);
  Kokkos::deep_copy(ps.velocity, v);
  const double dt = 0.1 * sim.critical_timestep();
  const long steps = std::lround(eps * height / speed / dt);
  sim.run(steps, dt);
  Kokkos::deep_copy(ps.velocity, Vec3{});
  sim.step(dt);  // the forces at the strained positions, nothing moving
  const double strain = speed * steps * dt / height;
  auto f = vrut_test::to_host(ps.force);
  x = vrut_test::to_host(ps.position);
  double top = 0.0, bottom = 0.0, interior = 0.0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    if (x(i).z > height - 0.5 * a) top += f(i).z;
    else if (x(i).z < 0.1 * a) bottom += f(i).z;
    else interior = std::max(interior, norm(f(i)));
  }
  const double c11 = std::sqrt(2.0) * (kn + ks) / d, c12 = (kn - ks) / (std::sqrt(2.0) * d);
  const double area = (cells * a) * (cells * a), expected = c11 * strain * area;
  INFO("top " << top << " bottom " << bottom << " expected " << expected);
  CHECK(top == Approx(expected).epsilon(1e-3));  // pushed up by the block
  CHECK(bottom == Approx(-expected).epsilon(1e-3));
  CHECK(interior < 1e-6 * expected / (cells * cells));  // the interior is in equilibrium

  // The stresses inside, from the contact forces (the virial sum of force
  // times branch vector over the block between the outer layers): the
  // vertical one C11 eps again, the lateral ones C12 eps (8 of the 12 bonds
  // cross the layers; 4 of those lie in each vertical plane of a lateral axis,
  // f_x l_x = (k_n - k_s) eps d^2 / 4 each). C11 and C12 give the modulus
  // along a cube axis that the 3D Burger's rules use (MicroConversion::fcc_lattice).
  const auto& list = sim.contacts();
  auto partner = vrut_test::to_host(list.partner);
  auto count = vrut_test::to_host(list.count);
  auto load = vrut_test::to_host(list.load);
  Vec3 virial{};
  for (std::size_t i = 0; i < set.size(); ++i)
    for (int k = 0; k < count(i); ++k) {
      const Vec3 l = settings.box.separation(x(i), x(partner(i, k)));
      const Vec3 f = load(i, k).force;  // on the row's partner
      virial += Vec3{f.x * l.x, f.y * l.y, f.z * l.z};
    }
  const Vec3 stress = (1.0 / (area * height)) * virial;  // compression positive
  CHECK(stress.z == Approx(c11 * strain).epsilon(1e-3));
  CHECK(stress.x == Approx(c12 * strain).epsilon(1e-3));
  CHECK(stress.y == Approx(c12 * strain).epsilon(1e-3));
  const double m11 = stress.z / strain, m12 = 0.5 * (stress.x + stress.y) / strain;
  const double modulus = (m11 - m12) * (m11 + 2.0 * m12) / (m11 + m12);
  CHECK(modulus == Approx(MicroConversion::fcc_lattice_modulus_factor(ks / kn) * kn / d).epsilon(2e-3));
}

// The contact-laws page's law for both dimensions
// (examples/custom_law/stiffening_both.hpp), in the engine and against the
// 2D law it generalises (soft_contact.hpp). Two equal spheres meeting head
// on at v each store their relative kinetic energy m v^2 in the spring, so
// the deepest overlap solves k (delta^2 / 2 + delta^3 / (3 r0)) = m v^2; the
// law conserves energy, so they part at v each. In 2D it is the page's 2D
// law, bit for bit; in 3D a slip along any direction is capped at mu F_n
// against it.
TEST_CASE("the contact-laws page's law for both dimensions: a head-on collision's deepest overlap, and the 2D law",
          "[engine3][laws]") {
  using namespace vrut;
  using Both = StiffeningContactIn<Dim2>;
  using Both3 = in_dimension_t<Both, Dim3>;
  static_assert(std::is_same_v<Both3, StiffeningContactIn<Dim3>>);
  const double r = 0.5, k = 1e5, r0 = 0.01, v = 0.1, mu = 0.5;
  ParticleSet set;
  set.add_sphere(-1.0001 * r, 0.0, 0.0, r, 1000.0);
  set.add_sphere(1.0001 * r, 0.0, 0.0, r, 1000.0);
  AssignmentTable<Both3> table;
  table.set_all({k, r0, k, mu});
  Simulation3<Both3, Kokkos::DefaultHostExecutionSpace, CentralDifference, VelocityControl> sim(set, table);
  auto ps = sim.particles();
  auto hv = vrut_test::to_host(ps.velocity);
  hv(0) = {v, 0.0, 0.0};
  hv(1) = {-v, 0.0, 0.0};
  Kokkos::deep_copy(ps.velocity, hv);
  const double m = vrut_test::to_host(ps.mass)(0);
  double delta = std::sqrt(2.0 * m * v * v / k);  // the linear spring's, then Newton's steps
  for (int i = 0; i < 50; ++i)
    delta -= (k * (0.5 * delta * delta + delta * delta * delta / (3.0 * r0)) - m * v * v) /
             (k * (delta + delta * delta / r0));
  const double dt = 1e-3 * delta / v;
  double deepest = 0.0;
  for (int i = 0; i < 6000; ++i) {
    sim.run(1, dt);
    auto x = vrut_test::to_host(ps.position);
    deepest = std::max(deepest, 2.0 * r - norm(x(1) - x(0)));
  }
  CHECK(deepest == Approx(delta).epsilon(1e-4));
  auto after = vrut_test::to_host(ps.velocity);
  CHECK(after(0).x == Approx(-v).epsilon(1e-4));
  CHECK(after(1).x == Approx(v).epsilon(1e-4));

  const Both::params_type p{k, r0, 0.4 * k, mu};
  Both::state_type both{};
  StiffeningContact::state_type plain{};
  Both3::state_type three{};
  const Vec3 e{2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0};
  for (int i = 0; i < 200; ++i) {
    ContactGeometry g;
    g.overlap = 1e-5 * (1 + i % 50);
    g.shear_increment = i < 120 ? 2e-6 : -3e-6;
    const ContactForce a = Both::force(p, both, g);
    const ContactForce b = StiffeningContact::force({k, r0, 0.4 * k, mu}, plain, g);
    CHECK(a.normal == b.normal);
    CHECK(a.shear == b.shear);
    ContactGeometry3 g3;
    g3.overlap = g.overlap;
    g3.shear_increment = g.shear_increment * e;
    const ContactForceIn<Dim3> f3 = Both3::force(p, three, g3);
    CHECK(f3.normal == a.normal);
    CHECK(norm(f3.shear - a.shear * e) <= 1e-12 * mu * f3.normal);
  }
}
