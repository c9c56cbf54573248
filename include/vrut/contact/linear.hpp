#pragma once
/// \file
/// Linear springs: the normal and shear slots of a composed law (see composite.hpp).
#include <vrut/contact/geometry.hpp>
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

/// Normal force proportional to the total overlap: F_n = k_n * overlap.
/// With a bond holding, a negative overlap gives tension.
struct LinearNormal {
  struct params_type { double stiffness = 0.0; };  // k_n, N/m
  struct state_type {};
  template <class Geometry>
  KOKKOS_INLINE_FUNCTION static double force(const params_type& p, state_type&, const Geometry& g) {
    return p.stiffness * g.overlap;
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.stiffness; }
};

/// A linear spring with a viscous dashpot beside it, set as a fraction of the
/// critical damping of the pair: F_n = k_n overlap + c d(overlap)/dt, with
/// c = 2 zeta sqrt(k_n m*), m* = m_1 m_2 / (m_1 + m_2) (m_2 against a wall).
/// Rigid stones ring undamped on a plain spring; real stone rings down. With
/// zeta = 0 it is LinearNormal, bit for bit.
struct DampedLinearNormal {
  struct params_type {
    double stiffness = 0.0;      // k_n, N/m
    double damping_ratio = 0.0;  // zeta, of critical
  };
  struct state_type {};
  static constexpr bool uses_mass = true;
  template <class Geometry>
  KOKKOS_INLINE_FUNCTION static double force(const params_type& p, state_type&, const Geometry& g) {
    double f = p.stiffness * g.overlap;
    if (p.damping_ratio > 0.0) {
      const double m = g.mass_1 > 0.0 ? g.mass_1 * g.mass_2 / (g.mass_1 + g.mass_2) : g.mass_2;
      f += 2.0 * p.damping_ratio * sqrt(p.stiffness * m) * g.normal_increment / g.dt;
    }
    return f;
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.stiffness; }
};

/// Incremental shear spring: dF_s = -k_s * (tangential slip during the step),
/// a scalar along the tangent in 2D, a vector in the tangent plane in 3D.
struct LinearShearParams { double stiffness = 0.0; };  // k_s, N/m

template <class D>
struct LinearShearIn {
  using dimension = D;
  using params_type = LinearShearParams;
  using shear_type = typename D::shear;
  struct state_type { shear_type force{}; };
  KOKKOS_INLINE_FUNCTION static shear_type force(const params_type& p, state_type& s, const ContactGeometryIn<D>& g) {
    s.force -= p.stiffness * g.shear_increment;
    return s.force;
  }
  /// Coulomb cap: the stored force slides back to the limit, so unloading starts from there.
  KOKKOS_INLINE_FUNCTION static shear_type limit(const params_type&, state_type& s, double max_abs) {
    return s.force = cap_magnitude(s.force, max_abs);
  }
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) { s.force = turn(s.force); }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.stiffness; }
};
using LinearShear = LinearShearIn<Dim2>;

}  // namespace vrut
