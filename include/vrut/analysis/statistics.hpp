#pragma once
// Descriptive statistics of an ensemble's results: mean, standard deviation,
// the Student-t confidence interval of the mean, and the median (robust where
// a few specimens give extreme values, as the DS does); and, for a positive
// quantity that spreads by factors (the DS), the geometric mean with an
// interval that stays positive. Host-only.
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace vrut {

struct SampleStatistics {
  int n = 0;
  double mean = 0.0, sd = 0.0;                 // sd with n - 1
  double ci_low = 0.0, ci_high = 0.0;          // of the mean, at `confidence`
  double median = 0.0, min = 0.0, max = 0.0;
  double confidence = 0.95;
};

// Statistics of the values; with one value the spread and interval are NaN.
// An infinite value (a DS whose deformation did not grow) makes the mean and
// interval infinite or NaN, while the median stays meaningful.
inline SampleStatistics describe(std::vector<double> values, double confidence = 0.95) {
  if (values.empty()) throw std::invalid_argument("statistics of no values");
  if (!(confidence > 0.0 && confidence < 1.0)) throw std::invalid_argument("confidence must lie in (0, 1)");
  SampleStatistics s;
  s.n = static_cast<int>(values.size());
  s.confidence = confidence;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / s.n;
  std::sort(values.begin(), values.end());
  s.min = values.front();
  s.max = values.back();
  s.median = s.n % 2 ? values[s.n / 2] : 0.5 * (values[s.n / 2 - 1] + values[s.n / 2]);
  if (s.n < 2) {
    s.sd = s.ci_low = s.ci_high = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(squares / (s.n - 1));
  const boost::math::students_t t(s.n - 1);
  const double half = boost::math::quantile(t, 0.5 + 0.5 * confidence) * s.sd / std::sqrt(static_cast<double>(s.n));
  s.ci_low = s.mean - half;
  s.ci_high = s.mean + half;
  return s;
}

// The geometric mean of positive values, exp(mean(ln x)), and its interval:
// the Student-t interval of the logarithms' mean, mapped back,
// exp(mean(ln x) -+ t s / sqrt(n)) with s the logarithms' sd. The DS is
// positive and spreads by factors (it is passes / deformation), so the
// arithmetic mean's interval, symmetric about the mean, can reach below zero
// (2#, seeds 1-10: -349 to 3607); this one cannot. With one value the
// interval is NaN; with a value that is not positive (or NaN: a run stopped
// early) all is NaN; an infinite value gives an infinite mean, NaN interval.
struct GeometricStatistics {
  int n = 0;
  double mean = 0.0;                   // the geometric mean
  double ci_low = 0.0, ci_high = 0.0;  // of it, at `confidence`
  double confidence = 0.95;
};

inline GeometricStatistics describe_geometric(const std::vector<double>& values, double confidence = 0.95) {
  if (values.empty()) throw std::invalid_argument("statistics of no values");
  std::vector<double> logs;
  for (double v : values) logs.push_back(v > 0.0 ? std::log(v) : std::numeric_limits<double>::quiet_NaN());
  const SampleStatistics s = describe(logs, confidence);
  return {s.n, std::exp(s.mean), std::exp(s.ci_low), std::exp(s.ci_high), confidence};
}

}  // namespace vrut
