#pragma once
/// \file
/// What a contact law must provide, checked with messages that name the gap.
///
///   struct MyLaw {
///     struct params_type { ... };   // trivially copyable, per material pair
///     struct state_type  { ... };   // trivially copyable, per contact; {} = fresh
///     KOKKOS_INLINE_FUNCTION static ContactForce
///       force(const params_type&, state_type&, const ContactGeometry&);
///     KOKKOS_INLINE_FUNCTION static double stiffness(const params_type&);  // for the time step
///   };
///
/// The geometry and force are ContactGeometryIn<D> and ContactForceIn<D> of
/// the law's dimension D (data/dimension.hpp): a law declares it with
/// `using dimension = Dim3;`, and without it is a 2D law, written with
/// ContactGeometry and ContactForce.
///
/// Optional: `static bool bonded(const state_type&)` (a bonded contact is kept,
/// and evaluated, while its disks are apart), `static void bond(state_type&)`
/// (called for every touching pair by Simulation::bond_touching_contacts), and
/// `static void prepare(params_type&, double dt)` (called on the host for every
/// material pair whenever the time step changes, so that a law can work out
/// once what depends only on its parameters and dt; force() must give the same
/// result with or without it). A 3D law with history that lies in the
/// tangent plane (a shear spring's force) provides
/// `template <class Turn> static void turn(state_type&, const Turn& turn)`,
/// which replaces each such vector v by turn(v) as the contact's frame turns
/// (contact/geometry3.hpp, ContactTurn). `static void forget(state_type&)`
/// makes a state behave as fresh more cheaply than writing `{}` over it (the
/// engine forgets every pair of its list that is apart, every step).
#include <vrut/contact/geometry.hpp>
#include <vrut/data/dimension.hpp>

#include <type_traits>
#include <utility>

namespace vrut {

/// The dimension a law is written for: its member type `dimension`, else 2D.
template <class L, class = void>
struct law_dimension { using type = Dim2; };
template <class L>
struct law_dimension<L, std::void_t<typename L::dimension>> { using type = typename L::dimension; };
template <class L>
using law_dimension_t = typename law_dimension<L>::type;

template <class T> struct is_dimension : std::false_type {};
template <> struct is_dimension<Dim2> : std::true_type {};
template <> struct is_dimension<Dim3> : std::true_type {};

/// A law's form in dimension D, so that one law (Linear, the rutting test's
/// laws) serves 2D and 3D. A law written for D is its own form; a slot that
/// is a template on its dimension alone (LinearShearIn<D>) takes D; the
/// composed laws (Composite, Choice) rebind their slots. Any other law keeps
/// its dimension, and the engine says so where it does not match.
template <class L, class D, class = void>
struct in_dimension { using type = L; };
template <template <class> class Slot, class Old, class D>
struct in_dimension<Slot<Old>, D, std::enable_if_t<is_dimension<Old>::value>> { using type = Slot<D>; };
template <class L, class D>
using in_dimension_t = typename in_dimension<L, D>::type;

namespace detail {

template <class, class = void> struct has_params_type : std::false_type {};
template <class L> struct has_params_type<L, std::void_t<typename L::params_type>> : std::true_type {};
template <class, class = void> struct has_state_type : std::false_type {};
template <class L> struct has_state_type<L, std::void_t<typename L::state_type>> : std::true_type {};

template <class, class = void> struct has_force : std::false_type {};
template <class L>
struct has_force<L, std::void_t<decltype(L::force(std::declval<const typename L::params_type&>(),
                                                  std::declval<typename L::state_type&>(),
                                                  std::declval<const ContactGeometryIn<law_dimension_t<L>>&>()))>>
    : std::is_convertible<decltype(L::force(std::declval<const typename L::params_type&>(),
                                            std::declval<typename L::state_type&>(),
                                            std::declval<const ContactGeometryIn<law_dimension_t<L>>&>())),
                          ContactForceIn<law_dimension_t<L>>> {};

template <class, class = void> struct has_stiffness : std::false_type {};
template <class L>
struct has_stiffness<L, std::void_t<decltype(L::stiffness(std::declval<const typename L::params_type&>()))>>
    : std::is_convertible<decltype(L::stiffness(std::declval<const typename L::params_type&>())), double> {};

template <class, class = void> struct has_bonded : std::false_type {};
template <class L>
struct has_bonded<L, std::void_t<decltype(L::bonded(std::declval<const typename L::state_type&>()))>>
    : std::true_type {};
template <class, class = void> struct has_bond : std::false_type {};
template <class L>
struct has_bond<L, std::void_t<decltype(L::bond(std::declval<typename L::state_type&>()))>> : std::true_type {};

template <class, class = void> struct has_prepare : std::false_type {};
template <class L>
struct has_prepare<L, std::void_t<decltype(L::prepare(std::declval<typename L::params_type&>(), 0.0))>>
    : std::true_type {};

template <class, class = void> struct has_forget : std::false_type {};
template <class L>
struct has_forget<L, std::void_t<decltype(L::forget(std::declval<typename L::state_type&>()))>> : std::true_type {};
template <class, class, class = void> struct has_turn : std::false_type {};
template <class L, class Turn>
struct has_turn<L, Turn, std::void_t<decltype(L::turn(std::declval<typename L::state_type&>(),
                                                      std::declval<const Turn&>()))>> : std::true_type {};

template <class, class = void> struct has_uses_mass : std::false_type {};
template <class L> struct has_uses_mass<L, std::void_t<decltype(L::uses_mass)>> : std::bool_constant<L::uses_mass> {};

template <class L, bool = has_params_type<L>::value && has_state_type<L>::value>
struct law_members_ok : std::false_type {};
template <class L>
struct law_members_ok<L, true>
    : std::bool_constant<has_force<L>::value && has_stiffness<L>::value &&
                         std::is_trivially_copyable<typename L::params_type>::value &&
                         std::is_trivially_copyable<typename L::state_type>::value> {};

}  // namespace detail

/// Fails the build with one message per missing piece. Use it where a law
/// enters a template: `static_assert(check_contact_law<Law>())`.
template <class Law>
constexpr bool check_contact_law() {
  static_assert(detail::has_params_type<Law>::value,
                "vrut contact law: missing member type 'params_type' (per material pair parameters)");
  static_assert(detail::has_state_type<Law>::value,
                "vrut contact law: missing member type 'state_type' (per-contact history; an empty struct if none)");
  if constexpr (detail::has_params_type<Law>::value && detail::has_state_type<Law>::value) {
    static_assert(detail::has_force<Law>::value,
                  "vrut contact law: missing 'static ContactForce force(const params_type&, state_type&, "
                  "const ContactGeometry&)' (ContactForceIn<Dim3> and ContactGeometryIn<Dim3> for a law whose "
                  "dimension is Dim3)");
    static_assert(detail::has_stiffness<Law>::value,
                  "vrut contact law: missing 'static double stiffness(const params_type&)' (used for the "
                  "critical time step)");
    static_assert(std::is_trivially_copyable<typename Law::params_type>::value,
                  "vrut contact law: 'params_type' must be trivially copyable (it is copied to the device)");
    static_assert(std::is_trivially_copyable<typename Law::state_type>::value,
                  "vrut contact law: 'state_type' must be trivially copyable (it lives in a Kokkos::View)");
  }
  return detail::law_members_ok<Law>::value;
}

/// Bond queries that work for every law, bonded or not.
template <class Law>
KOKKOS_INLINE_FUNCTION bool is_bonded(const typename Law::state_type& s) {
  if constexpr (detail::has_bonded<Law>::value) return Law::bonded(s);
  else { (void)s; return false; }
}
template <class Law>
KOKKOS_INLINE_FUNCTION void make_bonded(typename Law::state_type& s) {
  if constexpr (detail::has_bond<Law>::value) Law::bond(s);
  else (void)s;
}
/// Makes a contact's state fresh: the law's own `forget`, else `{}`.
template <class Law>
KOKKOS_INLINE_FUNCTION void forget_contact(typename Law::state_type& s) {
  if constexpr (detail::has_forget<Law>::value) Law::forget(s);
  else s = typename Law::state_type{};
}
/// Whether a law reads the masses of ContactGeometry (a law or slot says so
/// with `static constexpr bool uses_mass = true`); the engine fills them only
/// then, so laws without it cost no extra memory traffic.
template <class Law>
constexpr bool law_uses_mass() {
  return detail::has_uses_mass<Law>::value;
}

/// Carries a 3D law's tangent-plane history into the contact's new frame
/// (see `turn` above); a law without it keeps none.
template <class Law, class Turn>
KOKKOS_INLINE_FUNCTION void turn_history(typename Law::state_type& s, const Turn& turn) {
  if constexpr (detail::has_turn<Law, Turn>::value) Law::turn(s, turn);
  else (void)s, (void)turn;
}

/// Host-side: a law's per-time-step preparation, where it has one.
template <class Law>
void prepare_law(typename Law::params_type& p, double dt) {
  if constexpr (detail::has_prepare<Law>::value) Law::prepare(p, dt);
  else (void)p, (void)dt;
}

}  // namespace vrut
