#pragma once
// The dynamic stability as the wheel-tracking standard reports it, and the
// statistics of an ensemble whose DS values are partly censored. Host-only.
//
// JTG E20 T0719 computes DS = (t2 - t1) N C1 C2 / (d2 - d1) with t1 = 45 and
// t2 = 60 min, N = 42 passes a minute, C1 = 1.0 for a crank-driven wheel and
// C2 = 1.0 for a 300 mm laboratory slab (the values the rutting protocol
// uses), and writes a DS above 6000 passes/mm as "> 6000". So a reported DS
// is either a value or a lower bound: the cap, or (ours) the DS of the
// smallest deformation change the curve resolves (RuttingResult). A lower
// bound is a right-censored value: the true DS lies at or above it.
//
// The median of censored values is the Kaplan-Meier median: the survival
// curve S(t) (the share of DS values above t) falls at each known value by
// its share of the values still at risk, and a censored value leaves the risk
// set without a fall. The median is where S first falls to 0.5 or below;
// where S sits at exactly 0.5, the midpoint to the next known value, so that
// with nothing censored it is the ordinary median. Where S never falls to 0.5
// the median is itself censored: above the largest value at risk.
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

// One DS as reported: `value`, and whether the DS is only known to lie at or above it.
struct ReportedDS {
  double value = 0.0;
  bool censored = false;
};

// The standard's cap (passes/mm).
inline constexpr double standard_ds_cap = 6000.0;

// A computed DS (passes/mm; `lower_bound`: only a lower bound already) as
// the standard reports it: capped at `cap`. A DS that did not grow at all is
// infinite and reports as the cap.
inline ReportedDS report_ds(double ds, bool lower_bound, double cap = standard_ds_cap) {
  if (std::isnan(ds)) throw std::invalid_argument("a DS that was not computed cannot be reported");
  if (ds > cap) return {cap, true};
  return {ds, lower_bound};
}

// The Kaplan-Meier median of right-censored values (see above).
inline ReportedDS censored_median(std::vector<ReportedDS> values) {
  if (values.empty()) throw std::invalid_argument("the median of no values");
  // Known values before censored ones at a tie: a censored value equal to a
  // known one is still at risk when the known one falls (the usual rule).
  std::sort(values.begin(), values.end(), [](const ReportedDS& a, const ReportedDS& b) {
    return a.value < b.value || (a.value == b.value && !a.censored && b.censored);
  });
  const std::size_t n = values.size();
  double survival = 1.0;
  for (std::size_t i = 0; i < n;) {
    // The known values tied at this one fall together.
    std::size_t j = i, known = 0;
    while (j < n && values[j].value == values[i].value && !values[j].censored) ++j, ++known;
    if (known > 0) {
      const double at_risk = static_cast<double>(n - i);
      survival *= 1.0 - known / at_risk;
      constexpr double tie = 1e-12;  // S is a product of ratios: exactly 0.5 up to rounding
      if (survival < 0.5 - tie) return {values[i].value, false};
      if (survival <= 0.5 + tie) {
        // On the plateau at 0.5: the midpoint to the next known value.
        // (Where the next value is censored, every value after lies at or
        // above it, so the midpoint to it is a lower bound.)
        if (j < n) return {0.5 * (values[i].value + values[j].value), values[j].censored};
        return {values[i].value, false};  // unreachable: S is 0 after the last known value
      }
      i = j;
    } else {
      ++i;  // a censored value leaves the risk set
    }
  }
  // S never reached 0.5: the median lies above the largest value at risk.
  double largest = 0.0;
  for (const auto& v : values) largest = std::max(largest, v.value);
  return {largest, true};
}

// A confidence interval for the ensemble's DS median that assumes no
// distribution: the order statistics x_(k) and x_(n+1-k) of the n values,
// with k the largest for which the chance that the median lies outside,
// 2 P(Binomial(n, 1/2) <= k - 1), is at most 1 - confidence; `coverage` is
// then the interval's own (at least `confidence`). A censored value is a
// lower bound on its true value, so the true order statistics lie at or
// above the reported ones: the low end stays valid, and the high end is only
// a lower bound ("above") where a censored value lies at or below it.
// `defined` is false when n is too small for the confidence (n < 6 at 95 %).
struct MedianInterval {
  ReportedDS low, high;
  double coverage = 0.0;
  bool defined = false;
};

inline MedianInterval median_interval(std::vector<ReportedDS> values, double confidence = 0.95) {
  if (values.empty()) throw std::invalid_argument("the median of no values");
  if (!(confidence > 0.0 && confidence < 1.0)) throw std::invalid_argument("confidence must lie in (0, 1)");
  std::sort(values.begin(), values.end(), [](const ReportedDS& a, const ReportedDS& b) {
    return a.value < b.value || (a.value == b.value && !a.censored && b.censored);
  });
  const std::size_t n = values.size();
  const boost::math::binomial_distribution<double> ranks(static_cast<double>(n), 0.5);
  // The largest k whose chance of missing the median is within 1 - confidence.
  std::size_t k = 0;
  while (2 * (k + 1) <= n + 1 && 2.0 * boost::math::cdf(ranks, static_cast<double>(k)) <= 1.0 - confidence) ++k;
  MedianInterval m;
  if (k == 0) return m;
  m.defined = true;
  m.coverage = 1.0 - 2.0 * boost::math::cdf(ranks, static_cast<double>(k - 1));
  m.low = {values[k - 1].value, false};
  m.high = {values[n - k].value, false};
  for (std::size_t i = 0; i <= n - k; ++i) m.high.censored = m.high.censored || values[i].censored;
  return m;
}

// A DS as text the way the standard writes it: "> 6000" past the cap, and
// (ours) "above N" for a DS the curve does not resolve.
inline std::string reported_ds_text(const ReportedDS& d) {
  char text[64];
  std::snprintf(text, sizeof text, "%s%.0f", d.censored ? (d.value >= standard_ds_cap ? "> " : "above ") : "",
                d.value);
  return text;
}

// A confidence interval for the DS of an ensemble's mean curve. That DS is
// passes / (mean of the specimens' deformation over the window), since the
// mean curve's deformation at minutes 45 and 60 is the mean of theirs; the
// Student-t interval of that mean, mapped through passes / x (decreasing),
// is the DS's interval. Where the interval of the deformation reaches zero,
// the DS has no upper end: reported at the cap, censored. Both ends are
// reported as the standard would (capped). `window_deformation` in mm gives
// passes/mm.
struct DSInterval {
  ReportedDS low, high;
};

inline DSInterval mean_curve_ds_interval(const std::vector<double>& window_deformation, double passes,
                                         double confidence = 0.95) {
  const std::size_t n = window_deformation.size();
  if (n < 2) throw std::invalid_argument("an interval needs at least two specimens");
  if (!(confidence > 0.0 && confidence < 1.0)) throw std::invalid_argument("confidence must lie in (0, 1)");
  double sum = 0.0;
  for (double d : window_deformation) sum += d;
  const double mean = sum / n;
  double squares = 0.0;
  for (double d : window_deformation) squares += (d - mean) * (d - mean);
  const boost::math::students_t t(static_cast<double>(n - 1));
  const double half = boost::math::quantile(t, 0.5 + 0.5 * confidence) * std::sqrt(squares / (n - 1) / n);
  DSInterval ds;
  ds.low = report_ds(mean + half > 0.0 ? passes / (mean + half) : std::numeric_limits<double>::infinity(), false);
  ds.high = report_ds(mean - half > 0.0 ? passes / (mean - half) : std::numeric_limits<double>::infinity(), false);
  return ds;
}

// How well a median of n specimens is known, by resampling an ensemble: the
// half-width of the central 95 % of the medians of `draws` samples of n
// specimens, over the whole ensemble's median.
//
// Drawn plainly (with replacement), a median of many draws can only land on
// one of the ensemble's few middle values, so its spread stops shrinking at
// their gap. So by default the draws are smoothed (the smoothed bootstrap):
// each known value drawn is multiplied by exp(h Z), Z standard normal, h
// Silverman's bandwidth 1.06 s N^(-1/5) of the logarithms of the known values
// (s their standard deviation, N their count): the DS is positive and
// spreads by factors; one smoothed past the cap is reported at the cap, as
// the standard would. A censored value is drawn as it is: a bound, not a value.
inline double median_relative_halfwidth(const std::vector<ReportedDS>& ensemble, int n, int draws = 4000,
                                        std::uint64_t seed = 1, bool smoothed = true) {
  if (ensemble.empty() || n < 1 || draws < 40) throw std::invalid_argument("resampling needs values, n >= 1, draws >= 40");
  const double centre = censored_median(ensemble).value;
  double h = 0.0;
  if (smoothed) {
    // The variance of the logarithms about the first one's (shifted data:
    // exactly 0 where all values are equal).
    double first = 0.0, sum = 0.0, squares = 0.0, known = 0.0;
    for (const auto& v : ensemble) {
      if (v.censored) continue;
      if (known == 0.0) first = std::log(v.value);
      const double x = std::log(v.value) - first;
      sum += x, squares += x * x, known += 1.0;
    }
    if (known >= 2.0) h = 1.06 * std::sqrt(std::max(0.0, (squares - sum * sum / known) / (known - 1.0))) * std::pow(known, -0.2);
  }
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, ensemble.size() - 1);
  std::normal_distribution<double> z(0.0, 1.0);
  std::vector<double> medians;
  std::vector<ReportedDS> sample(static_cast<std::size_t>(n));
  for (int d = 0; d < draws; ++d) {
    for (auto& s : sample) {
      s = ensemble[pick(rng)];
      if (!s.censored && h > 0.0) s = report_ds(s.value * std::exp(h * z(rng)), false);  // capped as reported
    }
    medians.push_back(censored_median(sample).value);
  }
  std::sort(medians.begin(), medians.end());
  const double low = medians[static_cast<std::size_t>(0.025 * (draws - 1))];
  const double high = medians[static_cast<std::size_t>(std::ceil(0.975 * (draws - 1)))];
  return 0.5 * (high - low) / centre;
}

}  // namespace vrut
