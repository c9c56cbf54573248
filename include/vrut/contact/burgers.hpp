#pragma once
/// \file
/// Burger's viscoelastic contact: a Maxwell element (spring K_m, dashpot C_m)
/// in series with a Kelvin element (spring K_k, dashpot C_k), in the normal and
/// in the shear direction. Slots for vrut::Composite (composite.hpp).
///
/// Time-discrete update: the trapezoidal rule (Crank-Nicolson) applied to each
/// element over one step, the form Itasca PFC documents for its "burger"
/// model. With f the force, u the contact displacement and u_k the Kelvin
/// displacement:
///   Kelvin:   (f' + f)/2 = K_k (u_k' + u_k)/2 + C_k (u_k' - u_k)/dt
///   dashpot:  du_md = dt (f' + f) / (2 C_m)
///   spring:   du_ms = (f' - f) / K_m
///   du = du_ms + du_md + (u_k' - u_k)
/// which solve to
///   A = 1 + K_k dt/(2 C_k),  B = 1 - K_k dt/(2 C_k)
///   C = dt/(2 C_k A) - 1/K_m + dt/(2 C_m),  D = dt/(2 C_k A) + 1/K_m + dt/(2 C_m)
///   f'   = (du + (1 - B/A) u_k - C f) / D
///   u_k' = (B u_k + dt/(2 C_k) (f' + f)) / A
/// The rule is A-stable and second order, and exact for the elastic jump
/// (dt -> 0 gives f' - f = K_m du). Its instantaneous stiffness 1/D is below
/// K_m, so K_m bounds it for the critical time step. tests/test_burgers.cpp
/// checks it against the exact creep and relaxation solutions.
///
/// The element is linear, so in 3D it acts on the shear vector as a whole:
/// the same update with vectors for f, u and u_k (BurgersShearIn<Dim3>).
#include <vrut/contact/geometry.hpp>
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

struct BurgersElement {
  double maxwell_stiffness = 0.0;  // K_m, N/m
  double maxwell_viscosity = 0.0;  // C_m, N s/m
  double kelvin_stiffness = 0.0;   // K_k, N/m
  double kelvin_viscosity = 0.0;   // C_k, N s/m
  /// The update's coefficients for one time step (burgers_prepare): they
  /// depend on the parameters and dt only, and working them out per contact
  /// and step cost five divisions each time. prepared_dt = 0: not prepared.
  double prepared_dt = 0.0;
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0, kelvin_release = 0.0 /* 1 - b/a */, half_dt_kelvin = 0.0;
};

/// The history of an element: scalars, or in 3D shear vectors.
template <class Value>
struct BurgersHistoryOf {
  Value force{};   // f at the end of the last step
  Value kelvin{};  // u_k
};
using BurgersHistory = BurgersHistoryOf<double>;

namespace detail {
template <class T> struct same_type { using type = T; };  // keeps du out of Value's deduction
}  // namespace detail

/// The coefficients of burgers_step for time step dt, the same operations in
/// the same order, so a prepared element gives the same bits as one that is not.
KOKKOS_INLINE_FUNCTION void burgers_prepare(BurgersElement& e, double dt) {
  e.a = 1.0 + e.kelvin_stiffness * dt / (2.0 * e.kelvin_viscosity);
  e.b = 1.0 - e.kelvin_stiffness * dt / (2.0 * e.kelvin_viscosity);
  const double common = dt / (2.0 * e.kelvin_viscosity * e.a) + dt / (2.0 * e.maxwell_viscosity);
  e.c = common - 1.0 / e.maxwell_stiffness;
  e.d = common + 1.0 / e.maxwell_stiffness;
  e.kelvin_release = 1.0 - e.b / e.a;
  e.half_dt_kelvin = dt / (2.0 * e.kelvin_viscosity);
  e.prepared_dt = dt;
}

/// One trapezoidal step of a Burger's element: displacement increment du
/// (positive loads it), returns the new force.
template <class Value>
KOKKOS_INLINE_FUNCTION Value burgers_step(const BurgersElement& e, BurgersHistoryOf<Value>& h,
                                          typename detail::same_type<Value>::type du, double dt) {
  BurgersElement k = e;
  if (e.prepared_dt != dt) burgers_prepare(k, dt);
  const Value f = (du + k.kelvin_release * h.kelvin - k.c * h.force) / k.d;
  h.kelvin = (k.b * h.kelvin + k.half_dt_kelvin * (f + h.force)) / k.a;
  h.force = f;
  return f;
}

/// Normal slot: u is the overlap (compression positive).
struct BurgersNormal {
  using params_type = BurgersElement;
  using state_type = BurgersHistory;
  template <class Geometry>
  KOKKOS_INLINE_FUNCTION static double force(const params_type& p, state_type& s, const Geometry& g) {
    return burgers_step(p, s, g.normal_increment, g.dt);
  }
  static void prepare(params_type& p, double dt) { burgers_prepare(p, dt); }
  /// Without a bond a contact cannot pull: the stored force restarts from zero.
  KOKKOS_INLINE_FUNCTION static void cut_tension(const params_type&, state_type& s) {
    if (s.force < 0.0) s.force = 0.0;
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.maxwell_stiffness; }
};

/// Shear slot: u is minus the slip of the second body, so the force (on the
/// second body, in the tangent) resists the slip, as the linear spring does.
template <class D>
struct BurgersShearIn {
  using dimension = D;
  using params_type = BurgersElement;
  using shear_type = typename D::shear;
  using state_type = BurgersHistoryOf<shear_type>;
  KOKKOS_INLINE_FUNCTION static shear_type force(const params_type& p, state_type& s, const ContactGeometryIn<D>& g) {
    return burgers_step(p, s, -g.shear_increment, g.dt);
  }
  static void prepare(params_type& p, double dt) { burgers_prepare(p, dt); }
  /// Coulomb cap: the stored force slides back to the limit; the Kelvin
  /// element keeps its displacement.
  KOKKOS_INLINE_FUNCTION static shear_type limit(const params_type&, state_type& s, double max_abs) {
    return s.force = cap_magnitude(s.force, max_abs);
  }
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) {
    s.force = turn(s.force);
    s.kelvin = turn(s.kelvin);
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.maxwell_stiffness; }
};
using BurgersShear = BurgersShearIn<Dim2>;

}  // namespace vrut
