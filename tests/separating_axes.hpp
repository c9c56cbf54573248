#pragma once
// Whether two placed 3D stones share interior points, decided exactly by the
// separating axis theorem, independently of the library's own test (libccd's
// MPR, specimen/stone3.hpp): two convex polyhedra are apart if and only if
// one of these axes separates them, a face normal of either, or the cross
// product of an edge of one with an edge of the other.
#include <vrut/specimen/placement3.hpp>
#include <vrut/specimen/stone3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace vrut_test {

// The stone's edge directions: every pair of vertices on a common face plane
// (the sides of its faces, and diagonals of faces of more than three
// corners, whose extra axes do no harm: any axis that parts two stones is a
// valid witness).
inline std::vector<vrut::Point3> edge_directions(const vrut::Stone3& s, double on_plane) {
  std::vector<vrut::Point3> edges;
  for (const auto& p : s.planes) {
    std::vector<std::size_t> on;
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
      if (std::abs(p.head<3>().dot(s.vertices[v]) - p[3]) <= on_plane) on.push_back(v);
    for (std::size_t i = 0; i < on.size(); ++i)
      for (std::size_t j = i + 1; j < on.size(); ++j) edges.push_back(s.vertices[on[j]] - s.vertices[on[i]]);
  }
  return edges;
}

// The gap between the stones along `axis` (not normalised): negative where
// their projections overlap.
inline double gap_along(const vrut::Stone3& a, const vrut::Stone3& b, const vrut::Point3& axis) {
  double a_low = std::numeric_limits<double>::infinity(), a_high = -a_low, b_low = a_low, b_high = -a_low;
  for (const auto& v : a.vertices) {
    const double t = axis.dot(v);
    a_low = std::min(a_low, t), a_high = std::max(a_high, t);
  }
  for (const auto& v : b.vertices) {
    const double t = axis.dot(v);
    b_low = std::min(b_low, t), b_high = std::max(b_high, t);
  }
  return std::max(b_low - a_high, a_low - b_high);
}

// The widest gap over every candidate axis, in mm (each axis normalised): at
// least -slack means apart (or touching within slack); below, the stones
// overlap by at least that much along every axis.
inline double separation(const vrut::Stone3& a, const vrut::Stone3& b) {
  double best = -std::numeric_limits<double>::infinity();
  auto try_axis = [&](const vrut::Point3& axis) {
    const double n = axis.norm();
    if (n > 1e-12) best = std::max(best, gap_along(a, b, axis / n));
  };
  for (const auto& p : a.planes) try_axis(p.head<3>());
  for (const auto& p : b.planes) try_axis(p.head<3>());
  if (best >= 0.0) return best;
  const double on_plane = 1e-9 * (1.0 + a.reach + b.reach);
  const auto ea = edge_directions(a, on_plane), eb = edge_directions(b, on_plane);
  for (const auto& u : ea)
    for (const auto& v : eb) {
      try_axis(u.cross(v));
      if (best >= 0.0) return best;
    }
  return best;
}

// Every pair of stones, across the periodic depth too: the pairs whose
// bounding boxes meet, and among them those that overlap by more than
// `slack` mm (rounding on stones of a few mm: 1e-9 is a million times finer
// than the placements' clearances).
struct OverlapCount {
  int pairs_near = 0, overlapping = 0;
  double deepest = 0.0;  // mm, the largest overlap found (0 if none)
};

inline OverlapCount overlapping_pairs(const vrut::Placement3& p, double slack = 1e-9) {
  OverlapCount out;
  const std::size_t n = p.stones.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (double image : {0.0, -p.depth, p.depth}) {
        vrut::Stone3 b = p.stones[j].shape;
        b.translate(vrut::Point3(0.0, 0.0, image));
        const auto box_a = p.stones[i].shape.bounds(), box_b = b.bounds();
        if (!box_a.intersects(box_b)) continue;
        ++out.pairs_near;
        const double s = separation(p.stones[i].shape, b);
        if (s < -slack) {
          ++out.overlapping;
          out.deepest = std::max(out.deepest, -s);
        }
      }
  return out;
}

}  // namespace vrut_test
