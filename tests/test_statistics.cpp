// Ensemble statistics against values worked by hand and against the
// textbook Student-t quantiles.
#include <vrut/analysis/rutting_ensemble.hpp>
#include <vrut/analysis/standard_ds.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

TEST_CASE("ensemble statistics match hand-worked values", "[analysis][unit]") {
  // 1..5: mean 3, sd sqrt(2.5); t(0.975, 4 dof) = 2.7764 (printed tables).
  const auto s = vrut::describe({5.0, 1.0, 4.0, 2.0, 3.0});
  CHECK(s.n == 5);
  CHECK(s.mean == Approx(3.0));
  CHECK(s.sd == Approx(std::sqrt(2.5)));
  CHECK(s.median == Approx(3.0));
  CHECK(s.ci_low == Approx(3.0 - 2.7764 * std::sqrt(2.5) / std::sqrt(5.0)).epsilon(1e-4));
  CHECK(s.ci_high == Approx(3.0 + 2.7764 * std::sqrt(2.5) / std::sqrt(5.0)).epsilon(1e-4));
  // Even count: the median is the mean of the middle two; t(0.975, 1 dof) = 12.706.
  const auto two = vrut::describe({10.0, 20.0});
  CHECK(two.median == Approx(15.0));
  CHECK(two.ci_high - two.mean == Approx(12.706 * std::sqrt(50.0) / std::sqrt(2.0)).epsilon(1e-4));
  // 90 %: t(0.95, 4 dof) = 2.1318.
  const auto ninety = vrut::describe({5.0, 1.0, 4.0, 2.0, 3.0}, 0.90);
  CHECK(ninety.ci_high - ninety.mean == Approx(2.1318 * std::sqrt(2.5) / std::sqrt(5.0)).epsilon(1e-4));
  const auto one = vrut::describe({7.0});
  CHECK(one.mean == 7.0);
  CHECK(std::isnan(one.sd));
  CHECK_THROWS(vrut::describe({}));
}

// The DS's interval: the geometric mean's, from the logarithms. 1, 10, 100:
// ln 10 x (0, 1, 2), mean ln 10, sd ln 10, so the geometric mean is 10 and
// its interval 10^(1 -+ 4.3027 / sqrt(3)) = 0.0328 to 3049. DS 100, 200,
// 600 (tests/pool.sh): the arithmetic mean's interval reaches below zero
// (300 -+ 657), the geometric mean's is 24.27 to 2160.
TEST_CASE("a positive quantity's geometric mean has an interval that stays positive", "[analysis][unit]") {
  const auto g = vrut::describe_geometric({100.0, 1.0, 10.0});
  CHECK(g.n == 3);
  CHECK(g.mean == Approx(10.0));
  CHECK(g.ci_low == Approx(std::pow(10.0, 1.0 - 4.3027 / std::sqrt(3.0))).epsilon(1e-4));
  CHECK(g.ci_high == Approx(std::pow(10.0, 1.0 + 4.3027 / std::sqrt(3.0))).epsilon(1e-4));
  const std::vector<double> ds{100.0, 200.0, 600.0};
  CHECK(vrut::describe(ds).ci_low < 0.0);
  const auto spread = vrut::describe_geometric(ds);
  CHECK(spread.mean == Approx(std::cbrt(100.0 * 200.0 * 600.0)));
  CHECK(spread.ci_low == Approx(24.27).epsilon(1e-3));
  CHECK(spread.ci_high == Approx(2160.0).epsilon(1e-3));
  // One value: no interval; a value not positive (or a run stopped early): no geometric mean.
  const auto one = vrut::describe_geometric({7.0});
  CHECK(one.mean == Approx(7.0));
  CHECK(std::isnan(one.ci_low));
  CHECK(std::isnan(vrut::describe_geometric({5.0, 0.0}).mean));
  CHECK(std::isnan(vrut::describe_geometric({5.0, std::nan("")}).mean));
  CHECK_THROWS(vrut::describe_geometric({}));
}

TEST_CASE("the ensemble's mean curve and its DS", "[analysis][unit]") {
  // Two curves sampled at 0, 45 and 60 min: 0 / 4 / 5 mm and 0 / 6 / 9 mm.
  // Mean curve 0 / 5 / 7 mm: DS = 15 min * 42 / 2 mm = 315 passes/mm, while
  // the specimens' own DS are 630 and 210.
  auto run = [](double d45, double d60) {
    vrut::RuttingResult r;
    for (auto [minute, d] : {std::pair<double, double>{0.0, 0.0}, {45.0, d45}, {60.0, d60}}) {
      vrut::RuttingSample s;
      s.minutes = minute;
      s.deformation = d * 1e-3;
      s.plate_pressure = 0.7e6;
      r.samples.push_back(s);
    }
    vrut::finish_deformation(r, vrut::WheelTracking{});
    return r;
  };
  const auto summary = vrut::summarize_rutting({run(4.0, 5.0), run(6.0, 9.0)}, vrut::WheelTracking{});
  CHECK(summary.mean_curve.dynamic_stability == Approx(315.0));
  CHECK(summary.dynamic_stability.mean == Approx(0.5 * (630.0 + 210.0)));
  CHECK(summary.dynamic_stability_geometric.mean == Approx(std::sqrt(630.0 * 210.0)));
  CHECK(summary.dynamic_stability_geometric.ci_low > 0.0);
  CHECK(summary.rut_depth.mean == Approx(7.0));
  CHECK(summary.deformation_at_ds_start.mean == Approx(5.0));
  CHECK(summary.deformation_sd[2] == Approx(std::sqrt(8.0) * 1e-3));
  CHECK(summary.mean_curve.samples[1].plate_pressure == Approx(0.7e6));
}

// The DS's resolution, against values worked by hand. A curve sampled every
// minute, d(t) = b t plus a jitter of +e, -e, -e, +e repeated from minute 45:
// that pattern sums to zero and so does its product with t over each group of
// four, so a least-squares line through minutes 45-60 (16 samples) finds the
// trend exactly and leaves the jitter as its residuals: s = e sqrt(16 / 14).
// The resolution is 2 sqrt(2) s; minutes 45 and 60 both carry +e, so the
// change between them is exactly 15 b.
TEST_CASE("a DS whose deformation the curve cannot resolve is a lower bound", "[analysis][unit]") {
  const double e = 0.01e-3;  // m
  auto curve = [&](double slope_mm_per_min) {
    vrut::RuttingResult r;
    for (int minute = 0; minute <= 60; ++minute) {
      vrut::RuttingSample s;
      s.minutes = minute;
      const int k = minute - 45;
      const double jitter = k < 0 ? 0.0 : ((k % 4 == 0 || k % 4 == 3) ? e : -e);
      s.deformation = slope_mm_per_min * 1e-3 * minute + jitter;
      r.samples.push_back(s);
    }
    vrut::finish_deformation(r, vrut::WheelTracking{});
    return r;
  };
  const double resolution = 2.0 * std::sqrt(2.0) * e * std::sqrt(16.0 / 14.0);  // m
  // Resolved: 0.05 mm/min, 0.75 mm over the window, far above 0.034 mm.
  const auto steep = curve(0.05);
  CHECK(steep.deformation_resolution == Approx(resolution).epsilon(1e-9));
  CHECK_FALSE(steep.dynamic_stability_is_lower_bound);
  CHECK(steep.dynamic_stability == Approx(15.0 * 42.0 / 0.75).epsilon(1e-9));
  // Not resolved: 0.001 mm/min, 0.015 mm, below it: "above 630 / 0.034 mm".
  const auto flat = curve(0.001);
  CHECK(flat.deformation_resolution == Approx(resolution).epsilon(1e-9));
  CHECK(flat.dynamic_stability_is_lower_bound);
  CHECK(flat.dynamic_stability == Approx(15.0 * 42.0 / (resolution * 1e3)).epsilon(1e-9));
  // In an ensemble, one bound of three: the mean is a bound, the median not
  // (the bound sorts last); two of three: the median is one too.
  const auto two_steep = vrut::summarize_rutting({steep, flat, curve(0.04)}, vrut::WheelTracking{});
  CHECK(two_steep.dynamic_stability_lower_bounds == 1);
  CHECK_FALSE(two_steep.dynamic_stability_median_is_lower_bound);
  const auto two_flat = vrut::summarize_rutting({steep, flat, curve(0.0005)}, vrut::WheelTracking{});
  CHECK(two_flat.dynamic_stability_lower_bounds == 2);
  CHECK(two_flat.dynamic_stability_median_is_lower_bound);
}

TEST_CASE("a median is a lower bound where a bound sorts at or below the middle", "[analysis][unit]") {
  // 100, 200, 600 with one of them only a lower bound: the median 200 is
  // only a lower bound if that bound's true value can lift it, which 100's
  // (it may be 1000: median 600) and 200's can and 600's cannot.
  CHECK(vrut::median_is_lower_bound({{600.0, false}, {100.0, true}, {200.0, false}}));
  CHECK(vrut::median_is_lower_bound({{600.0, false}, {100.0, false}, {200.0, true}}));
  CHECK_FALSE(vrut::median_is_lower_bound({{600.0, true}, {100.0, false}, {200.0, false}}));
  // Even: the median (200 + 600) / 2 rises with either middle value or one
  // below them, not with one above.
  CHECK(vrut::median_is_lower_bound({{100.0, true}, {200.0, false}, {600.0, false}, {900.0, false}}));
  CHECK(vrut::median_is_lower_bound({{100.0, false}, {200.0, false}, {600.0, true}, {900.0, false}}));
  CHECK_FALSE(vrut::median_is_lower_bound({{100.0, false}, {200.0, false}, {600.0, false}, {900.0, true}}));
}

// The DS as the standard writes it (analysis/standard_ds.hpp): capped at
// 6000 passes/mm, "> 6000"; and the median of censored values, worked by hand.
TEST_CASE("the standard caps a DS at 6000 and keeps a lower bound a lower bound", "[analysis][unit]") {
  const auto plain = vrut::report_ds(970.0, false);
  CHECK((plain.value == 970.0 && !plain.censored));
  const auto capped = vrut::report_ds(7200.0, false);
  CHECK((capped.value == 6000.0 && capped.censored));
  const auto bound = vrut::report_ds(2100.0, true);  // "above 2100" stays that
  CHECK((bound.value == 2100.0 && bound.censored));
  const auto bound_over = vrut::report_ds(9000.0, true);  // "above 9000" is "> 6000"
  CHECK((bound_over.value == 6000.0 && bound_over.censored));
  const auto flat = vrut::report_ds(std::numeric_limits<double>::infinity(), false);
  CHECK((flat.value == 6000.0 && flat.censored));
  CHECK_THROWS(vrut::report_ds(std::nan(""), false));
}

TEST_CASE("the median of censored DS values is the Kaplan-Meier median", "[analysis][unit]") {
  using R = vrut::ReportedDS;
  auto median = [](std::vector<R> v) { return vrut::censored_median(std::move(v)); };
  // Nothing censored: the ordinary median, odd and even.
  CHECK(median({{900, false}, {500, false}, {700, false}}).value == 700.0);
  const auto even = median({{4, false}, {1, false}, {3, false}, {2, false}});
  CHECK((even.value == 2.5 && !even.censored));
  // Censored above every known value: S falls 0.8, 0.6, 0.4 at 500, 700, 900.
  const auto capped = median({{500, false}, {6000, true}, {700, false}, {6000, true}, {900, false}});
  CHECK((capped.value == 900.0 && !capped.censored));
  // A bound inside: {500, >800, 1000, 1200}. S = 3/4 after 500; >800 leaves
  // two at risk; at 1000 S = 3/4 * 1/2 = 3/8 < 1/2: the median is 1000 (the
  // plain median, taking the bound as a value, would say 900).
  const auto inside = median({{1000, false}, {800, true}, {500, false}, {1200, false}});
  CHECK((inside.value == 1000.0 && !inside.censored));
  // S at exactly 1/2 with only censored values after: {500, 700, >6000, >6000}
  // has its median between 700 and a value of 6000 or more: above 3350.
  const auto half = median({{500, false}, {700, false}, {6000, true}, {6000, true}});
  CHECK((half.value == 3350.0 && half.censored));
  // Most censored: S = 2/3 after 500 and never falls further: above 6000.
  const auto most = median({{500, false}, {6000, true}, {6000, true}});
  CHECK((most.value == 6000.0 && most.censored));
  // A tie of a known and a censored value: the censored one is still at
  // risk at the tie: {600, >600, 700}: S = 2/3 at 600, then 0 at 700.
  const auto tie = median({{600, true}, {600, false}, {700, false}});
  CHECK((tie.value == 700.0 && !tie.censored));
  CHECK_THROWS(median({}));
}

// The distribution-free interval of a median, worked by hand: for n = 16,
// P(Binomial(16, 1/2) <= 3) = (1 + 16 + 120 + 560) / 65536 = 697 / 65536, so
// 2 x that = 0.0213 <= 0.05, while P(<= 4) = 2517 / 65536 gives 0.077: the
// interval is x_(4) to x_(13), coverage 1 - 1394 / 65536. For n = 10:
// P(<= 1) = 11 / 1024, P(<= 2) = 56 / 1024: x_(2) to x_(9), coverage
// 1 - 22 / 1024. For n = 5 the widest, x_(1) to x_(5), covers only
// 1 - 2 / 32 = 0.9375: no 95 % interval.
TEST_CASE("the DS median's interval is the order statistics the binomial law gives", "[analysis][unit]") {
  std::vector<vrut::ReportedDS> sixteen;
  for (int v = 16; v >= 1; --v) sixteen.push_back({100.0 * v, false});  // unsorted on purpose
  auto m = vrut::median_interval(sixteen);
  REQUIRE(m.defined);
  CHECK(m.low.value == 400.0);
  CHECK(m.high.value == 1300.0);
  CHECK_FALSE(m.high.censored);
  CHECK(m.coverage == Approx(1.0 - 1394.0 / 65536.0).epsilon(1e-12));
  // A bound above the high end leaves it a value; one at or below makes it a bound.
  sixteen[0] = {1600.0, true};  // x_(16) only known to lie above 1600
  CHECK_FALSE(vrut::median_interval(sixteen).high.censored);
  sixteen[0] = {1600.0, false};
  sixteen[10] = {600.0, true};  // x = 600 only a lower bound: the 13th could be higher
  m = vrut::median_interval(sixteen);
  CHECK(m.high.value == 1300.0);
  CHECK(m.high.censored);
  CHECK(m.low.value == 400.0);
  std::vector<vrut::ReportedDS> ten;
  for (int v = 1; v <= 10; ++v) ten.push_back({static_cast<double>(v), false});
  m = vrut::median_interval(ten);
  REQUIRE(m.defined);
  CHECK(m.low.value == 2.0);
  CHECK(m.high.value == 9.0);
  CHECK(m.coverage == Approx(1.0 - 22.0 / 1024.0).epsilon(1e-12));
  ten.resize(5);
  CHECK_FALSE(vrut::median_interval(ten).defined);
  ten.push_back({6.0, false});  // six: 2 / 64 = 0.031, x_(1) to x_(6)
  m = vrut::median_interval(ten);
  REQUIRE(m.defined);
  CHECK(m.low.value == 1.0);
  CHECK(m.high.value == 6.0);
  CHECK(m.coverage == Approx(1.0 - 2.0 / 64.0).epsilon(1e-12));
}

// The DS of the mean curve, passes / mean window deformation, and its
// interval through the Student-t interval of that mean, worked by hand:
// deformations 1.0, 1.2, 1.4, 1.6 mm: mean 1.3, sd 0.2581989, t(3, 0.975)
// 3.1824463, half-width 0.4108527; 630 passes give 630 / 1.7108527 =
// 368.24 and 630 / 0.8891473 = 708.54 passes/mm. Deformations 1, 2, 3 mm:
// mean 2, half-width 4.3026527 / sqrt(3) = 2.4841377 > 2, so no upper end
// (the cap, censored) and 630 / 4.4841377 = 140.495 below.
TEST_CASE("the DS of the mean curve has the interval of the mean deformation, inverted", "[analysis][unit]") {
  auto ds = vrut::mean_curve_ds_interval({1.0, 1.2, 1.4, 1.6}, 630.0);
  CHECK(ds.low.value == Approx(630.0 / 1.7108527).epsilon(1e-6));
  CHECK(ds.high.value == Approx(630.0 / 0.8891473).epsilon(1e-6));
  CHECK_FALSE(ds.low.censored);
  CHECK_FALSE(ds.high.censored);
  ds = vrut::mean_curve_ds_interval({1.0, 2.0, 3.0}, 630.0);
  CHECK(ds.low.value == Approx(140.495).epsilon(1e-5));
  CHECK(ds.high.value == vrut::standard_ds_cap);
  CHECK(ds.high.censored);
  // A low end past the cap is capped too.
  ds = vrut::mean_curve_ds_interval({0.01, 0.011}, 630.0);
  CHECK(ds.low.value == vrut::standard_ds_cap);
  CHECK(ds.low.censored);
  CHECK_THROWS(vrut::mean_curve_ds_interval({1.0}, 630.0));
}

TEST_CASE("resampling says how well a median of n specimens is known", "[analysis][unit]") {
  // Drawn plainly: every specimen alike, any resampled median is that value;
  // two values, 500 and 1500, half each: a sample of one gives either, so the
  // central 95 % spans both, a half-width of 500 over the median 1000.
  const std::vector<vrut::ReportedDS> same(10, {800.0, false});
  CHECK(vrut::median_relative_halfwidth(same, 3, 4000, 1, false) == 0.0);
  CHECK(vrut::median_relative_halfwidth(same, 3) == 0.0);  // no spread to smooth either
  std::vector<vrut::ReportedDS> two;
  for (int k = 0; k < 5; ++k) two.push_back({500.0, false}), two.push_back({1500.0, false});
  CHECK(vrut::median_relative_halfwidth(two, 1, 4000, 1, false) == Approx(0.5));
  // Smoothed, against the median of a log-normal population: ln DS of the
  // median of n draws has the standard deviation sqrt(pi / 2) sigma /
  // sqrt(n) for large n, so the 95 % half-width over the median is
  // sinh(1.96 sqrt(pi / 2) sigma / sqrt(n)); sigma 0.5 and n = 16: 0.312.
  // The ensemble: 400 values at the normal quantiles of (i - 0.5) / 400, a
  // log-normal sample without sampling noise. Tolerance 10 %: the asymptotic
  // form at n = 16 and the kernel's widening (h = 1.06 sigma 400^-0.2 =
  // 0.32 sigma, which widens each draw's spread by sqrt(1 + 0.1), 5 %),
  // with 4,000 draws.
  std::vector<vrut::ReportedDS> lognormal;
  for (int i = 1; i <= 400; ++i) {
    const double q = (i - 0.5) / 400.0;
    // The normal quantile by bisection on erfc.
    double lo = -10.0, hi = 10.0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (0.5 * std::erfc(-mid / std::sqrt(2.0)) < q ? lo : hi) = mid;
    }
    lognormal.push_back({1000.0 * std::exp(0.5 * 0.5 * (lo + hi)), false});
  }
  const double expected = std::sinh(1.96 * std::sqrt(M_PI / 2.0) * 0.5 / 4.0);
  CHECK(vrut::median_relative_halfwidth(lognormal, 16) == Approx(expected).epsilon(0.10));
  // A spread ensemble: a median of 16 specimens is known better than one of 4.
  std::vector<vrut::ReportedDS> spread;
  for (int k = 1; k <= 20; ++k) spread.push_back({100.0 * k, false});
  CHECK(vrut::median_relative_halfwidth(spread, 16) < vrut::median_relative_halfwidth(spread, 4));
}
