#pragma once
// Descriptive statistics of an ensemble's results: mean, standard deviation,
// the Student-t confidence interval of the mean, and the median (robust where
// a few specimens give extreme values, as the DS does). Host-only.
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

}  // namespace vrut
