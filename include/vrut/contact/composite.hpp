#pragma once
/// \file
/// A contact law composed of a normal slot, a shear slot and a bond slot,
/// evaluated in that order; the composition is itself a contact law.
///
/// Normal slot: params_type, state_type,
///   double force(const params_type&, state_type&, const ContactGeometry&), double stiffness(params).
/// Shear slot: the same with the shear value of its dimension (double in 2D,
///   Vec3 in 3D; data/dimension.hpp) in place of the double, plus
///   limit(const params_type&, state_type&, double max_abs), which caps the
///   stored shear force's magnitude (the Coulomb slider). A shear slot that is
///   a template on its dimension (LinearShearIn<D>) gives the law both forms:
///   Composite<N, LinearShearIn<Dim2>, B> in 3D is Composite<N, LinearShearIn<Dim3>, B>,
///   with the same params_type.
/// Bond slot: see bond.hpp.
/// A normal slot with history may also provide
///   void cut_tension(const params_type&, state_type&),
/// called when an unbonded contact would pull, to drop the stored tension.
///
/// While a bond holds, tension and any shear below the bond strength are carried.
/// Without a bond (or once it breaks) tension is cut to zero and the shear force
/// to friction * normal force.
#include <vrut/contact/bond.hpp>
#include <vrut/contact/burgers.hpp>
#include <vrut/contact/concept.hpp>
#include <vrut/contact/geometry.hpp>
#include <vrut/contact/linear.hpp>

#include <Kokkos_Core.hpp>

#include <type_traits>
#include <utility>

namespace vrut {
namespace detail {
template <class, class = void> struct has_cut_tension : std::false_type {};
template <class N>
struct has_cut_tension<N, std::void_t<decltype(N::cut_tension(std::declval<const typename N::params_type&>(),
                                                               std::declval<typename N::state_type&>()))>>
    : std::true_type {};
}  // namespace detail

/// A composed law's parameters, the same type in 2D and 3D.
template <class NormalParams, class ShearParams, class BondParams>
struct CompositeParams {
  NormalParams normal;
  ShearParams shear;
  BondParams bond;
  double friction = 0.0;  // Coulomb coefficient, used where no bond holds
};

template <class Normal, class Shear, class Bond = NoBond>
struct Composite {
  using normal_slot = Normal;
  using shear_slot = Shear;
  using bond_slot = Bond;
  using dimension = law_dimension_t<Shear>;
  using shear_type = typename dimension::shear;
  static constexpr bool uses_mass = law_uses_mass<Normal>() || law_uses_mass<Shear>();

  using params_type =
      CompositeParams<typename Normal::params_type, typename Shear::params_type, typename Bond::params_type>;
  struct state_type {
    typename Normal::state_type normal;
    typename Shear::state_type shear;
    typename Bond::state_type bond;
  };

  KOKKOS_INLINE_FUNCTION static ContactForceIn<dimension> force(const params_type& p, state_type& s,
                                                                const ContactGeometryIn<dimension>& g) {
    double fn = Normal::force(p.normal, s.normal, g);
    shear_type fs = Shear::force(p.shear, s.shear, g);
    if (Bond::intact(s.bond)) {
      if (Bond::holds(p.bond, fn, fs)) return {fn, fs};
      Bond::release(s.bond);
    }
    if (fn < 0.0) {
      fn = 0.0;
      if constexpr (detail::has_cut_tension<Normal>::value) Normal::cut_tension(p.normal, s.normal);
    }
    fs = Shear::limit(p.shear, s.shear, p.friction * fn);
    return {fn, fs};
  }

  static void prepare(params_type& p, double dt) {
    prepare_law<Normal>(p.normal, dt);
    prepare_law<Shear>(p.shear, dt);
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) {
    const double kn = Normal::stiffness(p.normal), ks = Shear::stiffness(p.shear);
    return kn > ks ? kn : ks;
  }
  KOKKOS_INLINE_FUNCTION static bool bonded(const state_type& s) { return Bond::intact(s.bond); }
  KOKKOS_INLINE_FUNCTION static void bond(state_type& s) { Bond::bond(s.bond); }
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) {
    turn_history<Normal>(s.normal, turn);
    turn_history<Shear>(s.shear, turn);
  }
};

template <class Normal, class Shear, class Bond, class D>
struct in_dimension<Composite<Normal, Shear, Bond>, D> {
  using type = Composite<in_dimension_t<Normal, D>, in_dimension_t<Shear, D>, Bond>;
};

/// The two laws of the core, and helpers that spell their parameters.
using Linear = Composite<LinearNormal, LinearShear, NoBond>;
using LinearBonded = Composite<LinearNormal, LinearShear, ContactBond>;
using Burgers = Composite<BurgersNormal, BurgersShear, NoBond>;
using BurgersBonded = Composite<BurgersNormal, BurgersShear, ContactBond>;
/// Stone on stone and stone on wall with rigid stones: damped (linear.hpp).
using DampedLinear = Composite<DampedLinearNormal, LinearShear, NoBond>;
using DampedLinearBonded = Composite<DampedLinearNormal, LinearShear, ContactBond>;

inline Linear::params_type linear_params(double kn, double ks, double friction) {
  Linear::params_type p;
  p.normal.stiffness = kn;
  p.shear.stiffness = ks;
  p.friction = friction;
  return p;
}

inline DampedLinear::params_type damped_linear_params(double kn, double ks, double friction, double damping_ratio) {
  DampedLinear::params_type p;
  p.normal.stiffness = kn;
  p.normal.damping_ratio = damping_ratio;
  p.shear.stiffness = ks;
  p.friction = friction;
  return p;
}

inline LinearBonded::params_type linear_bonded_params(double kn, double ks, double friction,
                                                      double normal_strength, double shear_strength) {
  LinearBonded::params_type p;
  p.normal.stiffness = kn;
  p.shear.stiffness = ks;
  p.friction = friction;
  p.bond.normal_strength = normal_strength;
  p.bond.shear_strength = shear_strength;
  return p;
}

}  // namespace vrut
