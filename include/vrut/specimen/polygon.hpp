#pragma once
// Random polygonal aggregates (docs/method.md section 4) and the geometry placement
// needs. Host-only; Eigen 2-vectors; lengths in mm.
//
// n vertices, n uniform in [4, 10]; vertex k at radius r_k = R0 + (2 lambda - 1) R
// and angle step dtheta_k = 2 pi [1 + (2 eta - 1) delta] / n, the steps
// scaled to sum to 2 pi; lambda, eta uniform in [0, 1]; a random rotation.
// With R < R0 every radius is positive and the vertices go round once in
// angular order, so the polygon is simple (star-shaped about its centre).
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace vrut {

using Point = Eigen::Vector2d;

struct ShapeParameters {
  double radius_fluctuation = 0.25;  // R / R0, in [0, 1)
  double angle_fluctuation = 0.4;    // delta, in [0, 1]
  int min_vertices = 4, max_vertices = 10;

  void validate() const {
    if (!(radius_fluctuation >= 0.0 && radius_fluctuation < 1.0))
      throw std::invalid_argument("radius fluctuation R/R0 must lie in [0, 1)");
    if (!(angle_fluctuation >= 0.0 && angle_fluctuation <= 1.0))
      throw std::invalid_argument("angle fluctuation delta must lie in [0, 1]");
    if (min_vertices < 3 || max_vertices < min_vertices) throw std::invalid_argument("bad vertex count range");
  }
};

struct Polygon {
  std::vector<Point> vertices;  // counter-clockwise, absolute coordinates

  double area() const {
    double a = 0.0;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      const Point& p = vertices[k];
      const Point& q = vertices[(k + 1) % vertices.size()];
      a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
  }
  Point centroid_of_vertices() const {
    Point c = Point::Zero();
    for (const Point& p : vertices) c += p;
    return c / static_cast<double>(vertices.size());
  }
  void translate(const Point& d) {
    for (Point& p : vertices) p += d;
  }
};

// Vertices about the origin.
template <class Rng>
Polygon random_polygon(double mean_radius, const ShapeParameters& shape, Rng& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> count(shape.min_vertices, shape.max_vertices);
  const int n = count(rng);
  std::vector<double> step(n), radius(n);
  double total = 0.0;
  for (int k = 0; k < n; ++k) {
    radius[k] = mean_radius * (1.0 + (2.0 * u(rng) - 1.0) * shape.radius_fluctuation);
    step[k] = 2.0 * M_PI * (1.0 + (2.0 * u(rng) - 1.0) * shape.angle_fluctuation) / n;
    step[k] = std::max(step[k], 1e-3);  // delta = 1 may draw a zero step
    total += step[k];
  }
  double theta = 2.0 * M_PI * u(rng);
  Polygon poly;
  for (int k = 0; k < n; ++k) {
    poly.vertices.emplace_back(radius[k] * std::cos(theta), radius[k] * std::sin(theta));
    theta += step[k] * 2.0 * M_PI / total;
  }
  return poly;
}

inline bool point_in_polygon(const Polygon& poly, const Point& p) {
  bool inside = false;
  const auto& v = poly.vertices;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
        p.x() < (v[j].x() - v[i].x()) * (p.y() - v[i].y()) / (v[j].y() - v[i].y()) + v[i].x())
      inside = !inside;
  }
  return inside;
}

namespace detail {
inline double orient(const Point& a, const Point& b, const Point& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}
// Closed segments ab and cd share a point.
inline bool segments_intersect(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  auto on = [](const Point& p, const Point& q, const Point& r, double o) {
    return o == 0.0 && std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4);
}
}  // namespace detail

// Two simple polygons overlap (share any point).
inline bool polygons_overlap(const Polygon& a, const Polygon& b) {
  const auto& va = a.vertices;
  const auto& vb = b.vertices;
  for (std::size_t i = 0; i < va.size(); ++i)
    for (std::size_t j = 0; j < vb.size(); ++j)
      if (detail::segments_intersect(va[i], va[(i + 1) % va.size()], vb[j], vb[(j + 1) % vb.size()])) return true;
  return point_in_polygon(a, vb[0]) || point_in_polygon(b, va[0]);
}

// The least distance between two polygons that do not overlap: it lies
// between a vertex of one and an edge of the other.
inline double polygon_distance(const Polygon& a, const Polygon& b) {
  auto vertex_to_edges = [](const Polygon& from, const Polygon& to) {
    double best = std::numeric_limits<double>::infinity();
    const auto& v = to.vertices;
    for (const Point& p : from.vertices)
      for (std::size_t k = 0; k < v.size(); ++k) {
        const Point e = v[(k + 1) % v.size()] - v[k];
        const double t = std::clamp((p - v[k]).dot(e) / e.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (v[k] + t * e - p).norm());
      }
    return best;
  };
  return std::min(vertex_to_edges(a, b), vertex_to_edges(b, a));
}

// No two non-adjacent edges meet.
inline bool is_simple(const Polygon& p) {
  const auto& v = p.vertices;
  const std::size_t n = v.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a vertex
      if (detail::segments_intersect(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) return false;
    }
  return true;
}

}  // namespace vrut
