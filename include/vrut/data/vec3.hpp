#pragma once
/// \file
/// A 3-vector with arithmetic usable inside Kokkos kernels, the 3D sibling of
/// vec2.hpp (Eigen stays on the host).
#include <Kokkos_Core.hpp>

#include <cmath>

namespace vrut {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

KOKKOS_INLINE_FUNCTION Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
KOKKOS_INLINE_FUNCTION Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
KOKKOS_INLINE_FUNCTION Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
KOKKOS_INLINE_FUNCTION Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
KOKKOS_INLINE_FUNCTION Vec3 operator*(Vec3 a, double s) { return {s * a.x, s * a.y, s * a.z}; }
/// Each component divided, as a scalar formula divides (not times 1 / s).
KOKKOS_INLINE_FUNCTION Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
KOKKOS_INLINE_FUNCTION Vec3& operator+=(Vec3& a, Vec3 b) { a.x += b.x; a.y += b.y; a.z += b.z; return a; }
KOKKOS_INLINE_FUNCTION Vec3& operator-=(Vec3& a, Vec3 b) { a.x -= b.x; a.y -= b.y; a.z -= b.z; return a; }

/// Component k (0, 1, 2: x, y, z).
KOKKOS_INLINE_FUNCTION double& component(Vec3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }
KOKKOS_INLINE_FUNCTION double component(const Vec3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

KOKKOS_INLINE_FUNCTION double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
KOKKOS_INLINE_FUNCTION Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
KOKKOS_INLINE_FUNCTION double norm(Vec3 a) { return sqrt(dot(a, a)); }
/// Component by component: the body frame's diagonal inertia times a vector.
KOKKOS_INLINE_FUNCTION Vec3 times_each(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
KOKKOS_INLINE_FUNCTION Vec3 over_each(Vec3 a, Vec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }

}  // namespace vrut
