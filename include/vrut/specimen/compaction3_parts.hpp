#pragma once
// The compaction's parts (compaction3.hpp): a stone as a rigid body, its
// periodic image, libccd's view of it, and one pair's contact; and the host
// threads that share a step's pairs. Host-only; mm. Needs the target
// vrut::stones3.
#include <vrut/specimen/placement3.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <thread>
#include <vector>

namespace vrut {

namespace detail {

// A stone as a rigid body of the compaction.
struct CompactedStone {
  Stone3 shape;                  // as placed loosely, its centroid at the origin
  std::vector<Point3> vertices;  // about the centroid, as turned now
  Eigen::Quaterniond turn = Eigen::Quaterniond::Identity();
  Point3 centre = Point3::Zero(), velocity = Point3::Zero(), spin = Point3::Zero();
  Point3 force = Point3::Zero(), torque = Point3::Zero();
  double mass = 0.0, inertia = 0.0, reach = 0.0;
  double moved = 0.0;  // at most, any of its points in the last step: dt |velocity| + the turn's angle x reach
  long wraps = 0;  // whole depths taken off the centre's z, to keep it in [0, depth)
};

// The shift along the periodic depth that puts b's image beside a: the image
// the pair was found with, moved by a whole depth for each time either stone
// has wrapped across the depth since (its centre kept in [0, depth)).
inline double pair_image(double image_at_search, long a_wraps_since, long b_wraps_since, double depth) {
  return image_at_search + depth * static_cast<double>(b_wraps_since - a_wraps_since);
}

// The stone as libccd sees it, shifted (a periodic image) and grown by
// `margin` all round (the Minkowski sum with a ball). It keeps the last
// direction libccd asked it for: when MPR finds two stones apart, the last
// direction it asked the first stone for is one along which they lie apart
// (or nearly: it is only a hint, which gap_along checks).
struct ShiftedCompactedStone {
  const CompactedStone* stone;
  Point3 shift;
  double margin;
  mutable Point3 last_asked = Point3::Zero();
};
inline void compacted_support(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out) {
  const auto* s = static_cast<const ShiftedCompactedStone*>(object);
  const Point3 d(ccdVec3X(direction), ccdVec3Y(direction), ccdVec3Z(direction));
  s->last_asked = d;
  const double length = d.norm();
  const Point3 p = s->stone->centre + farthest_along(s->stone->vertices, d) + s->shift +
                   (length > 0.0 ? s->margin / length : 0.0) * d;
  ccdVec3Set(out, p.x(), p.y(), p.z());
}
inline void compacted_centre(const void* object, ccd_vec3_t* out) {
  const auto* s = static_cast<const ShiftedCompactedStone*>(object);
  const Point3 c = s->stone->centre + s->shift;
  ccdVec3Set(out, c.x(), c.y(), c.z());
}

// How far b (shifted) lies beyond a along the unit direction `along`: the
// gap between the plane through a's farthest vertex along it and the plane
// through b's nearest (a separating axis where positive).
inline double gap_along(const CompactedStone& a, const CompactedStone& b, const Point3& shift, const Point3& along) {
  double top_a = -std::numeric_limits<double>::infinity(), bottom_b = std::numeric_limits<double>::infinity();
  for (const auto& v : a.vertices) top_a = std::max(top_a, v.dot(along));
  for (const auto& v : b.vertices) bottom_b = std::min(bottom_b, v.dot(along));
  return (b.centre + shift - a.centre).dot(along) + bottom_b - top_a;
}

// body(i) for i in [0, n), on `threads` threads, each a contiguous share.
template <class Body>
void for_each_index(std::size_t n, int threads, const Body& body) {
  const std::size_t parts = std::min<std::size_t>(std::max(1, threads), n);
  if (parts <= 1) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  auto share = [&](std::size_t part) {
    for (std::size_t i = n * part / parts; i < n * (part + 1) / parts; ++i) body(i);
  };
  std::vector<std::thread> others;
  for (std::size_t part = 1; part < parts; ++part) others.emplace_back(share, part);
  share(0);
  for (auto& t : others) t.join();
}

// One pair's contact in a compaction step: its force on b (a gets the
// opposite) and the arms from each stone's centre to the contact point.
struct PairContact {
  bool touching = false;
  double depth = 0.0;  // of the overlap, less the clearance kept between stones
  Point3 force = Point3::Zero(), arm_a = Point3::Zero(), arm_b = Point3::Zero();
};

}  // namespace detail

}  // namespace vrut
