#pragma once
/// \file
/// The dimension of a simulation as a type: what a position, a spin, an
/// orientation and a contact's shear are in 2D and in 3D. The engine, the
/// contact laws' shear slots and the integrator take one of these as a
/// template parameter and keep one source for both.
///
///              2D (disks of thickness t)        3D (spheres)
///   vector     Vec2                             Vec3
///   spin       double, about the out-of-plane   Vec3
///              axis (angular velocity, moment)
///   orientation double, an angle                Quaternion (data/quaternion.hpp)
///   shear      double, along the contact's      Vec3, in the contact's
///              tangent (the normal turned by    tangent plane
///              +90 degrees)
#include <vrut/data/quaternion.hpp>
#include <vrut/data/vec2.hpp>
#include <vrut/data/vec3.hpp>

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace vrut {

struct Dim2 {
  static constexpr int value = 2;
  using vector = Vec2;
  using spin = double;
  using orientation = double;
  using shear = double;
};

struct Dim3 {
  static constexpr int value = 3;
  using vector = Vec3;
  using spin = Vec3;
  using orientation = Quaternion;
  using shear = Vec3;
};

template <class D>
inline constexpr bool is_3d = D::value == 3;

/// The length of a shear value, and the shear value cut down to a length:
/// the Coulomb slider. For a scalar the sign is kept; for a vector its direction.
KOKKOS_INLINE_FUNCTION double magnitude(double v) { return v < 0.0 ? -v : v; }
KOKKOS_INLINE_FUNCTION double magnitude(Vec3 v) { return norm(v); }
KOKKOS_INLINE_FUNCTION double clamp_magnitude(double v, double limit) {
  return v > limit ? limit : (v < -limit ? -limit : v);
}
KOKKOS_INLINE_FUNCTION double cap_magnitude(double v, double limit) { return clamp_magnitude(v, limit); }
/// A limit at or below zero leaves nothing: a cap that the film's share has
/// used up may come out a rounding error below zero, and a zero vector would
/// otherwise be scaled by 0 / 0.
KOKKOS_INLINE_FUNCTION Vec3 cap_magnitude(Vec3 f, double limit) {
  const double length = norm(f);
  if (!(length > limit)) return f;
  return limit > 0.0 ? (limit / length) * f : Vec3{};
}

}  // namespace vrut
