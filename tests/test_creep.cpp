// The virtual creep test (protocol/creep.hpp): a bonded all-mastic block
// under a dead-load plate, against the macro Burger's model.
#include "openmp_threads.hpp"
#include "spaces.hpp"

#include <vrut/material/burgers_fit.hpp>
#include <vrut/protocol/creep.hpp>

#include <catch2/catch.hpp>

#include <cmath>

namespace {

vrut::CreepSettings small_strain(double shift, const vrut::MicroConversion& conv) {
  vrut::CreepSettings cs;
  cs.stress = 0.01e6;  // 5.5 % strain at 342 s: the small-strain range of the comparison
  cs.shift = shift;
  cs.conversion = conv;
  return cs;
}

double worst_deviation(const vrut::CreepResult& res, double from_time = 0.0) {
  double worst = 0.0;
  for (const auto& s : res.samples)
    if (s.time >= from_time) worst = std::max(worst, std::abs(s.strain_virtual / s.strain_analytic - 1.0));
  return worst;
}

vrut::BurgersFit fit(const vrut::CreepResult& res, double stress) {
  std::vector<double> t, e;
  for (const auto& s : res.samples) t.push_back(s.time), e.push_back(s.strain_virtual);
  return vrut::fit_burgers(t, e, stress);
}

}  // namespace

TEST_CASE("calibrated creep follows the macro Burger's model at every written time (alpha_T = 1e3)",
          "[burgers][creep][physics]") {
  const auto cs = small_strain(1e3, vrut::MicroConversion::calibrated(0.35));
  const vrut::CreepResult res = vrut::run_creep<Kokkos::DefaultHostExecutionSpace>(cs);
  REQUIRE(res.samples.size() == 100);
  CHECK(res.samples.back().time == Approx(342.2).epsilon(1e-3));
  INFO("worst deviation " << worst_deviation(res));
  CHECK(worst_deviation(res) < 0.05);
}

TEST_CASE("at alpha_T = 1e4 the creep matches once the inertial transient has passed",
          "[burgers][creep][physics]") {
  // The shift multiplies inertia by alpha_T^2 relative to the material's
  // time constants (1.2 and 1.8 ms reduced): the first seconds of the curve
  // carry the specimen's ringing. docs/burgers.md gives the numbers.
  const auto cs = small_strain(1e4, vrut::MicroConversion::calibrated(0.35));
  const vrut::CreepResult res = vrut::run_creep<Kokkos::DefaultHostExecutionSpace>(cs);
  std::printf("alpha_T = 1e4: worst deviation %.3f overall, %.3f from 20 s on\n", worst_deviation(res),
              worst_deviation(res, 20.0));
  CHECK(worst_deviation(res, 20.0) < 0.05);
}

// Against a reference this code did not produce: the infinite hexagonal
// lattice (docs/burgers.md) makes every apparent constant c times the macro
// one, c = 2 sqrt(3)(1+b)/(3+b), b = 1/(2(1+nu)). A finite block is softer
// at its free sides, by a part that falls as 1/width: the blocks of 20 x 10
// and 40 x 20 disks extrapolate (Richardson, 2 r40 - r20) to the infinite
// lattice. Measured 2.7 % and 1.5 % below c, and 0.2 % in the limit.
// The 1 % tolerance covers the remaining strain (1.1 % at 0.002 MPa; the
// lattice softens with strain, by about 0.3 % here, from the slope between
// 0.002 and 0.01 MPa) and what the 1/width law leaves (it predicts the 80 x 40
// block within 0.05 %). Only eta1, the long-time slope: E1 carries the
// start-up transient, which grows with the block, and E2 and eta2 share it
// through the fit.
TEST_CASE("seed rules: a growing block tends to the lattice theory's stiffness and viscosity",
          "[burgers][creep][physics]") {
  auto ratio = [](int columns, int rows) {
    auto cs = small_strain(1e3, vrut::MicroConversion::seed());
    cs.stress = 0.002e6;
    cs.columns = columns;
    cs.rows = rows;
    const vrut::CreepResult res = vrut::run_creep<Kokkos::DefaultHostExecutionSpace>(cs);
    return fit(res, cs.stress).macro.eta1 / cs.macro.eta1;
  };
  const double b = 1.0 / 2.7, c = 2.0 * std::sqrt(3.0) * (1.0 + b) / (3.0 + b);
  const double r20 = ratio(20, 10), r40 = ratio(40, 20), limit = 2.0 * r40 - r20;
  std::printf("seed rules, apparent/macro eta1 over lattice theory %.4f: 20 x 10 %.4f, 40 x 20 %.4f, limit %.4f\n", c,
              r20 / c, r40 / c, limit / c);
  CHECK(r20 < r40);
  CHECK(r40 < c);
  CHECK(limit == Approx(c).epsilon(0.01));
}

#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
// Every sum in a fixed order: the same bits on one thread and on several.
TEST_CASE("Serial and OpenMP give the same creep curve, bit for bit", "[burgers][creep][backends]") {
  if (!vrut_test::openmp_runs_several_threads()) return;
  auto cs = small_strain(1e4, vrut::MicroConversion::seed());
  cs.duration = 40.0;
  const vrut::CreepResult serial = vrut::run_creep<Kokkos::Serial>(cs);
  const vrut::CreepResult openmp = vrut::run_creep<Kokkos::OpenMP>(cs);
  REQUIRE(serial.samples.size() == openmp.samples.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < serial.samples.size(); ++i)
    differ += serial.samples[i].strain_virtual != openmp.samples[i].strain_virtual;
  CHECK(differ == 0);
  CHECK(openmp.samples.back().strain_virtual > 0.0);  // it crept
}
#endif
