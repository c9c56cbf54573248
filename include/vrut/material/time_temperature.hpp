#pragma once
// Time-temperature superposition (docs/method.md section 6): with a shift factor
// alpha_T, viscosities and loading time are divided by alpha_T while the
// stiffnesses stay. A linear viscoelastic model run at reduced time then
// gives the same deformation as the unshifted one at real time; what changes
// is the inertia, which is why the claim "shift factors up to 1e4 change
// nothing" must be checked on the full model.
#include <cmath>
#include <stdexcept>
#include <string>

namespace vrut {

struct TimeShift {
  double alpha = 1.0;

  explicit TimeShift(double a = 1.0) : alpha(a) {
    if (!(alpha > 0.0) || !std::isfinite(alpha))
      throw std::invalid_argument("shift factor alpha_T must be positive and finite, got " + std::to_string(a));
  }
  double reduced_time(double t) const { return t / alpha; }
  double real_time(double reduced) const { return reduced * alpha; }
  double reduced_viscosity(double eta) const { return eta / alpha; }
};

}  // namespace vrut
