#pragma once
// From macroscopic material constants to contact (micro) parameters,
// docs/method.md section 6. Host-only.
//
// Burger's mastic (macro E1, eta1 Maxwell; E2, eta2 Kelvin; disk width t;
// Poisson's ratio nu of the mastic):
//   K_mn = E1 t     C_mn = eta1 t     K_kn = E2 t     C_kn = eta2 t
//   K_ms = K_mn / (2(1+nu)) and likewise C_ms, K_ks, C_ks
// Aggregate (linear elastic, modulus E): k_n = 2 t E, k_s = k_n / (2(1+nu)).
// Source: the 2D DEM virtual rutting test with a Burger's contact model
// (restated in docs/method.md), following the PFC2D convention of a disk-disk
// contact of width t.
//
// The rules are "seed" rules: a hex packing built on them does not creep like
// the macro model (docs/burgers.md). MicroConversion scales the four micro
// parameters to correct that.
#include <vrut/contact/burgers.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/material/time_temperature.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vrut {

// Macro Burger's constants, Pa and Pa s. Defaults: asphalt mastic at 60 C
// from dynamic shear tests (docs/method.md section 6).
struct BurgersMacro {
  double E1 = 4.64e6, eta1 = 83.34e6, E2 = 0.82e6, eta2 = 10.0e6;

  void validate() const {
    auto positive = [](double v, const char* name) {
      if (!(v > 0.0) || !std::isfinite(v))
        throw std::invalid_argument(std::string("Burger's parameter ") + name + " must be positive and finite, got " +
                                    std::to_string(v));
    };
    positive(E1, "E1");
    positive(eta1, "eta1");
    positive(E2, "E2");
    positive(eta2, "eta2");
  }
  BurgersMacro shifted(const TimeShift& shift) const {
    return {E1, shift.reduced_viscosity(eta1), E2, shift.reduced_viscosity(eta2)};
  }
  // Creep strain under constant stress sigma0 from t = 0.
  double creep_strain(double sigma0, double t) const {
    return sigma0 * (1.0 / E1 + t / eta1 + (1.0 - std::exp(-E2 * t / eta2)) / E2);
  }
};

inline void validate_poisson(double nu) {
  if (!(nu >= 0.0 && nu < 0.5))
    throw std::invalid_argument("Poisson's ratio must lie in [0, 0.5), got " + std::to_string(nu));
}

// Factors on the four micro parameters (both directions alike).
struct MicroConversion {
  double maxwell_stiffness = 1.0, maxwell_viscosity = 1.0, kelvin_stiffness = 1.0, kelvin_viscosity = 1.0;

  // The method's rules unchanged.
  static MicroConversion seed() { return {}; }

  // Makes a hex packing creep like the macro model. A hexagonal lattice of
  // normal springs k and shear springs beta k (beta = 1/(2(1+nu))) has the
  // plane-stress modulus E = c k / t with c = 2 sqrt(3)(1+beta)/(3+beta)
  // (docs/core.md); by the correspondence principle every Burger's constant
  // of the lattice is c times its contact value over t, so each micro
  // parameter is divided by c, and multiplied by the finite-size factor below.
  static MicroConversion calibrated(double nu) {
    validate_poisson(nu);
    const double beta = 1.0 / (2.0 * (1.0 + nu));
    const double c = 2.0 * std::sqrt(3.0) * (1.0 + beta) / (3.0 + beta);
    const double f = finite_size_factor / c;
    return {f, f, f, f};
  }
  // 3D: makes spheres of diameter d on a face-centred cubic packing creep
  // like the macro model along a cube axis, when the micro parameters are
  // the macro constants times d (pass d where the 2D rules take the disk
  // width t). Normal springs k and shear springs beta k between the twelve
  // neighbours give the cubic constants C11 = sqrt(2)(1+beta) k / d,
  // C12 = (1-beta) k / (sqrt(2) d), C44 = (1+beta) k / (sqrt(2) d), so a
  // uniaxial stress along a cube axis meets the modulus
  //   E = (C11 - C12)(C11 + 2 C12)/(C11 + C12) = c k / d,
  //   c = 2 sqrt(2) (1 + 3 beta)/(3 + beta)
  // (docs/burgers.md, "The FCC lattice"); each micro parameter is divided
  // by c, as in 2D. Lattice theory alone: no finite-size factor is measured
  // for 3D yet.
  static MicroConversion fcc_lattice(double nu) {
    validate_poisson(nu);
    const double beta = 1.0 / (2.0 * (1.0 + nu));
    const double f = 1.0 / fcc_lattice_modulus_factor(beta);
    return {f, f, f, f};
  }
  // c above: the FCC lattice's modulus along a cube axis, E = c k / d.
  static double fcc_lattice_modulus_factor(double beta) {
    return 2.0 * std::sqrt(2.0) * (1.0 + 3.0 * beta) / (3.0 + beta);
  }
  // The free sides of a finite block make it softer than the infinite
  // lattice. Measured with vrut-creep on its default 20 x 10 block at
  // alpha_T = 1e2 (quasi-static): apparent eta1 = 0.957 of the lattice value
  // (docs/burgers.md). By the correspondence principle one factor serves all
  // four parameters.
  static constexpr double finite_size_factor = 1.0 / 0.957;
};

// Burger's element of one direction from the macro constants.
inline BurgersElement burgers_element(const BurgersMacro& macro, double thickness, double direction_factor,
                                      const MicroConversion& conv) {
  macro.validate();
  if (!(thickness > 0.0)) throw std::invalid_argument("disk thickness must be positive");
  BurgersElement e;
  e.maxwell_stiffness = macro.E1 * thickness * direction_factor * conv.maxwell_stiffness;
  e.maxwell_viscosity = macro.eta1 * thickness * direction_factor * conv.maxwell_viscosity;
  e.kelvin_stiffness = macro.E2 * thickness * direction_factor * conv.kelvin_stiffness;
  e.kelvin_viscosity = macro.eta2 * thickness * direction_factor * conv.kelvin_viscosity;
  return e;
}

struct BondStrength {
  double normal = 1e30, shear = 1e30;  // N; the method's bonds never break
};

// Mastic-mastic contact: Burger's in both directions, a contact bond, and
// friction for when no bond holds. `factor` multiplies every micro parameter:
// 1 for mastic-mastic; for mastic-aggregate the method keeps 1 by default, and
// 2 is the reading of two Burger's disks in series with one side rigid.
inline BurgersBonded::params_type mastic_params(const BurgersMacro& macro, double thickness, double nu,
                                                const MicroConversion& conv = MicroConversion::seed(),
                                                double factor = 1.0, double friction = 0.5,
                                                const BondStrength& bond = {}) {
  validate_poisson(nu);
  if (!(factor > 0.0)) throw std::invalid_argument("the mastic-aggregate factor must be positive");
  BurgersBonded::params_type p;
  p.normal = burgers_element(macro, thickness, factor, conv);
  p.shear = burgers_element(macro, thickness, factor / (2.0 * (1.0 + nu)), conv);
  p.bond.normal_strength = bond.normal;
  p.bond.shear_strength = bond.shear;
  p.friction = friction;
  return p;
}

// Aggregate contact (linear elastic): k_n = 2 t E, k_s = k_n / (2(1+nu)).
inline LinearBonded::params_type aggregate_params(double modulus, double thickness, double nu, double friction = 0.5,
                                                  const BondStrength& bond = {}) {
  validate_poisson(nu);
  if (!(modulus > 0.0) || !std::isfinite(modulus))
    throw std::invalid_argument("aggregate modulus must be positive and finite");
  if (!(thickness > 0.0)) throw std::invalid_argument("disk thickness must be positive");
  const double kn = 2.0 * thickness * modulus;
  return linear_bonded_params(kn, kn / (2.0 * (1.0 + nu)), friction, bond.normal, bond.shear);
}

}  // namespace vrut
