#pragma once
// What a contact law sees of a contact, and what it returns.
//
// Conventions: the normal points from the first body to the second; the
// tangent is the normal turned by +90 degrees. A positive normal force pushes
// the bodies apart (compression); a negative one is tension (bonded only).
// The shear force is the tangential force on the second body.
#include <vrut/data/vec2.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

struct ContactGeometry {
  Vec2 normal;                 // unit, first -> second body
  double overlap = 0.0;        // r1 + r2 - distance (> 0 when touching, < 0 a gap)
  double normal_increment = 0.0;  // change of overlap during the last step
  double shear_increment = 0.0;   // tangential slip of the second body relative to the first, last step
  double dt = 0.0;
  double radius_1 = 0.0, radius_2 = 0.0;  // radius_1 == 0 for a wall
  // The masses the contact moves: a disk's own, or its rigid body's where it
  // is a member of one; 0 for a wall (which no contact moves). Set only for
  // laws that read them (`static constexpr bool uses_mass = true`).
  double mass_1 = 0.0, mass_2 = 0.0;
};

// v limited to [-limit, limit]: the Coulomb slider of the shear slots.
KOKKOS_INLINE_FUNCTION double clamp_magnitude(double v, double limit) {
  return v > limit ? limit : (v < -limit ? -limit : v);
}

struct ContactForce {
  double normal = 0.0;  // > 0 compression
  double shear = 0.0;   // on the second body, along the tangent
};

}  // namespace vrut
