#pragma once
// Fits the four macro Burger's constants to a creep curve eps(t) under a
// constant stress sigma0:
//   eps / sigma0 = 1/E1 + t/eta1 + (1/E2)(1 - exp(-t/tau)),  tau = eta2/E2.
// For a fixed tau the model is linear in (1/E1, 1/eta1, 1/E2): solved by
// least squares (Eigen); tau is found by a log-spaced scan refined by golden
// section (variable projection). Host-only.
#include <vrut/material/burgers_parameters.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace vrut {

struct BurgersFit {
  BurgersMacro macro;
  double rms_residual = 0.0;  // of the strain
};

namespace detail {
inline double burgers_fit_residual(const std::vector<double>& t, const std::vector<double>& eps, double sigma0,
                                   double tau, Eigen::Vector3d& coef) {
  const Eigen::Index n = static_cast<Eigen::Index>(t.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = t[i];
    a(i, 2) = 1.0 - std::exp(-t[i] / tau);
    b(i) = eps[i] / sigma0;
  }
  coef = a.colPivHouseholderQr().solve(b);
  return (a * coef - b).norm() * sigma0 / std::sqrt(static_cast<double>(n));
}
}  // namespace detail

inline BurgersFit fit_burgers(const std::vector<double>& t, const std::vector<double>& eps, double sigma0) {
  if (t.size() != eps.size() || t.size() < 4) throw std::invalid_argument("fit_burgers needs 4 or more points");
  const double t_max = t.back();
  Eigen::Vector3d coef;
  double best_tau = t_max, best = 1e300;
  for (int k = 0; k <= 80; ++k) {  // tau from t_max/1e4 to 10 t_max
    const double tau = t_max * std::pow(10.0, -4.0 + 5.0 * k / 80.0);
    const double r = detail::burgers_fit_residual(t, eps, sigma0, tau, coef);
    if (r < best) best = r, best_tau = tau;
  }
  double lo = std::log(best_tau) - std::log(10.0) * 5.0 / 80.0, hi = std::log(best_tau) + std::log(10.0) * 5.0 / 80.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 100; ++it) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (detail::burgers_fit_residual(t, eps, sigma0, std::exp(a), coef) <
        detail::burgers_fit_residual(t, eps, sigma0, std::exp(b), coef))
      hi = b;
    else
      lo = a;
  }
  const double tau = std::exp(0.5 * (lo + hi));
  BurgersFit fit;
  fit.rms_residual = detail::burgers_fit_residual(t, eps, sigma0, tau, coef);
  fit.macro.E1 = 1.0 / coef(0);
  fit.macro.eta1 = 1.0 / coef(1);
  fit.macro.E2 = 1.0 / coef(2);
  fit.macro.eta2 = tau * fit.macro.E2;
  return fit;
}

}  // namespace vrut
