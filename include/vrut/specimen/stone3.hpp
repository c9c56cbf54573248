#pragma once
// Random convex polyhedral stones for 3D specimens (docs/specimen.md, "In
// 3D"), the method's polygon carried into 3D. Host-only; Eigen 3-vectors;
// mm. Needs the target vrut::stones3 (Qhull for the hull, libccd for the
// overlap test).
//
// A stone of mean radius R0 has n vertices, n uniform in
// [min_vertices, max_vertices]:
//   - directions: n points spread evenly over the unit sphere (a Fibonacci
//     spiral, mean spacing s = sqrt(4 pi / n)), each moved along a random
//     tangent by an angle eta delta s, eta uniform in [0, 1]: the 2D angle
//     step's fluctuation, a fraction delta of the spacing;
//   - radii: r_k = R0 + (2 lambda - 1) R, lambda uniform in [0, 1], as in 2D;
//   - a uniformly random rotation;
// and the stone is the convex hull of these points (a vertex that falls
// inside the others' hull is dropped). The defaults draw 5 to 10 vertices:
// then a plane through a stone cuts a polygon of 7.0 edges on average, 97 %
// of them with 4 to 10, as the method's 2D stones have (n uniform in
// [4, 10]); 8 to 20 vertices would cut 11 on average (docs/specimen.md).
#include <vrut/specimen/polygon.hpp>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <ccd/ccd.h>
#include <libqhullcpp/Qhull.h>
#include <libqhullcpp/QhullFacetList.h>
#include <libqhullcpp/QhullVertexSet.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

using Point3 = Eigen::Vector3d;

struct StoneShape3 {
  double radius_fluctuation = 0.25;  // R / R0, in [0, 1)
  double angle_fluctuation = 0.4;    // delta, in [0, 1]
  int min_vertices = 5, max_vertices = 10;

  void validate() const {
    if (!(radius_fluctuation >= 0.0 && radius_fluctuation < 1.0))
      throw std::invalid_argument("radius fluctuation R/R0 must lie in [0, 1)");
    if (!(angle_fluctuation >= 0.0 && angle_fluctuation <= 1.0))
      throw std::invalid_argument("angle fluctuation delta must lie in [0, 1]");
    if (min_vertices < 4 || max_vertices < min_vertices)
      throw std::invalid_argument("a 3D stone needs at least 4 vertices, and max_vertices >= min_vertices");
  }
};

// A convex polyhedron: its hull vertices, its faces as planes n . x <= h
// (n the outward unit normal), its volume and centroid, and its reach (the
// farthest vertex from the centroid).
struct Stone3 {
  std::vector<Point3> vertices;
  std::vector<Eigen::Vector4d> planes;  // (n, h)
  Point3 centroid = Point3::Zero();
  double volume = 0.0, reach = 0.0;

  bool contains(const Point3& x) const {
    for (const auto& p : planes)
      if (p.head<3>().dot(x) > p[3]) return false;
    return true;
  }
  void translate(const Point3& d) {
    for (auto& v : vertices) v += d;
    for (auto& p : planes) p[3] += p.head<3>().dot(d);
    centroid += d;
  }
  Eigen::AlignedBox3d bounds() const {
    Eigen::AlignedBox3d b;
    for (const auto& v : vertices) b.extend(v);
    return b;
  }
};

// The convex hull of points (at least 4, not all in a plane) as a Stone3.
inline Stone3 convex_hull_stone(const std::vector<Point3>& points) {
  std::vector<double> coords;
  coords.reserve(3 * points.size());
  for (const auto& p : points) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  orgQhull::Qhull hull;
  hull.runQhull("", 3, static_cast<int>(points.size()), coords.data(), "Qt");  // triangulated faces
  Stone3 s;
  for (const orgQhull::QhullVertex& v : hull.vertexList()) {
    const double* c = v.point().coordinates();
    s.vertices.emplace_back(c[0], c[1], c[2]);
  }
  Point3 inside = Point3::Zero();
  for (const auto& v : s.vertices) inside += v;
  inside /= static_cast<double>(s.vertices.size());
  // Volume and centroid: the tetrahedra from an inner point to each face.
  Point3 moment = Point3::Zero();
  for (const orgQhull::QhullFacet& f : hull.facetList()) {
    if (!f.isGood()) continue;
    const orgQhull::QhullHyperplane h = f.hyperplane();  // n . x + offset = 0 on the face, < 0 inside
    const double* n = h.coordinates();
    s.planes.emplace_back(n[0], n[1], n[2], -h.offset());
    Point3 corner[3];
    int k = 0;
    for (const orgQhull::QhullVertex& v : f.vertices()) {
      if (k == 3) break;
      const double* c = v.point().coordinates();
      corner[k++] = Point3(c[0], c[1], c[2]);
    }
    const double v = std::abs((corner[0] - inside).dot((corner[1] - inside).cross(corner[2] - inside))) / 6.0;
    s.volume += v;
    moment += v * 0.25 * (inside + corner[0] + corner[1] + corner[2]);
  }
  s.centroid = moment / s.volume;
  for (const auto& v : s.vertices) s.reach = std::max(s.reach, (v - s.centroid).norm());
  return s;
}

// A uniformly random rotation (Shoemake's unit quaternion from three uniforms).
template <class Rng>
Eigen::Matrix3d random_rotation(Rng& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double a = u(rng), b = 2.0 * M_PI * u(rng), c = 2.0 * M_PI * u(rng);
  const Eigen::Quaterniond q(std::sqrt(a) * std::cos(c), std::sqrt(1.0 - a) * std::sin(b),
                             std::sqrt(1.0 - a) * std::cos(b), std::sqrt(a) * std::sin(c));
  return q.toRotationMatrix();
}

// A stone of mean radius R0 with its centroid at the origin.
template <class Rng>
Stone3 random_stone3(double mean_radius, const StoneShape3& shape, Rng& rng) {
  shape.validate();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> count(shape.min_vertices, shape.max_vertices);
  const int n = count(rng);
  const double spacing = std::sqrt(4.0 * M_PI / n), golden = M_PI * (3.0 - std::sqrt(5.0));
  const Eigen::Matrix3d turn = random_rotation(rng);
  std::vector<Point3> points;
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n, rho = std::sqrt(1.0 - z * z), phi = golden * k;
    const Point3 e(rho * std::cos(phi), rho * std::sin(phi), z);
    // A tangent direction at random, and the move along it.
    const Point3 any = std::abs(e.x()) < 0.9 ? Point3::UnitX() : Point3::UnitY();
    const Point3 t1 = e.cross(any).normalized(), t2 = e.cross(t1);
    const double psi = 2.0 * M_PI * u(rng), angle = u(rng) * shape.angle_fluctuation * spacing;
    const Point3 dir = std::cos(angle) * e + std::sin(angle) * (std::cos(psi) * t1 + std::sin(psi) * t2);
    const double r = mean_radius * (1.0 + (2.0 * u(rng) - 1.0) * shape.radius_fluctuation);
    points.push_back(r * (turn * dir));
  }
  Stone3 s = convex_hull_stone(points);
  s.translate(-s.centroid);
  s.centroid = Point3::Zero();  // exactly
  return s;
}

// The stone's section by the plane z = z0: a convex polygon, empty where
// the plane misses it (the faces' half-planes clipping a square about it).
inline Polygon section_at_z(const Stone3& s, double z0) {
  const double big = 2.0 * s.reach + 1.0;
  std::vector<Point> poly{{s.centroid.x() - big, s.centroid.y() - big}, {s.centroid.x() + big, s.centroid.y() - big},
                          {s.centroid.x() + big, s.centroid.y() + big}, {s.centroid.x() - big, s.centroid.y() + big}};
  for (const auto& p : s.planes) {
    // Inside: a x + b y <= c on the plane.
    const double a = p[0], b = p[1], c = p[3] - p[2] * z0;
    std::vector<Point> kept;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Point& u = poly[k];
      const Point& v = poly[(k + 1) % poly.size()];
      const double fu = a * u.x() + b * u.y() - c, fv = a * v.x() + b * v.y() - c;
      if (fu <= 0.0) kept.push_back(u);
      if ((fu < 0.0 && fv > 0.0) || (fu > 0.0 && fv < 0.0)) kept.push_back(u + (fu / (fu - fv)) * (v - u));
    }
    poly.swap(kept);
    if (poly.size() < 3) return {};
  }
  Polygon out;
  out.vertices = poly;
  return out;
}

namespace detail {

// A stone as libccd sees it: its vertices, shifted (a periodic image).
struct ShiftedStone {
  const Stone3* stone;
  Point3 shift;
};
// The vertex farthest along d: a convex hull's support point.
inline const Point3& farthest_along(const std::vector<Point3>& vertices, const Point3& d) {
  const Point3* best = &vertices.front();
  double most = best->dot(d);
  for (const auto& v : vertices)
    if (v.dot(d) > most) most = v.dot(d), best = &v;
  return *best;
}
inline void stone_support(const void* object, const ccd_vec3_t* direction, ccd_vec3_t* out) {
  const auto* s = static_cast<const ShiftedStone*>(object);
  const Point3 d(ccdVec3X(direction), ccdVec3Y(direction), ccdVec3Z(direction));
  const Point3 p = farthest_along(s->stone->vertices, d) + s->shift;
  ccdVec3Set(out, p.x(), p.y(), p.z());
}
inline void stone_centre(const void* object, ccd_vec3_t* out) {
  const auto* s = static_cast<const ShiftedStone*>(object);
  const Point3 c = s->stone->centroid + s->shift;
  ccdVec3Set(out, c.x(), c.y(), c.z());
}

}  // namespace detail

// Whether two stones overlap, b shifted by `shift` (a periodic image):
// their centroids' distance against the reaches first, then libccd's
// Minkowski portal refinement on the hull vertices.
inline bool stones_overlap(const Stone3& a, const Stone3& b, const Point3& shift = Point3::Zero()) {
  const double reach = a.reach + b.reach;
  if ((b.centroid + shift - a.centroid).squaredNorm() >= reach * reach) return false;
  detail::ShiftedStone sa{&a, Point3::Zero()}, sb{&b, shift};
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = detail::stone_support;
  ccd.support2 = detail::stone_support;
  ccd.center1 = detail::stone_centre;
  ccd.center2 = detail::stone_centre;
  ccd.max_iterations = 200;
  ccd.mpr_tolerance = 1e-10;
  return ccdMPRIntersect(&sa, &sb, &ccd) != 0;
}

// From x inside the stone, along the unit direction u: the distance to its
// surface (the nearest face plane the ray leaves through).
inline double distance_to_surface(const Stone3& s, const Point3& x, const Point3& u) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : s.planes) {
    const double along = p.head<3>().dot(u);
    if (along > 0.0) best = std::min(best, (p[3] - p.head<3>().dot(x)) / along);
  }
  return best;
}

}  // namespace vrut
