#pragma once
/// \file
/// Flat walls in 3D: rectangular plates, and the sphere-plate contact
/// geometry, the 3D siblings of the segments of walls.hpp.
#include <vrut/data/vec3.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

/// A rectangle: its centre and two orthogonal half-edges (from the centre
/// to the middle of an edge). Its inward normal (towards the spheres it holds) is
/// half_u x half_v, so a floor under spheres at larger z has half_u along x
/// and half_v along y. A wall meant to be endless (across a periodic axis,
/// say) is a plate larger than anything it will hold.
struct Wall3 {
  Vec3 centre, half_u, half_v;
  Vec3 velocity;
};

KOKKOS_INLINE_FUNCTION Vec3 inward_normal(const Wall3& w) {
  const Vec3 n = cross(w.half_u, w.half_v);
  return (1.0 / norm(n)) * n;
}

/// The plate's area (the 2D wall's length: zero for a degenerate wall).
KOKKOS_INLINE_FUNCTION double area(const Wall3& w) { return 4.0 * norm(cross(w.half_u, w.half_v)); }

KOKKOS_INLINE_FUNCTION void translate(Wall3& w, Vec3 d) { w.centre += d; }

/// Closest point of the plate to c; normal from there to c (wall -> sphere).
/// Returns the distance. A centre exactly on the plate gets the inward
/// normal. With orthogonal half-edges, the closest point's coordinates along
/// them are the centre's own, clamped to the plate.
KOKKOS_INLINE_FUNCTION double wall_distance(const Wall3& w, Vec3 c, Vec3& normal) {
  const Vec3 r0 = c - w.centre;
  double a = dot(r0, w.half_u) / dot(w.half_u, w.half_u), b = dot(r0, w.half_v) / dot(w.half_v, w.half_v);
  a = a < -1.0 ? -1.0 : (a > 1.0 ? 1.0 : a);
  b = b < -1.0 ? -1.0 : (b > 1.0 ? 1.0 : b);
  const Vec3 r = r0 - a * w.half_u - b * w.half_v;
  const double dist = norm(r);
  normal = dist > 0.0 ? (1.0 / dist) * r : inward_normal(w);
  return dist;
}

}  // namespace vrut
