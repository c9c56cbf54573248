#pragma once
// Monte Carlo placement of polyhedral stones in a 3D specimen (docs/specimen.md,
// "In 3D"). Host-only; mm. Needs the target vrut::stones3.
//
// The box is width x height (x, y; stones lie inside) x depth (z, periodic:
// a stone may cross the back face and come in at the front). In 3D the mass
// gradation gives the stones directly, no stereology: class i holds the
// volume fraction P_i of the mix (Stereology::volume_fraction), and stones of
// that class (a diameter D uniform in the class, R0 = D / 2, a random
// stone3.hpp shape) are drawn until their volume reaches P_i of the box, to
// within half a stone. So the number per class is the class's volume over
// its stones' mean volume. They are placed largest first, each at random
// positions (the shape is already turned at random) until it overlaps
// nothing; a stone with no room after `attempts` tries gets rounds of
// jiggling, as in 2D (placement.hpp) but local: each round draws a point at
// random, moves and turns the stones around it a little at random (kept
// where they fit), then tries the stone near that point. Jiggling every
// placed stone at each round, as 2D does, took twice as long for the same
// specimens. progress(placed, total) is told of every stone placed.
#include <vrut/specimen/stereology.hpp>
#include <vrut/specimen/stone3.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct PlacedStone3 {
  int size_class = 0;
  double diameter = 0.0;  // drawn in its class: twice the mean radius R0, mm
  Stone3 shape;           // placed: its centroid's z within [0, depth)
};

struct PlacementSettings3 {
  double width = 300.0, height = 50.0, depth = 40.0;  // mm; depth periodic, at least twice the largest stone
  StoneShape3 shape;
  int attempts = 3000;      // random tries per stone before jiggling
  int jiggle_rounds = 4000;  // at most, per stone that finds no room
};

struct Placement3 {
  std::vector<PlacedStone3> stones;
  double depth = 0.0;
  double target_fraction = 0.0, achieved_fraction = 0.0;  // stones' volume over the box's
  int jammed = 0;  // stones that found no room in their random tries (then jiggled)
  long compaction_steps = 0;  // the compaction's (compaction3.hpp); 0: random addition alone
  // A compaction that jammed under its lid (compaction3.hpp): the stone
  // pairs, and the stones and walls, left nearer than its clearance of
  // 0.001 mm, none overlapping. 0 where the stones settled.
  long pairs_within_clearance = 0, stones_within_clearance_of_a_wall = 0;
};

namespace detail {

// Stones by the cells their bounding boxes cover, z wrapped.
class StoneGrid3 {
 public:
  StoneGrid3(double width, double height, double depth, double cell)
      : cell_(cell), nx_(std::max(1, static_cast<int>(width / cell) + 1)),
        ny_(std::max(1, static_cast<int>(height / cell) + 1)), nz_(std::max(1, static_cast<int>(depth / cell))),
        depth_(depth), cells_(static_cast<std::size_t>(nx_) * ny_ * nz_) {}

  // f(id) for every stone in the cells the box covers, each once; stops at the first true.
  template <class F>
  bool any_near(const Eigen::AlignedBox3d& box, F&& f) {
    ++stamp_;
    bool hit = false;
    visit(box, [&](std::vector<int>& cell) {
      for (int id : cell) {
        if (hit) return;
        if (seen_.size() <= static_cast<std::size_t>(id)) seen_.resize(id + 1, 0);
        if (seen_[id] == stamp_) continue;
        seen_[id] = stamp_;
        hit = f(id);
      }
    });
    return hit;
  }
  void insert(int id, const Eigen::AlignedBox3d& box) {
    visit(box, [&](std::vector<int>& cell) { cell.push_back(id); });
  }
  void remove(int id, const Eigen::AlignedBox3d& box) {
    visit(box, [&](std::vector<int>& cell) { cell.erase(std::remove(cell.begin(), cell.end(), id), cell.end()); });
  }

 private:
  template <class F>
  void visit(const Eigen::AlignedBox3d& box, F&& f) {
    const int x0 = clamp(box.min().x(), nx_), x1 = clamp(box.max().x(), nx_);
    const int y0 = clamp(box.min().y(), ny_), y1 = clamp(box.max().y(), ny_);
    const int z0 = static_cast<int>(std::floor(box.min().z() / depth_ * nz_));
    const int z1 = std::min(z0 + nz_ - 1, static_cast<int>(std::floor(box.max().z() / depth_ * nz_)));
    for (int z = z0; z <= z1; ++z) {
      const int wz = ((z % nz_) + nz_) % nz_;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) f(cells_[(static_cast<std::size_t>(wz) * ny_ + y) * nx_ + x]);
    }
  }
  int clamp(double v, int n) const { return std::clamp(static_cast<int>(v / cell_), 0, n - 1); }
  double cell_;
  int nx_, ny_, nz_;
  double depth_;
  std::vector<std::vector<int>> cells_;
  std::vector<long> seen_;
  long stamp_ = 0;
};

inline Stone3 turned(const Stone3& s, const Eigen::Matrix3d& rotation) {
  Stone3 out = s;
  for (auto& v : out.vertices) v = s.centroid + rotation * (v - s.centroid);
  for (auto& p : out.planes) {
    const Point3 n = rotation * p.head<3>();
    p = Eigen::Vector4d(n.x(), n.y(), n.z(), n.dot(s.centroid) + (p[3] - p.head<3>().dot(s.centroid)));
  }
  return out;
}

// A small random rotation: about a random axis, by up to `angle` radians.
template <class Rng>
Eigen::Matrix3d small_rotation(double angle, Rng& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Drawn one by one, z first: a constructor's arguments are evaluated in no
  // set order (gcc went right to left, clang left to right), so a seed gave
  // another specimen under clang. Fixed in gcc's order, which every specimen
  // and pin was made with; the same below.
  const double draw_z = g(rng), draw_y = g(rng), draw_x = g(rng);
  const Point3 axis = Point3(draw_x, draw_y, draw_z).normalized();
  return Eigen::AngleAxisd(angle * u(rng), axis).toRotationMatrix();
}

}  // namespace detail

// The stones of every class, largest first.
template <class Rng>
std::vector<PlacedStone3> draw_stones3(const Stereology& st, double box_volume, const StoneShape3& shape, Rng& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<PlacedStone3> drawn;
  for (std::size_t i = 0; i < st.classes.size(); ++i) {
    const double target = st.volume_fraction[i] * box_volume;
    double volume = 0.0;
    while (true) {
      PlacedStone3 s;
      s.size_class = static_cast<int>(i);
      s.diameter = st.classes[i].lower_mm + u(rng) * (st.classes[i].upper_mm - st.classes[i].lower_mm);
      s.shape = random_stone3(0.5 * s.diameter, shape, rng);
      if (volume + 0.5 * s.shape.volume > target) break;
      volume += s.shape.volume;
      drawn.push_back(std::move(s));
    }
  }
  std::stable_sort(drawn.begin(), drawn.end(),
                   [](const PlacedStone3& a, const PlacedStone3& b) { return a.shape.volume > b.shape.volume; });
  return drawn;
}

template <class Rng>
Placement3 place_stones3(const Stereology& st, const PlacementSettings3& ps, Rng& rng,
                         const std::function<void(std::size_t placed, std::size_t total)>& progress = {}) {
  ps.shape.validate();
  if (!(ps.width > 0.0 && ps.height > 0.0 && ps.depth > 0.0))
    throw std::invalid_argument("the 3D specimen must have a positive width, height and depth");
  const double box_volume = ps.width * ps.height * ps.depth;
  Placement3 out;
  out.depth = ps.depth;
  out.target_fraction = st.coarse_volume_fraction;
  std::vector<PlacedStone3> todo = draw_stones3(st, box_volume, ps.shape, rng);
  // The depth holds at least two of the largest stones (by their drawn
  // diameter), so that a stone meets stones, not its own image.
  double largest = 0.0, widest = 0.0;
  for (const auto& s : todo) largest = std::max(largest, s.diameter), widest = std::max(widest, 2.0 * s.shape.reach);
  if (largest > 0.5 * ps.depth || widest > ps.height || widest > ps.width) {
    std::ostringstream msg;
    msg << "the 3D specimen is too small for its stones: the largest is " << largest << " mm (" << widest
        << " mm across its corners); the depth (" << ps.depth << " mm) must be at least twice " << largest
        << ", the width and height at least " << widest;
    throw std::invalid_argument(msg.str());
  }

  detail::StoneGrid3 grid(ps.width, ps.height, ps.depth, 4.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double placed_volume = 0.0;
  // Whether a stone fits where it is (skip: a placed stone being moved).
  std::vector<Eigen::AlignedBox3d> placed_bounds;  // of out.stones, kept with them
  auto fits = [&](const Stone3& c, int skip = -1) {
    const Eigen::AlignedBox3d box = c.bounds();
    if (box.min().x() < 0.0 || box.min().y() < 0.0 || box.max().x() > ps.width || box.max().y() > ps.height)
      return false;
    return !grid.any_near(box, [&](int id) {
      if (id == skip) return false;
      const Stone3& other = out.stones[id].shape;
      // The other and its images across the periodic depth: boxes that do
      // not meet pass most of them over before the overlap test.
      for (double image : {0.0, -ps.depth, ps.depth}) {
        const Point3 shift(0.0, 0.0, image);
        const Eigen::AlignedBox3d other_box(placed_bounds[id].min() + shift, placed_bounds[id].max() + shift);
        if (other_box.intersects(box) && stones_overlap(c, other, shift)) return true;
      }
      return false;
    });
  };
  // Random tries with the centroid in `where` (z taken modulo the depth),
  // as far as the walls let the stone lie inside.
  const Eigen::AlignedBox3d everywhere(Point3(-1e300, -1e300, 0.0), Point3(1e300, 1e300, ps.depth));
  auto random_tries = [&](PlacedStone3& s, int tries, const Eigen::AlignedBox3d& where) {
    const Eigen::AlignedBox3d local = s.shape.bounds();  // about its centroid, at the origin
    const double x0 = std::max(-local.min().x(), where.min().x());
    const double x1 = std::min(ps.width - local.max().x(), where.max().x());
    const double y0 = std::max(-local.min().y(), where.min().y());
    const double y1 = std::min(ps.height - local.max().y(), where.max().y());
    if (x1 < x0 || y1 < y0) return false;
    for (int t = 0; t < tries; ++t) {
      Stone3 c = s.shape;
      double z = where.min().z() + u(rng) * where.sizes().z();
      z -= ps.depth * std::floor(z / ps.depth);
      const double draw_y = u(rng), draw_x = u(rng);  // in this order: see small_rotation
      c.translate(Point3(x0 + draw_x * (x1 - x0), y0 + draw_y * (y1 - y0), z));
      if (fits(c)) {
        s.shape = std::move(c);
        return true;
      }
    }
    return false;
  };
  auto wrap = [&](Stone3& c) {
    const double z = c.centroid.z();
    if (z < 0.0 || z >= ps.depth) c.translate(Point3(0.0, 0.0, -ps.depth * std::floor(z / ps.depth)));
  };
  // One sweep of Monte Carlo moves over the placed stones that reach into
  // `region`, in random order: each moved by up to `reach` of its diameter
  // and turned by up to `reach` radians, kept where it fits. Returns the
  // fraction kept.
  auto jiggle = [&](double reach, const Eigen::AlignedBox3d& region) {
    std::vector<int> order;
    grid.any_near(region, [&](int id) {
      order.push_back(id);
      return false;
    });
    std::sort(order.begin(), order.end());  // the grid's order is its cells'
    std::shuffle(order.begin(), order.end(), rng);
    int kept = 0;
    for (int id : order) {
      PlacedStone3& b = out.stones[id];
      Stone3 moved = detail::turned(b.shape, detail::small_rotation(reach, rng));
      const double draw_z = u(rng), draw_y = u(rng), draw_x = u(rng);  // in this order: see small_rotation
      moved.translate(reach * b.diameter * Point3(2.0 * draw_x - 1.0, 2.0 * draw_y - 1.0, 2.0 * draw_z - 1.0));
      wrap(moved);
      if (!fits(moved, id)) continue;
      grid.remove(id, placed_bounds[id]);
      placed_bounds[id] = moved.bounds();
      grid.insert(id, placed_bounds[id]);
      b.shape = std::move(moved);
      ++kept;
    }
    return order.empty() ? 0.0 : static_cast<double>(kept) / order.size();
  };
  double reach = 0.05;  // adapted so that about a third of the moves are kept
  for (std::size_t k = 0; k < todo.size(); ++k) {
    PlacedStone3 s = todo[k];
    bool placed = random_tries(s, ps.attempts, everywhere);
    out.jammed += placed ? 0 : 1;
    // Jammed: rounds of jiggling about a point drawn at random, each
    // followed by tries about that point (the stones there were moved).
    for (int round = 0; round < ps.jiggle_rounds && !placed; ++round) {
      const double draw_z = u(rng), draw_y = u(rng), draw_x = u(rng);  // in this order: see small_rotation
      const Point3 at(draw_x * ps.width, draw_y * ps.height, draw_z * ps.depth);
      const Point3 half = Point3::Constant(1.5 * s.diameter);
      const double kept = jiggle(reach, Eigen::AlignedBox3d(at - half, at + half));
      reach = std::clamp(reach * (kept > 0.35 ? 1.25 : 0.8), 1e-3, 0.5);
      const Point3 near = Point3::Constant(0.5 * s.diameter);
      placed = random_tries(s, std::max(50, ps.attempts / 10), Eigen::AlignedBox3d(at - near, at + near));
    }
    if (!placed) {
      std::ostringstream msg;
      msg << "cannot reach the stones' volume fraction " << out.target_fraction << ": placed " << k << " of "
          << todo.size() << " stones (volume fraction " << placed_volume / box_volume << "), no room for one of "
          << s.diameter << " mm";
      throw std::runtime_error(msg.str());
    }
    placed_bounds.push_back(s.shape.bounds());
    grid.insert(static_cast<int>(out.stones.size()), placed_bounds.back());
    placed_volume += s.shape.volume;
    out.stones.push_back(std::move(s));
    if (progress) progress(out.stones.size(), todo.size());
  }
  out.achieved_fraction = placed_volume / box_volume;
  return out;
}

}  // namespace vrut
