#pragma once
// Unit quaternions for the orientation of a 3D rigid body: q turns a vector
// from the body's frame into the world's, v_world = q v_body q*. Usable in
// Kokkos kernels.
#include <vrut/data/vec3.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>

namespace vrut {

struct Quaternion {
  double w = 1.0;  // the scalar part; (1, 0, 0, 0) is no rotation
  double x = 0.0, y = 0.0, z = 0.0;
};

KOKKOS_INLINE_FUNCTION Quaternion operator*(Quaternion a, Quaternion b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
KOKKOS_INLINE_FUNCTION Quaternion conjugate(Quaternion q) { return {q.w, -q.x, -q.y, -q.z}; }

// The rotation by `angle` (radians, right-handed) about the unit `axis`.
KOKKOS_INLINE_FUNCTION Quaternion axis_angle(Vec3 axis, double angle) {
  const double s = sin(0.5 * angle);
  return {cos(0.5 * angle), s * axis.x, s * axis.y, s * axis.z};
}

// q scaled back to unit length: the products of many steps drift from it by rounding.
KOKKOS_INLINE_FUNCTION Quaternion normalized(Quaternion q) {
  const double n = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// v turned by q (q v q*, written out: v + 2 w (u x v) + 2 u x (u x v), u the vector part).
KOKKOS_INLINE_FUNCTION Vec3 rotate(Quaternion q, Vec3 v) {
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t = 2.0 * cross(u, v);
  return v + q.w * t + cross(u, t);
}
// v turned by the inverse of q: from the world's frame into the body's.
KOKKOS_INLINE_FUNCTION Vec3 rotate_back(Quaternion q, Vec3 v) { return rotate(conjugate(q), v); }

}  // namespace vrut
