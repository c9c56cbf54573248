#pragma once
// Linear springs: the normal and shear slots of a composed law (see composite.hpp).
#include <vrut/contact/geometry.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

// Normal force proportional to the total overlap: F_n = k_n * overlap.
// With a bond holding, a negative overlap gives tension.
struct LinearNormal {
  struct params_type { double stiffness = 0.0; };  // k_n, N/m
  struct state_type {};
  KOKKOS_INLINE_FUNCTION static double force(const params_type& p, state_type&, const ContactGeometry& g) {
    return p.stiffness * g.overlap;
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.stiffness; }
};

// Incremental shear spring: dF_s = -k_s * (tangential slip during the step).
struct LinearShear {
  struct params_type { double stiffness = 0.0; };  // k_s, N/m
  struct state_type { double force = 0.0; };
  KOKKOS_INLINE_FUNCTION static double force(const params_type& p, state_type& s, const ContactGeometry& g) {
    s.force -= p.stiffness * g.shear_increment;
    return s.force;
  }
  // Coulomb cap: the stored force slides back to the limit, so unloading starts from there.
  KOKKOS_INLINE_FUNCTION static double limit(const params_type&, state_type& s, double max_abs) {
    return s.force = clamp_magnitude(s.force, max_abs);
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return p.stiffness; }
};

}  // namespace vrut
