// The Burger's contact element against exact solutions: creep under constant
// force, relaxation under held displacement, the order of the scheme, and
// time-temperature superposition.
#include <vrut/contact/burgers.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/contact/film.hpp>
#include <vrut/material/burgers_parameters.hpp>
#include <vrut/material/contact_classes.hpp>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace {

using vrut::BurgersElement;
using vrut::BurgersHistory;

// SPEC section 8 values (t = 50 mm, alpha_T = 1): K_m, C_m, K_k, C_k.
BurgersElement spec_normal() { return vrut::burgers_element(vrut::BurgersMacro{}, 0.05, 1.0, {}); }
BurgersElement spec_shear() { return vrut::burgers_element(vrut::BurgersMacro{}, 0.05, 1.0 / 2.7, {}); }

double exact_creep(const BurgersElement& e, double force, double t) {
  return force * (1.0 / e.maxwell_stiffness + t / e.maxwell_viscosity +
                  (1.0 - std::exp(-e.kelvin_stiffness * t / e.kelvin_viscosity)) / e.kelvin_stiffness);
}

// Exact relaxation of f and u_k under u held at u0 from t = 0:
//   f'   = -K_m (f / C_m + (f - K_k u_k) / C_k),   u_k' = (f - K_k u_k) / C_k,
// solved by eigen-decomposition of the 2x2 system, f(0) = K_m u0, u_k(0) = 0.
double exact_relaxation(const BurgersElement& e, double u0, double t) {
  Eigen::Matrix2d a;
  a << -e.maxwell_stiffness * (1.0 / e.maxwell_viscosity + 1.0 / e.kelvin_viscosity),
      e.maxwell_stiffness * e.kelvin_stiffness / e.kelvin_viscosity, 1.0 / e.kelvin_viscosity,
      -e.kelvin_stiffness / e.kelvin_viscosity;
  Eigen::EigenSolver<Eigen::Matrix2d> solver(a);
  const Eigen::Matrix2cd v = solver.eigenvectors();
  const Eigen::Vector2cd lambda = solver.eigenvalues();
  const Eigen::Vector2cd c = v.colPivHouseholderQr().solve(Eigen::Vector2cd(e.maxwell_stiffness * u0, 0.0));
  Eigen::Vector2cd x = v * (c.array() * (lambda.array() * t).exp()).matrix();
  return x(0).real();
}

// The displacement step that brings the element to `force` this step, found
// by probing copies of the history (the element is linear in du).
double du_for_force(const BurgersElement& e, const BurgersHistory& h, double force, double dt) {
  BurgersHistory a = h, b = h;
  const double f0 = vrut::burgers_step(e, a, 0.0, dt);
  const double f1 = vrut::burgers_step(e, b, 1.0, dt);
  return (force - f0) / (f1 - f0);
}

// Creep under `force` applied at t = 0 (the elastic jump first, with dt -> 0),
// returns the largest relative error against the exact curve and the final error.
struct CreepError {
  double worst_relative, final_absolute, final_u;
};
CreepError creep(const BurgersElement& e, double force, double dt, double duration) {
  BurgersHistory h;
  double u = du_for_force(e, h, force, 1e-300 * dt);
  vrut::burgers_step(e, h, u, 1e-300 * dt);
  CreepError err{0.0, 0.0, 0.0};
  const long steps = std::lround(duration / dt);
  for (long s = 1; s <= steps; ++s) {
    const double du = du_for_force(e, h, force, dt);
    vrut::burgers_step(e, h, du, dt);
    u += du;
    const double exact = exact_creep(e, force, s * dt);
    err.worst_relative = std::max(err.worst_relative, std::abs(u / exact - 1.0));
    err.final_absolute = std::abs(u - exact);
  }
  err.final_u = u;
  return err;
}

// The slowest time constant of the element's relaxation under held
// displacement (the system of exact_relaxation).
double slowest_relaxation(const BurgersElement& e) {
  Eigen::Matrix2d a;
  a << -e.maxwell_stiffness * (1.0 / e.maxwell_viscosity + 1.0 / e.kelvin_viscosity),
      e.maxwell_stiffness * e.kelvin_stiffness / e.kelvin_viscosity, 1.0 / e.kelvin_viscosity,
      -e.kelvin_stiffness / e.kelvin_viscosity;
  return 1.0 / a.eigenvalues().real().cwiseAbs().minCoeff();
}

double tau_min(const BurgersElement& e) {
  return std::min(e.maxwell_viscosity / e.maxwell_stiffness, e.kelvin_viscosity / e.kelvin_stiffness);
}

}  // namespace

TEST_CASE("Burger's element creeps as the exact solution (normal and shear)", "[burgers][physics]") {
  for (const BurgersElement& e : {spec_normal(), spec_shear()}) {
    const double dt = 1e-3 * tau_min(e);
    const CreepError err = creep(e, 100.0, dt, 3.0 * e.kelvin_viscosity / e.kelvin_stiffness);
    INFO("K_m " << e.maxwell_stiffness << ": worst relative error " << err.worst_relative);
    CHECK(err.worst_relative < 1e-4);
  }
}

TEST_CASE("Burger's element relaxes as the exact solution", "[burgers][physics]") {
  for (const BurgersElement& e : {spec_normal(), spec_shear()}) {
    const double u0 = 1e-4, dt = 1e-3 * tau_min(e);
    BurgersHistory h;
    vrut::burgers_step(e, h, u0, 1e-300);  // the jump: f = K_m u0
    CHECK(h.force == Approx(e.maxwell_stiffness * u0).epsilon(1e-12));
    double worst = 0.0;
    const long steps = std::lround(3.0 * e.maxwell_viscosity / e.maxwell_stiffness / dt);
    for (long s = 1; s <= steps; ++s) {
      const double f = vrut::burgers_step(e, h, 0.0, dt);
      const double exact = exact_relaxation(e, u0, s * dt);
      // Relative to the initial force: the force decays towards zero.
      worst = std::max(worst, std::abs(f - exact) / (e.maxwell_stiffness * u0));
    }
    INFO("worst error / initial force " << worst);
    CHECK(worst < 1e-4);
  }
}

TEST_CASE("Burger's update converges at second order", "[burgers][physics]") {
  for (const BurgersElement& e : {spec_normal(), spec_shear()}) {
    const double duration = 2.0 * e.kelvin_viscosity / e.kelvin_stiffness;
    const double dt = 0.05 * tau_min(e);
    const double e1 = creep(e, 100.0, dt, duration).final_absolute;
    const double e2 = creep(e, 100.0, dt / 2, duration).final_absolute;
    const double e3 = creep(e, 100.0, dt / 4, duration).final_absolute;
    const double order1 = std::log2(e1 / e2), order2 = std::log2(e2 / e3);
    INFO("errors " << e1 << ", " << e2 << ", " << e3 << "; observed orders " << order1 << ", " << order2);
    CHECK(order1 > 1.8);
    CHECK(order2 > 1.8);
  }
}

TEST_CASE("time-temperature shift: creep at t / alpha_T equals unshifted creep at t", "[burgers][physics]") {
  const vrut::BurgersMacro macro;
  const vrut::TimeShift shift(1e4);
  const BurgersElement plain = vrut::burgers_element(macro, 0.05, 1.0, {});
  const BurgersElement shifted = vrut::burgers_element(macro.shifted(shift), 0.05, 1.0, {});
  CHECK(shifted.maxwell_viscosity == Approx(416.7).epsilon(1e-3));  // SPEC section 8
  CHECK(shifted.kelvin_viscosity == Approx(50.0).epsilon(1e-12));
  const double duration = 342.2, dt = 1e-3 * tau_min(plain);
  const double u_plain = creep(plain, 765.0, dt, duration).final_u;
  const double u_shifted = creep(shifted, 765.0, shift.reduced_time(dt), shift.reduced_time(duration)).final_u;
  INFO("plain " << u_plain << " shifted " << u_shifted);
  CHECK(std::abs(u_shifted / u_plain - 1.0) < 1e-9);
}

TEST_CASE("micro parameters follow the SPEC's rules and numbers", "[burgers][unit]") {
  const double t = 0.05, nu = 0.35;
  const auto p = vrut::mastic_params(vrut::BurgersMacro{}, t, nu);
  CHECK(p.normal.maxwell_stiffness == Approx(2.32e5));
  CHECK(p.normal.maxwell_viscosity == Approx(4.167e6).epsilon(1e-3));
  CHECK(p.normal.kelvin_stiffness == Approx(4.10e4));
  CHECK(p.normal.kelvin_viscosity == Approx(5.0e5));
  CHECK(p.shear.maxwell_stiffness == Approx(2.32e5 / 2.7));
  CHECK(p.shear.kelvin_viscosity == Approx(5.0e5 / 2.7));
  const auto twice = vrut::mastic_params(vrut::BurgersMacro{}, t, nu, vrut::MicroConversion::seed(), 2.0);
  CHECK(twice.normal.kelvin_stiffness == Approx(2.0 * 4.10e4));
  const auto agg = vrut::aggregate_params(55.5e9, t, nu);
  CHECK(agg.normal.stiffness == Approx(5.55e9));
  CHECK(agg.shear.stiffness == Approx(5.55e9 / 2.7));
  // SPEC section 8: the mastic alone creeps to a strain of 3.88 at 0.7 MPa and 342 s.
  CHECK(vrut::BurgersMacro{}.creep_strain(0.7e6, 342.2) == Approx(3.88).epsilon(2e-3));
}

TEST_CASE("bad Burger's parameters are refused with a message", "[burgers][unit]") {
  vrut::BurgersMacro bad;
  bad.eta1 = 0.0;
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("eta1"));
  bad = {};
  bad.E2 = -1.0;
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("E2"));
  CHECK_THROWS_WITH(vrut::mastic_params(vrut::BurgersMacro{}, 0.05, 0.5), Catch::Contains("Poisson"));
  CHECK_THROWS_WITH(vrut::mastic_params(vrut::BurgersMacro{}, 0.05, -0.1), Catch::Contains("Poisson"));
  CHECK_THROWS_WITH(vrut::TimeShift(0.0), Catch::Contains("alpha_T"));
  CHECK_THROWS_WITH(vrut::TimeShift(-3.0), Catch::Contains("alpha_T"));
}

TEST_CASE("an unbonded Burger's contact does not pull and is capped by friction", "[burgers][unit]") {
  using Law = vrut::Burgers;
  Law::params_type p;
  p.normal = spec_normal();
  p.shear = spec_shear();
  p.friction = 0.3;
  Law::state_type s{};
  vrut::ContactGeometry g;
  g.dt = 1e-3;
  g.normal_increment = 1e-4;  // load
  g.shear_increment = 1e-3;   // a large slip
  const vrut::ContactForce f1 = Law::force(p, s, g);
  CHECK(f1.normal > 0.0);
  CHECK(std::abs(f1.shear) == Approx(0.3 * f1.normal));
  g.normal_increment = -1e-3;  // pull away fast: the Maxwell spring would go into tension
  g.shear_increment = 0.0;
  const vrut::ContactForce f2 = Law::force(p, s, g);
  CHECK(f2.normal == 0.0);
  CHECK(s.normal.force == 0.0);  // the stored tension is dropped
  CHECK(f2.shear == 0.0);
}

// A film between two stones under a constant force: it creeps as the
// Burger's element alone until the overlap reaches the film's thickness; then
// the stones' spring takes the load over, and as the film relaxes the
// overlap tends to thickness + force / stone stiffness. Each step's
// displacement is solved here from the element (linear in du) and the spring
// (linear beyond the thickness); the slot must return the applied force.
TEST_CASE("a film creeps as Burger's until it squeezes out, then the stones bear", "[burgers][physics]") {
  const BurgersElement e = spec_normal();
  const double force = 100.0, dt = 1e-3 * tau_min(e);
  const double t_touch = e.kelvin_viscosity / e.kelvin_stiffness;
  vrut::FilmNormal::params_type p;
  p.film = e;
  p.thickness = exact_creep(e, force, t_touch);  // the stones touch at t_touch
  p.stone_stiffness = 10.0 * e.maxwell_stiffness;
  const double limit = p.thickness + force / p.stone_stiffness;

  BurgersHistory h;
  vrut::ContactGeometry g;
  g.dt = 1e-300 * dt;  // the elastic jump
  g.normal_increment = du_for_force(e, h, force, g.dt);
  g.overlap = g.normal_increment;
  CHECK(vrut::FilmNormal::force(p, h, g) == Approx(force).epsilon(1e-12));
  g.dt = dt;
  double worst_creep = 0.0, worst_force = 0.0, touched_at = -1.0, highest = 0.0;
  // Long enough for the film to relax: 30 of its slowest relaxation times
  // (the element under held displacement, exact_relaxation's system; the
  // spring, 10 times as stiff, holds the overlap to within about 10 %).
  const double slowest = slowest_relaxation(e);
  const long steps = std::lround((t_touch + 30.0 * slowest) / dt);
  for (long s = 1; s <= steps; ++s) {
    BurgersHistory a = h, b = h;
    const double f0 = vrut::burgers_step(e, a, 0.0, dt), slope = vrut::burgers_step(e, b, 1.0, dt) - f0;
    double du = (force - f0) / slope;
    if (g.overlap + du > p.thickness)
      du = (force - f0 + p.stone_stiffness * (p.thickness - g.overlap)) / (slope + p.stone_stiffness);
    g.normal_increment = du;
    g.overlap += du;
    worst_force = std::max(worst_force, std::abs(vrut::FilmNormal::force(p, h, g) / force - 1.0));
    highest = std::max(highest, g.overlap);
    if (touched_at < 0.0 && g.overlap > p.thickness) touched_at = s * dt;
    if (touched_at < 0.0) worst_creep = std::max(worst_creep, std::abs(g.overlap / exact_creep(e, force, s * dt) - 1.0));
  }
  INFO("creep error " << worst_creep << ", touched at " << touched_at << " s (exact " << t_touch << " s)");
  CHECK(worst_force < 1e-9);
  CHECK(worst_creep < 1e-4);
  // The crossing lies within a step of the exact time.
  CHECK(std::abs(touched_at - t_touch) <= 1.0001 * dt);
  // The film pushes too, so the overlap never passes the stones' limit; after
  // 30 relaxation times the film carries about e^-27 of the force.
  CHECK(highest <= limit * (1.0 + 1e-12));
  CHECK(g.overlap == Approx(limit).epsilon(1e-6));
  // Without stones it is the Burger's element, bit for bit.
  vrut::FilmNormal::params_type alone;
  alone.film = e;
  BurgersHistory x, y;
  g.normal_increment = 1e-5;
  g.overlap = 1.0;  // far past any thickness: no stones, no spring
  CHECK(vrut::FilmNormal::force(alone, x, g) == vrut::burgers_step(e, y, 1e-5, dt));
  CHECK(vrut::FilmNormal::stiffness(alone) == e.maxwell_stiffness);
}

// Two stones pressed together through a film, then sheared a little and
// held: while they touch, the stones' shear spring holds its force and only
// the film's part relaxes, so the shear tends to k_s times the slip; apart,
// the film alone relaxes it to nothing. Either way under the friction cap.
TEST_CASE("stones that bear on each other hold a shear, a film alone lets it relax", "[burgers][physics]") {
  using Law = vrut::BurgersFilmBonded;
  const double thickness = 1e-4, kn = 50.0 * spec_normal().maxwell_stiffness, ks = kn / 2.5;
  const Law::params_type p = vrut::film_params(
      vrut::mastic_params(vrut::BurgersMacro{}, 0.05, 0.35, vrut::MicroConversion::seed(), 2.5, 0.5), thickness, kn, ks);
  const double slip = 1e-6;
  const double dt = 1e-3 * tau_min(p.shear.film);
  const double hold = 30.0 * std::max(slowest_relaxation(p.normal.film), slowest_relaxation(p.shear.film));
  for (const double overlap : {2.0 * thickness, 0.5 * thickness}) {
    const bool touching = overlap > thickness;
    Law::state_type s{};
    vrut::ContactGeometry g;
    g.dt = 1e-300;  // press, then shear: elastic jumps
    g.overlap = overlap;
    g.normal_increment = overlap;
    Law::force(p, s, g);
    g.normal_increment = 0.0;
    g.shear_increment = slip;
    vrut::ContactForce f = Law::force(p, s, g);
    g.shear_increment = 0.0;
    g.dt = dt;
    double worst_cap = 0.0;
    for (long k = 0, steps = std::lround(hold / dt); k < steps; ++k) {
      f = Law::force(p, s, g);
      worst_cap = std::max(worst_cap, std::abs(f.shear) - p.friction * f.normal);
    }
    INFO((touching ? "touching" : "apart") << ": shear " << f.shear << " N, normal " << f.normal << " N");
    CHECK(worst_cap <= 0.0);
    if (touching) {
      CHECK(f.normal == Approx(kn * (overlap - thickness)).epsilon(1e-9));
      CHECK(f.shear == Approx(-ks * slip).epsilon(1e-9));
    } else {
      CHECK(std::abs(f.normal) < 1e-9 * kn * thickness);
      CHECK(std::abs(f.shear) < 1e-9 * ks * slip);
    }
  }
}

// Touching stones that still meet through their binder (an experiment:
// RuttingMaterials::stone_shear_film). Their shear spring k_s sits in series
// with the binder film's dashpot c, a Maxwell element of time tau = c / k_s,
// with c the mastic's Maxwell viscosity in shear over the film: in 2D on
// disks t thick and d across, c = (eta1 / alpha_T) t (d / h) / (2 (1 + nu))
// and k_s = ratio E1 t / (2 (1 + nu_a)), so tau = (eta1 / alpha_T) (d / h)
// (1 + nu_a) / (ratio E1 (1 + nu)): 1.6631 ms at alpha_T 1e4 for d = 2 mm
// and a 20 um film. Sheared at a constant rate v from rest, the spring's
// force is k_s v tau (1 - e^(-t / tau)); then held, it falls by e^-1 in each
// tau. The film beside it is the same as without the spring, so the total
// less that film's force alone is the spring's.
TEST_CASE("stones meeting through their binder: the held shear relaxes with the film's time constant", "[burgers][physics]") {
  vrut::RuttingMaterials m;
  m.stone_shear_film = 20e-6;
  vrut::ContactScales scales;
  scales.mastic_length = scales.stone_length = 0.05;
  scales.diameter = 2e-3;
  scales.shift = 1e4;
  const double tau = (83.34e6 / 1e4) * (2e-3 / 20e-6) * 1.25 / (100.0 * 4.64e6 * 1.35);
  REQUIRE(tau == Approx(1.6631e-3).epsilon(1e-4));
  const auto law = vrut::stone_film_params(m, scales, 0.3);
  CHECK(law.shear.stone_relaxation_time == Approx(tau).epsilon(1e-12));
  const double ks = 100.0 * 4.64e6 * 0.05 / 2.5;
  CHECK(law.shear.stone_stiffness == Approx(ks).epsilon(1e-12));

  using Shear = vrut::FilmShear;
  Shear::params_type with = law.shear, film_alone = law.shear;
  film_alone.stone_stiffness = 0.0;
  const double dt = tau / 100.0, v = 1e-3;  // m/s of slip
  Shear::prepare(with, dt);
  Shear::prepare(film_alone, dt);
  Shear::state_type a{}, b{};
  vrut::ContactGeometry g;
  g.dt = dt;
  g.overlap = 2.0 * with.thickness + 1e-6;  // the stones touch
  g.shear_increment = -v * dt;
  double worst = 0.0;
  for (int k = 1; k <= 300; ++k) {
    const double spring = Shear::force(with, a, g) - Shear::force(film_alone, b, g);
    const double exact = ks * v * tau * -std::expm1(-k * dt / tau);
    worst = std::max(worst, std::abs(spring / exact - 1.0));
  }
  CHECK(worst < 1e-12);
  const double loaded = a.stone;
  g.shear_increment = 0.0;
  for (int k = 1; k <= 100; ++k) Shear::force(with, a, g);
  CHECK(a.stone == Approx(loaded * std::exp(-1.0)).epsilon(1e-12));
  // Without the film's dashpot (the model) the spring holds the same force.
  Shear::params_type holding = law.shear;
  holding.stone_relaxation_time = 0.0;
  Shear::prepare(holding, dt);
  Shear::state_type c{};
  c.stone = loaded;
  for (int k = 1; k <= 100; ++k) Shear::force(holding, c, g);
  CHECK(c.stone == loaded);

  m.stone_film = vrut::StoneFilm::mean;
  CHECK_THROWS_WITH(vrut::stone_film_params(m, scales, 0.3), Catch::Contains("with the film per contact"));
  m.stone_film = vrut::StoneFilm::per_contact;
  m.stone_shear_film = 2e-3;
  CHECK_THROWS_WITH(vrut::stone_film_params(m, scales, 0.3), Catch::Contains("thinner than a particle's diameter"));
}
