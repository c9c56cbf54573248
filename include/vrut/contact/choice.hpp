#pragma once
// One of two contact laws, chosen per material pair by the assignment table:
// the rutting test's mastic contacts are Burger's, its aggregate contacts
// linear. The choice is data (an index in the pair's parameters), so a
// Simulation keeps one law type; the branch costs one predictable test per
// contact, not a virtual call.
#include <vrut/contact/concept.hpp>
#include <vrut/contact/geometry.hpp>

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace vrut {

// The choice's parameters, the same type in 2D and 3D.
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
  struct state_type {
    typename First::state_type first;
    typename Second::state_type second;
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
      const ContactForceIn<dimension> f = Second::force(p.second, s.second, g);
      if (!is_bonded<Second>(s.second)) s.first = typename First::state_type{};  // a broken bond stays broken
      return f;
    }
    const ContactForceIn<dimension> f = First::force(p.first, s.first, g);
    if (!is_bonded<First>(s.first)) s.second = typename Second::state_type{};
    return f;
  }
  static void prepare(params_type& p, double dt) {
    prepare_law<First>(p.first, dt);
    prepare_law<Second>(p.second, dt);
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) {
    return p.use_second ? Second::stiffness(p.second) : First::stiffness(p.first);
  }
  // Both halves are bonded together, and a contact counts as bonded while
  // either is (the half not in use is cleared when the one in use breaks).
  KOKKOS_INLINE_FUNCTION static bool bonded(const state_type& s) {
    return is_bonded<First>(s.first) || is_bonded<Second>(s.second);
  }
  KOKKOS_INLINE_FUNCTION static void bond(state_type& s) {
    make_bonded<First>(s.first);
    make_bonded<Second>(s.second);
  }
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) {
    turn_history<First>(s.first, turn);
    turn_history<Second>(s.second, turn);
  }
};

template <class First, class Second, class D>
struct in_dimension<Choice<First, Second>, D> {
  using type = Choice<in_dimension_t<First, D>, in_dimension_t<Second, D>>;
};

}  // namespace vrut
