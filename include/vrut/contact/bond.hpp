#pragma once
// Bond slots of a composed law: none, or a PFC-style contact bond.
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

struct NoBond {
  struct params_type {};
  struct state_type {};
  KOKKOS_INLINE_FUNCTION static bool intact(const state_type&) { return false; }
  KOKKOS_INLINE_FUNCTION static void bond(state_type&) {}
  KOKKOS_INLINE_FUNCTION static void release(state_type&) {}
  template <class Shear>
  KOKKOS_INLINE_FUNCTION static bool holds(const params_type&, double, const Shear&) { return false; }
};

// A contact bond: while intact the contact carries tension and its shear is
// not limited by friction. It breaks when the tension exceeds the normal
// strength or the shear force's magnitude exceeds the shear strength (both
// in N), and never heals.
struct ContactBond {
  struct params_type {
    double normal_strength = 0.0;
    double shear_strength = 0.0;
  };
  struct state_type { int intact = 0; };
  KOKKOS_INLINE_FUNCTION static bool intact(const state_type& s) { return s.intact != 0; }
  KOKKOS_INLINE_FUNCTION static void bond(state_type& s) { s.intact = 1; }
  KOKKOS_INLINE_FUNCTION static void release(state_type& s) { s.intact = 0; }
  template <class Shear>
  KOKKOS_INLINE_FUNCTION static bool holds(const params_type& p, double normal, const Shear& shear) {
    return -normal <= p.normal_strength && magnitude(shear) <= p.shear_strength;
  }
};

}  // namespace vrut
