// A user-written contact law for both dimensions (docs/contact-laws.md):
// soft_contact.hpp's stiffening spring, F_n = k (overlap + overlap^2 / r0),
// with a shear spring capped by friction, written once over the dimension D.
// In 2D the shear is a scalar along the tangent; in 3D a vector in the
// tangent plane, which turns with the contact's frame (turn). The engine
// takes StiffeningContactIn<Dim2> in 2D and rebinds it to Dim3 in 3D
// (contact/concept.hpp, in_dimension).
#pragma once
#include <vrut/contact/geometry.hpp>
#include <vrut/data/dimension.hpp>

// Outside the template, so that a table of parameters serves both dimensions.
struct StiffeningParams { double k, r0, ks, friction; };

template <class D>
struct StiffeningContactIn {
  using dimension = D;
  using shear_type = typename D::shear;  // double in 2D, vrut::Vec3 in 3D
  using params_type = StiffeningParams;
  struct state_type { shear_type shear; };
  KOKKOS_INLINE_FUNCTION static vrut::ContactForceIn<D> force(const params_type& p, state_type& s,
                                                              const vrut::ContactGeometryIn<D>& g) {
    const double fn = p.k * (g.overlap + g.overlap * g.overlap / p.r0);
    s.shear -= p.ks * g.shear_increment;
    s.shear = vrut::cap_magnitude(s.shear, p.friction * fn);
    return {fn, s.shear};
  }
  // The stored shear force lies in the tangent plane: it turns with it.
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) { s.shear = turn(s.shear); }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) { return 3.0 * p.k; }
};
