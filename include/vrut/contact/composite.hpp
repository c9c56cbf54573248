#pragma once
// A contact law composed of a normal slot, a shear slot and a bond slot,
// evaluated in that order; the composition is itself a contact law.
//
// Normal slot: params_type, state_type,
//   double force(const params_type&, state_type&, const ContactGeometry&), double stiffness(params).
// Shear slot: the same, plus double limit(const params_type&, state_type&, double max_abs),
//   which caps the stored shear force (the Coulomb slider).
// Bond slot: see bond.hpp.
// A normal slot with history may also provide
//   void cut_tension(const params_type&, state_type&),
// called when an unbonded contact would pull, to drop the stored tension.
//
// While a bond holds, tension and any shear below the bond strength are carried.
// Without a bond (or once it breaks) tension is cut to zero and the shear force
// to friction * normal force.
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

template <class Normal, class Shear, class Bond = NoBond>
struct Composite {
  using normal_slot = Normal;
  using shear_slot = Shear;
  using bond_slot = Bond;
  static constexpr bool uses_mass = law_uses_mass<Normal>() || law_uses_mass<Shear>();

  struct params_type {
    typename Normal::params_type normal;
    typename Shear::params_type shear;
    typename Bond::params_type bond;
    double friction = 0.0;  // Coulomb coefficient, used where no bond holds
  };
  struct state_type {
    typename Normal::state_type normal;
    typename Shear::state_type shear;
    typename Bond::state_type bond;
  };

  KOKKOS_INLINE_FUNCTION static ContactForce force(const params_type& p, state_type& s, const ContactGeometry& g) {
    double fn = Normal::force(p.normal, s.normal, g);
    double fs = Shear::force(p.shear, s.shear, g);
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
};

// The two laws of the core, and helpers that spell their parameters.
using Linear = Composite<LinearNormal, LinearShear, NoBond>;
using LinearBonded = Composite<LinearNormal, LinearShear, ContactBond>;
using Burgers = Composite<BurgersNormal, BurgersShear, NoBond>;
using BurgersBonded = Composite<BurgersNormal, BurgersShear, ContactBond>;
// Stone on stone and stone on wall with rigid stones: damped (linear.hpp).
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
