#pragma once
/// \file
/// One of two contact laws, chosen per material pair by the assignment table:
/// the rutting test's mastic contacts are Burger's, its aggregate contacts
/// linear. The choice is data (an index in the pair's parameters), so a
/// Simulation keeps one law type; the branch costs one predictable test per
/// contact, not a virtual call.
#include <vrut/contact/concept.hpp>
#include <vrut/contact/geometry.hpp>

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace vrut {

/// The choice's parameters, the same type in 2D and 3D.
template <class FirstParams, class SecondParams>
struct ChoiceParams {
  int use_second = 0;
  FirstParams first;
  SecondParams second;
};

template <class First, class Second>
struct Choice {
  static_assert(check_contact_law<First>(), "vrut::Choice: First is not a contact law");
  static_assert(check_contact_law<Second>(), "vrut::Choice: Second is not a contact law");
  static_assert(std::is_same_v<law_dimension_t<First>, law_dimension_t<Second>>,
                "vrut::Choice: First and Second are laws of different dimensions");

  using dimension = law_dimension_t<First>;
  static constexpr bool uses_mass = law_uses_mass<First>() || law_uses_mass<Second>();

  using params_type = ChoiceParams<typename First::params_type, typename Second::params_type>;

  /// A slot holds the state of the law that acts there only (`law`, set by
  /// the first force), the two laws' states sharing their bytes: in 3D's
  /// rutting table 104 bytes a slot instead of both laws' 136. A bond asked
  /// for before the first force (or between forces) waits in `bond_asked`
  /// and is made on the law that acts, as if both halves had been bonded.
  struct state_type {
    union Storage {
      typename First::state_type first;
      typename Second::state_type second;
      KOKKOS_INLINE_FUNCTION Storage() : first() {}
    } of;
    signed char law = 0;  // 0: no force yet, 1: First, 2: Second
    signed char bond_asked = 0;
  };

  static params_type make_first(const typename First::params_type& p) {
    params_type c{};
    c.use_second = 0;
    c.first = p;
    return c;
  }
  static params_type make_second(const typename Second::params_type& p) {
    params_type c{};
    c.use_second = 1;
    c.second = p;
    return c;
  }

  KOKKOS_INLINE_FUNCTION static ContactForceIn<dimension> force(const params_type& p, state_type& s,
                                                                const ContactGeometryIn<dimension>& g) {
    if (p.use_second) {
      if (s.law != 2) s.of.second = typename Second::state_type{}, s.law = 2;
      if (s.bond_asked) make_bonded<Second>(s.of.second), s.bond_asked = 0;
      return Second::force(p.second, s.of.second, g);
    }
    if (s.law != 1) s.of.first = typename First::state_type{}, s.law = 1;
    if (s.bond_asked) make_bonded<First>(s.of.first), s.bond_asked = 0;
    return First::force(p.first, s.of.first, g);
  }
  static void prepare(params_type& p, double dt) {
    prepare_law<First>(p.first, dt);
    prepare_law<Second>(p.second, dt);
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) {
    return p.use_second ? Second::stiffness(p.second) : First::stiffness(p.first);
  }
  /// A bond waiting for the first force counts as bonded where either law
  /// can hold one; after it, the law that acts says.
  KOKKOS_INLINE_FUNCTION static bool bonded(const state_type& s) {
    if (s.bond_asked) return true;
    if (s.law == 1) return is_bonded<First>(s.of.first);
    if (s.law == 2) return is_bonded<Second>(s.of.second);
    return false;
  }
  KOKKOS_INLINE_FUNCTION static void bond(state_type& s) {
    if (can_bond()) s.bond_asked = 1;
  }
  /// Fresh again: the next force starts its law's state from {} (writing two
  /// bytes, not the whole slot, for each pair of the list that is apart).
  KOKKOS_INLINE_FUNCTION static void forget(state_type& s) {
    s.law = 0;
    s.bond_asked = 0;
  }
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) {
    if (s.law == 1) turn_history<First>(s.of.first, turn);
    else if (s.law == 2) turn_history<Second>(s.of.second, turn);
  }

 private:
  /// Whether either law holds a bond once asked to (a law without bonds
  /// ignores the request).
  KOKKOS_INLINE_FUNCTION static bool can_bond() {
    typename First::state_type a{};
    make_bonded<First>(a);
    typename Second::state_type b{};
    make_bonded<Second>(b);
    return is_bonded<First>(a) || is_bonded<Second>(b);
  }
};

template <class First, class Second, class D>
struct in_dimension<Choice<First, Second>, D> {
  using type = Choice<in_dimension_t<First, D>, in_dimension_t<Second, D>>;
};

}  // namespace vrut
