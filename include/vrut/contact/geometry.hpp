#pragma once
/// \file
/// What a contact law sees of a contact, and what it returns, in 2D and 3D
/// (data/dimension.hpp).
///
/// Conventions: the normal points from the first body to the second. A
/// positive normal force pushes the bodies apart (compression); a negative
/// one is tension (bonded only). The shear is the second body's, relative to
/// the first: in 2D a scalar along the tangent (the normal turned by +90
/// degrees), in 3D a vector in the tangent plane.
#include <vrut/data/dimension.hpp>
#include <vrut/data/vec2.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

template <class D>
struct ContactGeometryIn {
  typename D::vector normal;       // unit, first -> second body
  double overlap = 0.0;            // r1 + r2 - distance (> 0 when touching, < 0 a gap)
  double normal_increment = 0.0;   // change of overlap during the last step
  typename D::shear shear_increment{};  // tangential slip of the second body relative to the first, last step
  double dt = 0.0;
  double radius_1 = 0.0, radius_2 = 0.0;  // radius_1 == 0 for a wall
  /// The masses the contact moves: a particle's own, or its rigid body's
  /// where it is a member of one; 0 for a wall (which no contact moves). Set
  /// only for laws that read them (`static constexpr bool uses_mass = true`).
  double mass_1 = 0.0, mass_2 = 0.0;
};

template <class D>
struct ContactForceIn {
  double normal = 0.0;              // > 0 compression
  typename D::shear shear{};        // on the second body, in the tangent (plane)
};

/// The 2D names every 2D law is written with.
using ContactGeometry = ContactGeometryIn<Dim2>;
using ContactForce = ContactForceIn<Dim2>;

}  // namespace vrut
