#pragma once
/// \file
/// A 2-vector with arithmetic usable inside Kokkos kernels (Eigen stays on the
/// host: its types are not trivially usable in every device lambda).
#include <Kokkos_Core.hpp>

#include <cmath>

namespace vrut {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

KOKKOS_INLINE_FUNCTION Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
KOKKOS_INLINE_FUNCTION Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
KOKKOS_INLINE_FUNCTION Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
KOKKOS_INLINE_FUNCTION Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
KOKKOS_INLINE_FUNCTION Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
KOKKOS_INLINE_FUNCTION Vec2& operator+=(Vec2& a, Vec2 b) { a.x += b.x; a.y += b.y; return a; }
KOKKOS_INLINE_FUNCTION Vec2& operator-=(Vec2& a, Vec2 b) { a.x -= b.x; a.y -= b.y; return a; }

/// Component k (0, 1: x, y).
KOKKOS_INLINE_FUNCTION double& component(Vec2& v, int k) { return k == 0 ? v.x : v.y; }
KOKKOS_INLINE_FUNCTION double component(const Vec2& v, int k) { return k == 0 ? v.x : v.y; }

KOKKOS_INLINE_FUNCTION double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z-component of the 3D cross product of two in-plane vectors.
KOKKOS_INLINE_FUNCTION double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// a rotated by +90 degrees: the in-plane tangent of a normal, and omega x r = omega * perp(r).
KOKKOS_INLINE_FUNCTION Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
KOKKOS_INLINE_FUNCTION double norm(Vec2 a) { return sqrt(a.x * a.x + a.y * a.y); }

}  // namespace vrut
