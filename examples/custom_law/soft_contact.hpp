// A user-written contact law (the README shows it): a normal spring that
// stiffens with overlap, F_n = k (overlap + overlap^2 / r0), with a linear
// shear spring capped by friction. Needs nothing but <vrut/contact/geometry.hpp>.
#pragma once
#include <vrut/contact/geometry.hpp>

struct StiffeningContact {
  struct params_type { double k, r0, ks, friction; };
  struct state_type { double shear; };
  KOKKOS_INLINE_FUNCTION static vrut::ContactForce force(const params_type& p, state_type& s,
                                                         const vrut::ContactGeometry& g) {
    const double fn = p.k * (g.overlap + g.overlap * g.overlap / p.r0);
    s.shear -= p.ks * g.shear_increment;
    const double cap = p.friction * fn;
    s.shear = s.shear > cap ? cap : (s.shear < -cap ? -cap : s.shear);
    return {fn, s.shear};
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return 3.0 * p.k; }
};
