#pragma once
/// \file
/// Straight walls (segments) and the disk-wall contact geometry, in 2D; the
/// load particles put on a wall, in 2D and 3D (walls3.hpp has the 3D plates).
#include <vrut/data/dimension.hpp>
#include <vrut/data/vec2.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

/// A segment from start to end. Its inward normal (towards the disks it holds)
/// is the direction start->end turned by +90 degrees: a bottom wall runs from
/// left to right, a top plate from right to left.
struct Wall {
  Vec2 start, end;
  Vec2 velocity;
};

KOKKOS_INLINE_FUNCTION Vec2 inward_normal(const Wall& w) {
  const Vec2 d = w.end - w.start;
  return (1.0 / norm(d)) * perp(d);
}

KOKKOS_INLINE_FUNCTION double length(const Wall& w) { return norm(w.end - w.start); }

/// The wall moved by d.
KOKKOS_INLINE_FUNCTION void translate(Wall& w, Vec2 d) {
  w.start += d;
  w.end += d;
}

/// Closest point of the segment to c; normal from there to c (wall -> disk).
/// Returns the distance. A centre exactly on the segment gets the inward normal.
KOKKOS_INLINE_FUNCTION double wall_distance(const Wall& w, Vec2 c, Vec2& normal) {
  const Vec2 d = w.end - w.start;
  double s = dot(c - w.start, d) / dot(d, d);
  s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
  const Vec2 q = w.start + s * d;
  const Vec2 r = c - q;
  const double dist = norm(r);
  normal = dist > 0.0 ? (1.0 / dist) * r : inward_normal(w);
  return dist;
}

/// Sum of the forces the particles exert on a wall, and how many touch it.
template <class D>
struct WallLoadIn {
  typename D::vector force;
  double contacts = 0.0;
};
using WallLoad = WallLoadIn<Dim2>;

template <class D>
KOKKOS_INLINE_FUNCTION WallLoadIn<D>& operator+=(WallLoadIn<D>& a, const WallLoadIn<D>& b) {
  a.force += b.force;
  a.contacts += b.contacts;
  return a;
}

}  // namespace vrut
