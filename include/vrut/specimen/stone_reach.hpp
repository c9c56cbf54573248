#pragma once
// How far each stone disk's centre lies inside its stone's true outline: the
// disk's "reach", which sizes the film each pair of stones meets through.
// Host-only; lengths in mm, reaches as fractions of the disk diameter.
//
// Why: a disk belongs to a stone when its centre lies inside the outline, so
// the outline lies somewhere between a boundary disk's centre and its
// neighbour's. Where disks of two stones meet, the mastic between the true
// outlines along the line of centres is one diameter less both reaches: the
// pair's own film (docs/validation.md, the film per contact). The film
// between stones otherwise takes one mean thickness for every pair.
#include <vrut/specimen/packing.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vrut {

// From p, inside `poly`, along the unit direction u: the distance to the
// first edge the ray crosses (infinity if none, p outside a closed outline).
inline double distance_to_outline(const Polygon& poly, const Point& p, const Point& u) {
  double best = std::numeric_limits<double>::infinity();
  const auto& v = poly.vertices;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    // p + t u = v[j] + s (v[i] - v[j]), solved by Cramer's rule.
    const Point e = v[i] - v[j], w = v[j] - p;
    const double det = e.x() * u.y() - e.y() * u.x();
    if (det == 0.0) continue;  // the ray runs along the edge's line
    const double t = (e.x() * w.y() - e.y() * w.x()) / det;
    const double s = (u.x() * w.y() - u.y() * w.x()) / det;
    if (t > 0.0 && s >= 0.0 && s <= 1.0) best = std::min(best, t);
  }
  return best;
}

// One value per disk: -1 for a mastic disk; for a stone disk, the mean
// distance from its centre to its stone's outline, in disk diameters (at
// most 1), along the lines to its lattice neighbours in other stones. Where
// it has none, along the lines to its mastic neighbours (where a stone meets
// another once the mastic between them has squeezed out); where it has
// neither, it lies deep inside its stone: 1.
inline std::vector<double> stone_reach(const DiskPacking& disks, const Placement& placement) {
  const std::size_t n = disks.centers.size();
  const double d = 2.0 * disks.radius;
  std::vector<double> stones(n, 0.0), mastic(n, 0.0);
  std::vector<int> stones_count(n, 0), mastic_count(n, 0);
  auto reach = [&](std::size_t from, std::size_t to) {
    const Point u = (disks.centers[to] - disks.centers[from]).normalized();
    const double t = distance_to_outline(placement.aggregates[disks.aggregate[from]].polygon, disks.centers[from], u);
    return std::min(t / d, 1.0);
  };
  // Lattice neighbours lie one diameter apart; the rows go up with the index.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Point gap = disks.centers[j] - disks.centers[i];
      if (gap.y() > 1.01 * d) break;
      if (gap.norm() > 1.001 * d) continue;
      const int a = disks.aggregate[i], b = disks.aggregate[j];
      if (a == b) continue;  // one stone, or two mastic disks
      if (a >= 0 && b >= 0) {
        stones[i] += reach(i, j), ++stones_count[i];
        stones[j] += reach(j, i), ++stones_count[j];
      } else if (a >= 0) {
        mastic[i] += reach(i, j), ++mastic_count[i];
      } else {
        mastic[j] += reach(j, i), ++mastic_count[j];
      }
    }
  std::vector<double> out(n, -1.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (disks.aggregate[i] < 0) continue;
    out[i] = stones_count[i] > 0   ? stones[i] / stones_count[i]
             : mastic_count[i] > 0 ? mastic[i] / mastic_count[i]
                                   : 1.0;
  }
  return out;
}

// The reach in `classes` equal bins over [0, 1] (the contact table holds one
// film per pair of bins); each bin stands for its middle.
inline int reach_class(double reach, int classes) {
  return std::clamp(static_cast<int>(reach * classes), 0, classes - 1);
}
inline double reach_class_middle(int c, int classes) { return (c + 0.5) / classes; }

}  // namespace vrut
