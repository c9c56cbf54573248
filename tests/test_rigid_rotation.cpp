// The rotation of a 3D rigid body (integrate/rigid_rotation.hpp) against
// closed forms and an independent integration: a spin about a principal
// axis, a constant torque's spin-up, the torque-free symmetric top, and an
// asymmetric body against Runge-Kutta on Euler's equations. Each runs in a
// Kokkos kernel on every backend.
#include "order_checks.hpp"
#include "spaces.hpp"

#include <vrut/geometry/clump3.hpp>
#include <vrut/integrate/rigid_rotation.hpp>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

namespace {

struct Rotor {
  vrut::Quaternion q;
  vrut::Vec3 momentum;  // world frame
};

// `steps` steps of one body, inside a kernel of Space.
template <class Space>
Rotor run_rotor(Rotor start, vrut::Vec3 inertia, vrut::Vec3 torque, double dt, long steps) {
  Kokkos::View<Rotor*, typename Space::memory_space> state("rotor", 1);
  auto host = Kokkos::create_mirror_view(state);
  host(0) = start;
  Kokkos::deep_copy(state, host);
  Kokkos::parallel_for(
      "rotor", Kokkos::RangePolicy<Space>(0, 1), KOKKOS_LAMBDA(int i) {
        Rotor r = state(i);
        for (long n = 0; n < steps; ++n) vrut::rotate_rigid_body(r.q, r.momentum, torque, inertia, dt);
        state(i) = r;
      });
  Kokkos::deep_copy(host, state);
  return host(0);
}

// The largest difference between where two orientations put the body's axes.
double axes_apart(vrut::Quaternion a, vrut::Quaternion b) {
  double worst = 0.0;
  for (vrut::Vec3 e : {vrut::Vec3{1, 0, 0}, vrut::Vec3{0, 1, 0}, vrut::Vec3{0, 0, 1}})
    worst = std::max(worst, vrut::norm(vrut::rotate(a, e) - vrut::rotate(b, e)));
  return worst;
}

}  // namespace

// About a principal axis the body turns at w = L / I_k, and each step's turn
// is exact: only rounding separates it from the angle w t (1e4 steps of a
// few ulp each: 1e-10 allows a hundred times that).
TEMPLATE_LIST_TEST_CASE("a torque-free spin about a principal axis turns at the constant rate", "[physics][bodies]",
                        vrut_test::ExecutionSpaces) {
  const vrut::Vec3 inertia{1.0, 2.0, 3.0};
  const double w = 7.0, dt = 1e-4;
  const long steps = 10000;
  for (int k = 0; k < 3; ++k) {
    vrut::Vec3 axis{0, 0, 0};
    vrut::component(axis, k) = 1.0;
    const Rotor end = run_rotor<TestType>({{}, vrut::component(inertia, k) * w * axis}, inertia, {}, dt, steps);
    INFO("axis " << k);
    CHECK(axes_apart(end.q, vrut::axis_angle(axis, w * dt * steps)) < 1e-10);
    CHECK(vrut::norm(vrut::angular_velocity(end.q, end.momentum, inertia) - w * axis) < 1e-10 * w);
  }
}

// A constant torque about a principal axis: w = tau t / I and the angle
// tau t^2 / (2 I). The momentum lives at half steps (central differences),
// so started at t = -dt/2, L = -tau dt / 2, the sum of the steps' turns,
// tau dt^2 (n + 1/2) / I over n < N, is tau (N dt)^2 / (2 I) exactly.
TEMPLATE_LIST_TEST_CASE("a constant torque spins a body up as the closed form says", "[physics][bodies]",
                        vrut_test::ExecutionSpaces) {
  const vrut::Vec3 inertia{2.0, 3.0, 5.0}, axis{0, 1, 0};
  const double tau = 0.3, dt = 1e-3;
  const long steps = 4000;  // 4 s: 0.3 x 16 / 6 = 0.8 rad
  const Rotor end = run_rotor<TestType>({{}, -0.5 * tau * dt * axis}, inertia, tau * axis, dt, steps);
  const double t = dt * steps;
  CHECK(axes_apart(end.q, vrut::axis_angle(axis, tau * t * t / (2.0 * 3.0))) < 1e-12);
  // L at t + dt/2.
  CHECK(vrut::norm(end.momentum - tau * (t - 0.5 * dt) * axis) < 1e-12);
}

// The torque-free symmetric top (I1 = I2): in the body frame the momentum's
// part across the axis turns at Omega = (I3 - I1) w3 / I1, and in the world
// the body's axis turns about L at |L| / I1 (Landau and Lifshitz, Mechanics,
// section 33). The scheme is second order: halving the step quarters the
// error (3.5 to 4.5 allows for the next order), and at dt = 1e-3 the axes
// lie within 1e-4 of the closed form (measured 7.9e-6).
TEMPLATE_LIST_TEST_CASE("the torque-free symmetric top precesses as the closed form says", "[physics][bodies]",
                        vrut_test::ExecutionSpaces) {
  const vrut::Vec3 inertia{2.0, 2.0, 1.0};
  const vrut::Vec3 w0{3.0, 0.0, 10.0};
  const vrut::Vec3 momentum = vrut::times_each(inertia, w0);  // the body starts aligned with the world
  const double t = 2.0;
  const double spin = (inertia.z - inertia.x) * w0.z / inertia.x;
  const double precession = vrut::norm(momentum) / inertia.x;
  const vrut::Vec3 l_hat = (1.0 / vrut::norm(momentum)) * momentum;
  const vrut::Quaternion about_l = vrut::axis_angle(l_hat, precession * t);
  const vrut::Vec3 axis_expected = vrut::rotate(about_l, vrut::Vec3{0, 0, 1});
  const vrut::Vec3 pi_expected{inertia.x * w0.x * std::cos(spin * t), inertia.x * w0.x * std::sin(spin * t),
                               inertia.z * w0.z};
  auto error = [&](double dt) {
    const Rotor end = run_rotor<TestType>({{}, momentum}, inertia, {}, dt, std::lround(t / dt));
    const double axis = vrut::norm(vrut::rotate(end.q, vrut::Vec3{0, 0, 1}) - axis_expected);
    const double pi = vrut::norm(vrut::rotate_back(end.q, end.momentum) - pi_expected) / vrut::norm(momentum);
    return std::max(axis, pi);
  };
  vrut_test::check_second_order(error(2e-3), error(1e-3), 1e-4);
}

namespace {

// An independent reference: Euler's equations I w' = (I w) x w in the body
// frame and q' = q (0, w) / 2, by classical Runge-Kutta on the host; the
// state is q (w, x, y, z) and w (body frame).
std::array<double, 7> euler_rates(const std::array<double, 7>& y, vrut::Vec3 I) {
  const vrut::Quaternion q{y[0], y[1], y[2], y[3]};
  const vrut::Vec3 w{y[4], y[5], y[6]};
  const vrut::Quaternion dq = q * vrut::Quaternion{0.0, w.x, w.y, w.z};
  const vrut::Vec3 dw = vrut::over_each(vrut::cross(vrut::times_each(I, w), w), I);
  return {0.5 * dq.w, 0.5 * dq.x, 0.5 * dq.y, 0.5 * dq.z, dw.x, dw.y, dw.z};
}

vrut::Quaternion runge_kutta(vrut::Vec3 w0, vrut::Vec3 I, double t, long steps) {
  std::array<double, 7> y{1, 0, 0, 0, w0.x, w0.y, w0.z};
  const double h = t / steps;
  auto plus = [](std::array<double, 7> a, const std::array<double, 7>& b, double s) {
    for (int i = 0; i < 7; ++i) a[i] += s * b[i];
    return a;
  };
  for (long n = 0; n < steps; ++n) {
    const auto k1 = euler_rates(y, I), k2 = euler_rates(plus(y, k1, h / 2), I);
    const auto k3 = euler_rates(plus(y, k2, h / 2), I), k4 = euler_rates(plus(y, k3, h), I);
    for (int i = 0; i < 7; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return vrut::normalized({y[0], y[1], y[2], y[3]});
}

}  // namespace

// A body with three different moments, tumbling near its intermediate axis
// (the unstable one, where errors grow fastest), against Runge-Kutta at a
// step 100 times finer (its error, fourth order, below 1e-10 here): second
// order again, and at dt = 1e-3 both the axes' error and the energy's
// relative drift (the scheme does not hold the energy exactly) below
// (w dt)^2 = 1.6e-5, the size of a second-order error at this spin
// (measured 2.0e-6 and 4e-8).
TEMPLATE_LIST_TEST_CASE("a tumbling body turns as Runge-Kutta on Euler's equations says", "[physics][bodies]",
                        vrut_test::ExecutionSpaces) {
  const vrut::Vec3 inertia{1.0, 2.0, 3.0}, w0{0.2, 4.0, 0.3};
  const double t = 2.0;
  const vrut::Quaternion reference = runge_kutta(w0, inertia, t, 200000);
  const vrut::Vec3 momentum = vrut::times_each(inertia, w0);
  const double energy = 0.5 * vrut::dot(w0, momentum);
  auto run = [&](double dt) { return run_rotor<TestType>({{}, momentum}, inertia, {}, dt, std::lround(t / dt)); };
  const Rotor coarse = run(2e-3), fine = run(1e-3);
  vrut_test::check_second_order(axes_apart(coarse.q, reference), axes_apart(fine.q, reference), 1.6e-5);
  CHECK(std::abs(vrut::rotational_energy(fine.q, fine.momentum, inertia) / energy - 1.0) < 1.6e-5);
}

// The mass properties of a clump of spheres (geometry/clump3.hpp):
//   - one sphere: 4/3 pi r^3 rho and 2/5 m r^2 about every axis;
//   - two equal spheres 2a apart along an oblique u: 2 (2/5 m r^2) about u,
//     2 (2/5 m r^2 + m a^2) across it, u the axis of the least moment;
//   - an L of four spheres, no symmetry: each principal axis, turned into
//     the world, is an eigenvector of the inertia tensor worked out here
//     directly in the world frame, and the members' offsets turned back
//     give their centres.
TEST_CASE("a clump's mass, principal moments and axes match closed forms", "[physics][bodies]") {
  const double rho = 2700.0, r = 0.002, m = rho * 4.0 / 3.0 * M_PI * r * r * r;
  const auto one = vrut::clump_properties({{0.1, 0.2, 0.3}}, {r}, rho);
  CHECK(one.mass == Approx(m).epsilon(1e-14));
  for (int k = 0; k < 3; ++k) CHECK(vrut::component(one.principal_moments, k) == Approx(0.4 * m * r * r).epsilon(1e-12));
  CHECK(vrut::norm(one.offsets[0]) < 1e-15);

  const vrut::Vec3 u{2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0}, middle{1.0, -2.0, 0.5};
  const double a = 0.0025;
  const auto pair = vrut::clump_properties({middle - a * u, middle + a * u}, {r, r}, rho);
  CHECK(vrut::norm(pair.centre - middle) < 1e-14);
  CHECK(pair.principal_moments.x == Approx(2 * 0.4 * m * r * r).epsilon(1e-9));
  CHECK(pair.principal_moments.y == Approx(2 * (0.4 * m * r * r + m * a * a)).epsilon(1e-9));
  CHECK(pair.principal_moments.z == Approx(2 * (0.4 * m * r * r + m * a * a)).epsilon(1e-9));
  CHECK(std::abs(vrut::dot(vrut::rotate(pair.orientation, vrut::Vec3{1, 0, 0}), u)) == Approx(1.0).epsilon(1e-12));

  const std::vector<vrut::Vec3> ell{{0, 0, 0}, {2 * r, 0, 0}, {4 * r, 0, 0}, {0, 2 * r, 0.5 * r}};
  const std::vector<double> radii{r, r, r, 0.7 * r};
  const auto body = vrut::clump_properties(ell, radii, rho);
  // The world tensor, independently: each sphere's own 2/5 m r^2, and the
  // parallel-axis terms written out component by component.
  double tensor[3][3] = {};
  for (std::size_t i = 0; i < ell.size(); ++i) {
    const double mi = rho * 4.0 / 3.0 * M_PI * std::pow(radii[i], 3);
    const vrut::Vec3 d = ell[i] - body.centre;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q)
        tensor[p][q] += (p == q ? 0.4 * mi * radii[i] * radii[i] + mi * vrut::dot(d, d) : 0.0) -
                        mi * vrut::component(d, p) * vrut::component(d, q);
  }
  for (int k = 0; k < 3; ++k) {
    vrut::Vec3 e{};
    vrut::component(e, k) = 1.0;
    const vrut::Vec3 axis = vrut::rotate(body.orientation, e);
    vrut::Vec3 image{};
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) vrut::component(image, p) += tensor[p][q] * vrut::component(axis, q);
    const double moment = vrut::component(body.principal_moments, k);
    INFO("axis " << k);
    CHECK(vrut::norm(image - moment * axis) < 1e-10 * moment);
  }
  CHECK(body.principal_moments.x < body.principal_moments.y);
  CHECK(body.principal_moments.y < body.principal_moments.z);
  for (std::size_t i = 0; i < ell.size(); ++i)
    CHECK(vrut::norm(body.centre + vrut::rotate(body.orientation, body.offsets[i]) - ell[i]) < 1e-15);
  CHECK_THROWS(vrut::clump_properties({}, {}, rho));
  CHECK_THROWS(vrut::clump_properties({{0, 0, 0}}, {-r}, rho));
}

// The mass a clump shows at a member's centre (the time step's, core.md):
// a dumbbell's in closed form, and any clump's against an independent
// computation in the world frame: 1 / (1/M + |d|^2 lambda), lambda the
// largest eigenvalue of the world I^-1 projected on the plane normal to d.
TEST_CASE("a clump's mass felt at a member: the dumbbell's closed form and the projected inverse inertia",
          "[physics][bodies]") {
  const double rho = 2700.0, r = 0.001, m = rho * 4.0 / 3.0 * M_PI * r * r * r;
  // Two spheres 2 sqrt(6) r apart (third neighbours on an FCC lattice of
  // spacing 2r): a force through one member, normal to the axis, turns the
  // pair about a transverse axis, I = 2 (2/5 m r^2 + m a^2), a = sqrt(6) r;
  // along the axis it only pushes. So M_felt = 1 / (1/(2m) + a^2 / I)
  // = m / (1/2 + 6/12.8), against m / 8 about the weakest axis (2 x 2/5 m r^2).
  const vrut::Vec3 u{2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0}, middle{0.01, -0.02, 0.005};
  const double a = std::sqrt(6.0) * r;
  const auto pair = vrut::clump_properties({middle - a * u, middle + a * u}, {r, r}, rho);
  for (const auto& d : pair.offsets)
    CHECK(vrut::mass_felt_at_member(pair, d) == Approx(m / (0.5 + 6.0 / 12.8)).epsilon(1e-12));
  const auto one = vrut::clump_properties({middle}, {r}, rho);
  CHECK(vrut::mass_felt_at_member(one, one.offsets[0]) == Approx(m).epsilon(1e-14));

  const std::vector<vrut::Vec3> lumpy{{0, 0, 0}, {2 * r, 0, 0}, {4 * r, 0, 0}, {0, 2 * r, 0.5 * r},
                                      {r, r, 1.4 * r}, {3 * r, -r, 1.4 * r}};
  const std::vector<double> radii(lumpy.size(), r);
  const auto body = vrut::clump_properties(lumpy, radii, rho);
  const Eigen::Matrix3d world_inverse =
      vrut::sphere_inertia_tensor(lumpy, radii, rho, body.centre).inverse();
  for (std::size_t i = 0; i < lumpy.size(); ++i) {
    const vrut::Vec3 d = lumpy[i] - body.centre;
    const Eigen::Vector3d e = Eigen::Vector3d(d.x, d.y, d.z).normalized();
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - e * e.transpose();
    const double lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(across * world_inverse * across).eigenvalues().maxCoeff();
    INFO("member " << i);
    CHECK(vrut::mass_felt_at_member(body, body.offsets[i]) ==
          Approx(1.0 / (1.0 / body.mass + vrut::dot(d, d) * lambda)).epsilon(1e-10));
  }
}

