#pragma once
// Compaction of a 3D specimen's stones (docs/specimen.md, "Compaction"):
// where random addition jams short of the stones' volume fraction (3#), the
// stones are pushed together as a real slab's are. Host-only (std::thread
// where `threads` > 1, with the same packing as one thread); mm.
// Needs the target vrut::stones3.
//
//   1. Random addition (placement3.hpp) places the same stones loosely, at
//      `loose_fraction`, in a box as much taller as that needs.
//   2. A lid comes down at a constant speed to the specimen's height. The
//      stones move as rigid bodies on soft, frictionless contacts: a spring
//      on the depth of each overlap (libccd's Minkowski portal refinement
//      gives its depth, direction and point) with a dashpot beside it; the
//      floor, the two ends and the lid push each vertex that crosses them.
//   3. The lid held, the stones settle with a little drag on their motion
//      until no two overlap and none crosses a wall (kept `clearance`
//      apart, below); the result is checked with the placement's own
//      overlap test. A packing can jam under the lid with some pairs (or
//      stones and walls) nearer than the clearance and none overlapping:
//      after settle_steps it is kept, if the placement's test passes, and
//      Placement3 counts those pairs.
// The stones keep moving as they settle, which lets them leave the chains of
// contacts that stop a projection or a growth (docs/specimen.md). The
// dynamics is only a way to a packing, so it has no units of force: a mass
// of 1 per mm^3 and a spring of 1 per mm; the step follows from the lightest
// stone. Each stone turns about its centroid with an isotropic moment of
// inertia, a sphere's 2/5 m R^2 with R^2 0.6 times its vertices' mean square
// distance (about a polyhedron's own; the packing needs the stones to turn,
// not their exact inertia tensors).
#include <vrut/specimen/compaction3_parts.hpp>
#include <vrut/specimen/placement3.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace vrut {

struct CompactionSettings3 {
  double loose_fraction = 0.40;  // the stones' volume fraction in the taller box they are first placed in
  long lid_steps = 5000;         // steps for the lid to come down
  long settle_steps = 60000;     // at most, the lid held, until nothing overlaps
  double damping_ratio = 0.3;    // of a contact's critical damping
  double drag = 0.002;           // of each stone's velocity, taken off at each settling step
  // Host threads for the pairs' contacts and the stones' moves. Each pair's
  // contact is found alone and the forces are added in the pairs' order, so
  // the packing is the same, bit for bit, for any count.
  int threads = 1;

  void validate() const {
    if (!(loose_fraction > 0.0 && loose_fraction < 0.5))
      throw std::invalid_argument("the compaction's loose fraction must lie in (0, 0.5): random addition places "
                                  "the stones there");
    if (lid_steps < 1 || settle_steps < 1) throw std::invalid_argument("the compaction needs at least one step");
    if (!(damping_ratio >= 0.0 && damping_ratio < 1.0) || !(drag >= 0.0 && drag < 1.0))
      throw std::invalid_argument("the compaction's damping ratio and drag must lie in [0, 1)");
    if (threads < 1) throw std::invalid_argument("the compaction needs at least one thread");
  }
};

// The stones of `st` compacted into the box of `ps` (its depth periodic).
// placing(placed, total): the loose placement; compacting(step, total): the
// lid's and the settling's steps (total: the most there can be).
template <class Rng>
Placement3 compact_stones3(const Stereology& st, const PlacementSettings3& ps, const CompactionSettings3& cs,
                           Rng& rng, const std::function<void(std::size_t, std::size_t)>& placing = {},
                           const std::function<void(long, long)>& compacting = {}) {
  cs.validate();
  const double target = st.coarse_volume_fraction;
  const double width = ps.width, height = ps.height, depth = ps.depth;
  // The same stones, placed loosely in a taller box: the classes' fractions
  // of it scaled so that they draw the volume of the specimen's box.
  const double loose_height = height * std::max(1.0, target / cs.loose_fraction);
  Stereology loose = st;
  for (double& p : loose.volume_fraction) p *= height / loose_height;
  loose.coarse_volume_fraction *= height / loose_height;
  PlacementSettings3 tall = ps;
  tall.height = loose_height;
  const Placement3 placed = place_stones3(loose, tall, rng, placing);

  std::vector<detail::CompactedStone> stones(placed.stones.size());
  double lightest = std::numeric_limits<double>::infinity(), volume = 0.0;
  for (std::size_t i = 0; i < stones.size(); ++i) {
    detail::CompactedStone& s = stones[i];
    s.shape = placed.stones[i].shape;
    s.centre = s.shape.centroid;
    s.shape.translate(-s.centre);
    s.vertices = s.shape.vertices;
    s.mass = s.shape.volume;
    double mean_square = 0.0;
    for (const auto& v : s.vertices) mean_square += v.squaredNorm();
    s.inertia = 0.4 * s.mass * 0.6 * mean_square / static_cast<double>(s.vertices.size());
    s.reach = s.shape.reach;
    lightest = std::min(lightest, s.mass);
    volume += s.mass;
  }
  const double k = 1.0, dt = 0.15 * std::sqrt(lightest / k);
  // The stones are kept this far apart, and from the walls: libccd's
  // penetration finds no overlap for some pairs that merely touch, which its
  // overlap test (the placement's, used at the end) counts as overlapping.
  const double clearance = 1e-3;  // mm
  const double lid_speed = (loose_height - height) / static_cast<double>(cs.lid_steps);  // mm a step

  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd.support2 = detail::compacted_support;
  ccd.center1 = ccd.center2 = detail::compacted_centre;
  ccd.max_iterations = 100;
  ccd.mpr_tolerance = 1e-10;

  // The pairs whose centres lie within their reaches and two skins (with the
  // image across the depth), found again when a stone's centre has moved
  // half a skin: by the reach, not the bounding box, which changes as a
  // stone turns about its centre. A stone that wraps across the depth between
  // two searches moves its pairs' images (pair_image): otherwise its contacts
  // with the stones across the depth go unseen until the next search, and
  // late in the settling, when nothing moves far, that may never come
  // (docs/specimen.md, "Compaction").
  struct Pair {
    int a, b;
    double image;          // as found
    long a_wraps, b_wraps;  // the stones' wraps when found
    // A unit direction to test the pair along first: the last direction
    // MPR asked for when it found them apart, or their contact's normal
    // (along which b leaves a); zero until MPR first ran on the pair.
    Point3 apart = Point3::Zero();
    // How much nearer the two may come and still be apart: their gap when
    // last measured by the reach or along `apart`, less the least one
    // (below), less what they have moved since; not positive: test again
    // (MPR leaves it so).
    double slack = -1.0;
  };
  std::vector<Pair> pairs;
  std::vector<Point3> centre_at_search(stones.size());
  const double skin = 0.5;
  auto reach_box = [&](std::size_t i) {
    const Point3 half = Point3::Constant(stones[i].reach + skin);
    return Eigen::AlignedBox3d(stones[i].centre - half, stones[i].centre + half);
  };
  auto find_pairs = [&] {
    detail::StoneGrid3 grid(width, loose_height, depth, 4.0);
    for (std::size_t i = 0; i < stones.size(); ++i) {
      grid.insert(static_cast<int>(i), reach_box(i));
      centre_at_search[i] = stones[i].centre;
    }
    pairs.clear();
    for (std::size_t i = 0; i < stones.size(); ++i)
      grid.any_near(reach_box(i), [&](int j) {
        if (j <= static_cast<int>(i)) return false;
        const double reach = stones[i].reach + stones[j].reach + 2.0 * skin;
        for (double image : {0.0, -depth, depth})
          if ((stones[j].centre + Point3(0.0, 0.0, image) - stones[i].centre).squaredNorm() < reach * reach)
            pairs.push_back({static_cast<int>(i), j, image, stones[i].wraps, stones[j].wraps});
        return false;
      });
  };
  auto moved_far = [&] {
    for (std::size_t i = 0; i < stones.size(); ++i) {
      Point3 d = stones[i].centre - centre_at_search[i];
      d.z() -= depth * std::round(d.z() / depth);
      if (d.squaredNorm() > 0.25 * skin * skin) return true;
    }
    return false;
  };

  // The loads; returns whether anything overlaps.
  double lid = loose_height;
  auto wall = [&](detail::CompactedStone& s, int axis, double plane, double side) {
    // side +1: the stone keeps to coordinates above the plane; -1: below.
    bool crossed = false;
    for (const auto& v : s.vertices) {
      const double depth_in = side * (plane - (s.centre[axis] + v[axis])) + clearance;
      if (depth_in <= 0.0) continue;
      crossed = true;
      const double approach = side * (s.velocity[axis] + s.spin.cross(v)[axis]);
      Point3 f = Point3::Zero();
      f[axis] = side * (k * depth_in - 2.0 * cs.damping_ratio * std::sqrt(k * s.mass) * approach);
      s.force += f;
      s.torque += v.cross(f);
    }
    return crossed;
  };
  // Each pair's contact alone (in parallel), then the forces added in the
  // pairs' order, and the walls' to each stone (in parallel).
  std::vector<detail::PairContact> contacts;
  std::vector<char> crossing(stones.size());
  // Of the last loads, for the error below: the pairs within the clearance
  // and the deepest overlap among them.
  long touching_pairs = 0;
  double deepest = 0.0;
  auto loads = [&] {
    for (auto& s : stones) s.force.setZero(), s.torque.setZero();
    contacts.resize(pairs.size());
    // Most pairs within their reaches are apart, and most of those lie apart
    // along the direction they did last step, or stay apart for many steps
    // by what they have moved since: then no MPR. Only pairs apart by more
    // than least_gap are passed by, far beyond the rounding of their
    // vertices and well within where MPR finds them apart too, so the
    // packing is the same, bit for bit, as with MPR on every pair.
    const double margin = 0.5 * clearance, least_gap = 1e-6;  // mm
    detail::for_each_index(pairs.size(), cs.threads, [&](std::size_t q) {
      Pair& p = pairs[q];
      contacts[q].touching = false;
      const detail::CompactedStone& a = stones[p.a];
      const detail::CompactedStone& b = stones[p.b];
      p.slack -= a.moved + b.moved;
      if (p.slack > 0.0) return;
      const Point3 shift(0.0, 0.0, detail::pair_image(p.image, a.wraps - p.a_wraps, b.wraps - p.b_wraps, depth));
      const double reach = a.reach + b.reach + clearance;
      const double beyond_reach = (b.centre + shift - a.centre).norm() - reach - least_gap;
      if (beyond_reach >= 0.0) {
        p.slack = beyond_reach;
        return;
      }
      if (p.apart != Point3::Zero()) {
        const double gap = detail::gap_along(a, b, shift, p.apart) - 2.0 * margin - least_gap;
        if (gap > 0.0) {
          p.slack = gap;
          return;
        }
      }
      detail::ShiftedCompactedStone sa{&a, Point3::Zero(), margin}, sb{&b, shift, margin};
      ccd_real_t overlap_depth;
      ccd_vec3_t direction, point;
      if (ccdMPRPenetration(&sa, &sb, &ccd, &overlap_depth, &direction, &point) != 0) {
        const double length = sa.last_asked.norm();
        p.apart = length > 0.0 ? Point3(sa.last_asked / length) : Point3::Zero();
        return;
      }
      detail::PairContact& c = contacts[q];
      c.touching = true;
      c.depth = overlap_depth - clearance;
      // The direction moves b out of a.
      const Point3 n(ccdVec3X(&direction), ccdVec3Y(&direction), ccdVec3Z(&direction));
      p.apart = n.normalized();
      const Point3 at(ccdVec3X(&point), ccdVec3Y(&point), ccdVec3Z(&point));
      c.arm_a = at - a.centre, c.arm_b = at - (b.centre + shift);
      const Point3 relative = (b.velocity + b.spin.cross(c.arm_b)) - (a.velocity + a.spin.cross(c.arm_a));
      const double reduced_mass = a.mass * b.mass / (a.mass + b.mass);
      c.force = (k * overlap_depth - 2.0 * cs.damping_ratio * std::sqrt(k * reduced_mass) * relative.dot(n)) * n;
    });
    bool overlap = false;
    touching_pairs = 0, deepest = 0.0;
    for (std::size_t q = 0; q < pairs.size(); ++q) {
      const detail::PairContact& c = contacts[q];
      if (!c.touching) continue;
      overlap = true;
      ++touching_pairs, deepest = std::max(deepest, c.depth);
      detail::CompactedStone& a = stones[pairs[q].a];
      detail::CompactedStone& b = stones[pairs[q].b];
      b.force += c.force;
      b.torque += c.arm_b.cross(c.force);
      a.force -= c.force;
      a.torque -= c.arm_a.cross(c.force);
    }
    detail::for_each_index(stones.size(), cs.threads, [&](std::size_t i) {
      detail::CompactedStone& s = stones[i];
      const bool floor = wall(s, 1, 0.0, 1.0), top = wall(s, 1, lid, -1.0);
      const bool ends = wall(s, 0, 0.0, 1.0) | wall(s, 0, width, -1.0);
      crossing[i] = floor || top || ends;
    });
    for (char c : crossing) overlap = overlap || c;
    return overlap;
  };
  auto advance = [&](double keep) {
    detail::for_each_index(stones.size(), cs.threads, [&](std::size_t i) {
      detail::CompactedStone& s = stones[i];
      s.velocity = keep * (s.velocity + (dt / s.mass) * s.force);
      s.spin = keep * (s.spin + (dt / s.inertia) * s.torque);
      s.centre += dt * s.velocity;
      const double across = std::floor(s.centre.z() / depth);
      s.centre.z() -= depth * across;
      s.wraps += static_cast<long>(across);
      const double angle = dt * s.spin.norm();
      s.moved = dt * s.velocity.norm() + angle * s.reach;
      if (angle > 0.0) {
        s.turn = Eigen::Quaterniond(Eigen::AngleAxisd(angle, s.spin.normalized())) * s.turn;
        s.turn.normalize();
        const Eigen::Matrix3d r = s.turn.toRotationMatrix();
        for (std::size_t v = 0; v < s.vertices.size(); ++v) s.vertices[v] = r * s.shape.vertices[v];
      }
    });
    if (moved_far()) find_pairs();
  };

  const long most = cs.lid_steps + cs.settle_steps;
  find_pairs();
  long step = 0;
  for (const long lid_steps = loose_height > height ? cs.lid_steps : 0; step < lid_steps; ++step) {
    lid = loose_height - lid_speed * static_cast<double>(step + 1);
    loads();
    advance(1.0);
    if (compacting && step % 100 == 0) compacting(step, most);
  }
  lid = height;
  const long settling_from = step;
  bool settled = false;
  for (; step < most && !settled; ++step) {
    settled = !loads();
    if (!settled) advance(1.0 - cs.drag);
    if (compacting && step % 100 == 0) compacting(step, most);
  }
  if (compacting) compacting(most, most);
  // The last step's move may have settled them: look once more. Where not,
  // touching_pairs and crossing are the stones' last state.
  if (!settled) settled = !loads();

  Placement3 out;
  out.depth = depth;
  out.target_fraction = target;
  out.jammed = placed.jammed;
  out.compaction_steps = step;
  for (std::size_t i = 0; i < stones.size(); ++i) {
    PlacedStone3 p = placed.stones[i];
    p.shape = detail::turned(stones[i].shape, stones[i].turn.toRotationMatrix());
    p.shape.translate(stones[i].centre);
    out.stones.push_back(std::move(p));
  }
  // The placement's own test: no stone outside the box, no two that overlap.
  int overlapping = 0, outside = 0;
  detail::StoneGrid3 grid(width, height, depth, 4.0);
  for (std::size_t i = 0; i < out.stones.size(); ++i) {
    const Eigen::AlignedBox3d box = out.stones[i].shape.bounds();
    if (box.min().x() < 0.0 || box.min().y() < 0.0 || box.max().x() > width || box.max().y() > height) ++outside;
    grid.any_near(box, [&](int j) {
      for (double image : {0.0, -depth, depth})
        if (stones_overlap(out.stones[i].shape, out.stones[j].shape, Point3(0.0, 0.0, image))) ++overlapping;
      return false;
    });
    grid.insert(static_cast<int>(i), box);
  }
  if (overlapping > 0 || outside > 0) {
    std::ostringstream msg;
    msg << "cannot compact the stones to the volume fraction " << volume / (width * height * depth);
    if (!settled) {
      long crossing_stones = 0;
      for (char c : crossing) crossing_stones += c;
      msg << ": after " << cs.settle_steps << " settling steps " << touching_pairs
          << " pairs still lie within the clearance (the deepest overlap " << deepest << " mm) and "
          << crossing_stones << " stones against a wall;";
    } else {
      msg << ": settled in " << step - settling_from << " steps, but";
    }
    msg << " the placement's test finds " << overlapping << " pairs overlapping and " << outside
        << " stones crossing a wall";
    throw std::runtime_error(msg.str());
  }
  out.achieved_fraction = volume / (width * height * depth);
  if (!settled) {
    out.pairs_within_clearance = touching_pairs;
    for (char c : crossing) out.stones_within_clearance_of_a_wall += c;
  }
  return out;
}

}  // namespace vrut
