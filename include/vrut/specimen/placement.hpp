#pragma once
// Monte Carlo placement of polygonal aggregates in the section (docs/method.md section 5.1).
// Host-only; mm.
//
// The aggregates to place are drawn first: a class with probability
// proportional to its N_A,j, a diameter uniform in the class, a shape; until
// their area reaches the target area fraction (near the end, a draw that
// would overshoot by more than the tolerance is redrawn). They are then
// placed largest first, each at random positions and rotations until it
// overlaps nothing and lies inside the section. A piece that finds no room in
// `attempts` random tries (the random tries jam first in the dense mixes)
// then gets, by PlacementSettings::method:
//   scan    a systematic scan of positions and rotations, from a random
//           origin (the method's first version; not random);
//   jiggle  rounds of Monte Carlo moves of the pieces already placed (each
//           moved and turned a little at random, kept only where it fits),
//           which open room without preferring any place, each round
//           followed by more random tries: random throughout.
// A piece that finds no room either way stops the generation with a message
// saying what was reached.
#include <vrut/specimen/polygon.hpp>
#include <vrut/specimen/stereology.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct Aggregate {
  int size_class = 0;
  double diameter = 0.0;  // drawn section diameter (2 R0), mm
  Polygon polygon;        // placed vertices
  double area = 0.0;
};

enum class PlacementMethod { scan, jiggle };

struct PlacementSettings {
  double width = 300.0, height = 50.0;  // mm
  ShapeParameters shape;
  int attempts = 3000;                  // random tries per aggregate before the scan or the jiggling
  double tolerance = 0.002;             // area-fraction tolerance of the drawn set
  PlacementMethod method = PlacementMethod::scan;
  int jiggle_rounds = 400;              // at most, per piece that finds no room
  // Least gap between two aggregates, mm: a film of mastic that keeps
  // stones from touching at the start. 0: they may touch (the method).
  double binder_film = 0.0;
};

struct Placement {
  std::vector<Aggregate> aggregates;
  double target_fraction = 0.0, achieved_fraction = 0.0;
  int jammed = 0;  // pieces that found no room in their random tries (then scanned or jiggled)
};

namespace detail {

class AggregateGrid {
 public:
  AggregateGrid(double width, double height, double cell)
      : cell_(cell), nx_(static_cast<int>(width / cell) + 1), ny_(static_cast<int>(height / cell) + 1),
        cells_(static_cast<std::size_t>(nx_) * ny_) {}

  template <class F>
  bool any_in_box(const Eigen::AlignedBox2d& box, F&& test) {
    ++stamp_;
    for (int iy = clampy(box.min().y()); iy <= clampy(box.max().y()); ++iy)
      for (int ix = clampx(box.min().x()); ix <= clampx(box.max().x()); ++ix)
        for (int id : cells_[static_cast<std::size_t>(iy) * nx_ + ix]) {
          if (seen_.size() <= static_cast<std::size_t>(id)) seen_.resize(id + 1, 0);
          if (seen_[id] == stamp_) continue;
          seen_[id] = stamp_;
          if (test(id)) return true;
        }
    return false;
  }
  void insert(int id, const Eigen::AlignedBox2d& box) {
    for (int iy = clampy(box.min().y()); iy <= clampy(box.max().y()); ++iy)
      for (int ix = clampx(box.min().x()); ix <= clampx(box.max().x()); ++ix)
        cells_[static_cast<std::size_t>(iy) * nx_ + ix].push_back(id);
  }
  void remove(int id, const Eigen::AlignedBox2d& box) {
    for (int iy = clampy(box.min().y()); iy <= clampy(box.max().y()); ++iy)
      for (int ix = clampx(box.min().x()); ix <= clampx(box.max().x()); ++ix) {
        auto& cell = cells_[static_cast<std::size_t>(iy) * nx_ + ix];
        cell.erase(std::remove(cell.begin(), cell.end(), id), cell.end());
      }
  }

 private:
  int clampx(double x) const { return std::clamp(static_cast<int>(x / cell_), 0, nx_ - 1); }
  int clampy(double y) const { return std::clamp(static_cast<int>(y / cell_), 0, ny_ - 1); }
  double cell_;
  int nx_, ny_;
  std::vector<std::vector<int>> cells_;
  std::vector<long> seen_;
  long stamp_ = 0;
};

inline Eigen::AlignedBox2d bounds(const Polygon& p) {
  Eigen::AlignedBox2d b;
  for (const Point& v : p.vertices) b.extend(v);
  return b;
}

inline Polygon rotated(const Polygon& p, double angle) {
  const Eigen::Rotation2Dd r(angle);
  Polygon out;
  for (const Point& v : p.vertices) out.vertices.push_back(r * v);
  return out;
}

}  // namespace detail

template <class Rng>
std::vector<Aggregate> draw_aggregates(const Stereology& st, double target_area, double tolerance_area,
                                       const ShapeParameters& shape, Rng& rng) {
  std::discrete_distribution<int> pick(st.sections_per_area.begin(), st.sections_per_area.end());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Aggregate> drawn;
  double total = 0.0;
  int redraws = 0;
  while (total < target_area - tolerance_area) {
    Aggregate a;
    a.size_class = pick(rng);
    const SizeClass& c = st.classes[a.size_class];
    a.diameter = c.lower_mm + u(rng) * (c.upper_mm - c.lower_mm);
    a.polygon = random_polygon(0.5 * a.diameter, shape, rng);
    a.area = a.polygon.area();
    if (total + a.area > target_area + tolerance_area && ++redraws < 100000) continue;
    total += a.area;
    drawn.push_back(std::move(a));
  }
  return drawn;
}

template <class Rng>
Placement place_aggregates(const Stereology& st, const PlacementSettings& ps, Rng& rng) {
  ps.shape.validate();
  if (!(ps.binder_film >= 0.0 && ps.binder_film < 0.5 * std::min(ps.width, ps.height)))
    throw std::invalid_argument("the binder film must be at least 0 mm and well inside the section");
  if (!(ps.width > 0.0 && ps.height > 0.0)) throw std::invalid_argument("the section must have a positive size");
  const double section = ps.width * ps.height;
  Placement out;
  out.target_fraction = st.target_area_fraction;
  std::vector<Aggregate> todo =
      draw_aggregates(st, st.target_area_fraction * section, ps.tolerance * section, ps.shape, rng);
  std::stable_sort(todo.begin(), todo.end(), [](const Aggregate& a, const Aggregate& b) { return a.diameter > b.diameter; });

  detail::AggregateGrid grid(ps.width, ps.height, 4.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double placed_area = 0.0;
  // skip: a placed piece that is being moved, which must not meet itself.
  const double film = ps.binder_film;
  auto fits = [&](const Polygon& candidate, const Eigen::AlignedBox2d& box, int skip = -1) {
    if (box.min().x() < 0.0 || box.min().y() < 0.0 || box.max().x() > ps.width || box.max().y() > ps.height)
      return false;
    const Eigen::AlignedBox2d reach(box.min() - Point(film, film), box.max() + Point(film, film));
    return !grid.any_in_box(reach, [&](int id) {
      const Polygon& other = out.aggregates[id].polygon;
      return id != skip && detail::bounds(other).intersects(reach) &&
             (polygons_overlap(other, candidate) || (film > 0.0 && polygon_distance(other, candidate) < film));
    });
  };
  auto random_tries = [&](Aggregate& a, int tries) {
    for (int t = 0; t < tries; ++t) {
      Polygon c = detail::rotated(a.polygon, 2.0 * M_PI * u(rng));
      const Eigen::AlignedBox2d local = detail::bounds(c);
      const Point lo(-local.min().x(), -local.min().y());
      const Point span(ps.width - local.sizes().x(), ps.height - local.sizes().y());
      if (span.x() < 0.0 || span.y() < 0.0) return false;
      // Drawn one by one, y first: a constructor's arguments are evaluated in
      // no set order (gcc went right to left, clang left to right), so a
      // seed gave another specimen under clang. Fixed in gcc's order, which
      // every specimen and pin was made with.
      const double draw_y = u(rng), draw_x = u(rng);
      c.translate(lo + Point(draw_x * span.x(), draw_y * span.y()));
      if (fits(c, detail::bounds(c))) {
        a.polygon = std::move(c);
        return true;
      }
    }
    return false;
  };
  // One Monte Carlo sweep: every placed piece, in random order, moved by up
  // to `reach` of its diameter and turned by up to `reach` radians, kept
  // where it fits. Returns the fraction of moves kept.
  auto jiggle = [&](double reach) {
    std::vector<int> order(out.aggregates.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::shuffle(order.begin(), order.end(), rng);
    int kept = 0;
    for (int id : order) {
      Aggregate& b = out.aggregates[id];
      const Point c = b.polygon.centroid_of_vertices();
      Polygon moved = b.polygon;
      moved.translate(-c);
      moved = detail::rotated(moved, reach * (2.0 * u(rng) - 1.0));
      const double draw_y = u(rng), draw_x = u(rng);  // in this order: see random_tries
      moved.translate(c + reach * b.diameter * Point(2.0 * draw_x - 1.0, 2.0 * draw_y - 1.0));
      const Eigen::AlignedBox2d box = detail::bounds(moved);
      if (!fits(moved, box, id)) continue;
      grid.remove(id, detail::bounds(b.polygon));
      grid.insert(id, box);
      b.polygon = std::move(moved);
      ++kept;
    }
    return order.empty() ? 0.0 : static_cast<double>(kept) / order.size();
  };
  double reach = 0.05;  // adapted so that about a third of the moves are kept
  for (std::size_t k = 0; k < todo.size(); ++k) {
    Aggregate a = todo[k];
    bool placed = random_tries(a, ps.attempts);
    out.jammed += placed ? 0 : 1;
    for (int round = 0; ps.method == PlacementMethod::jiggle && round < ps.jiggle_rounds && !placed; ++round) {
      const double kept = jiggle(reach);
      reach = std::clamp(reach * (kept > 0.35 ? 1.25 : 0.8), 1e-3, 0.5);
      placed = random_tries(a, std::max(50, ps.attempts / 10));
    }
    // Systematic scan: 12 rotations, positions on a grid of a quarter diameter, from a random origin.
    const double step = std::max(0.25, 0.25 * a.diameter);
    for (int rot = 0; ps.method == PlacementMethod::scan && rot < 12 && !placed; ++rot) {
      Polygon base = detail::rotated(a.polygon, M_PI * rot / 6.0 + u(rng));
      const Eigen::AlignedBox2d local = detail::bounds(base);
      base.translate(Point(-local.min().x(), -local.min().y()));
      const double ox = u(rng) * step, oy = u(rng) * step;
      for (double y = oy; y + local.sizes().y() <= ps.height && !placed; y += step)
        for (double x = ox; x + local.sizes().x() <= ps.width && !placed; x += step) {
          Polygon c = base;
          c.translate(Point(x, y));
          if (fits(c, detail::bounds(c))) a.polygon = std::move(c), placed = true;
        }
    }
    if (!placed) {
      std::ostringstream msg;
      msg << "cannot reach the aggregate area fraction " << st.target_area_fraction << ": placed " << k << " of "
          << todo.size() << " aggregates (area fraction " << placed_area / section << "), no room for one of "
          << a.diameter << " mm";
      throw std::runtime_error(msg.str());
    }
    grid.insert(static_cast<int>(out.aggregates.size()), detail::bounds(a.polygon));
    placed_area += a.area;
    out.aggregates.push_back(std::move(a));
  }
  out.achieved_fraction = placed_area / section;
  return out;
}

}  // namespace vrut
