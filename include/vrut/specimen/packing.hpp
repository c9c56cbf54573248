#pragma once
// Hexagonally packed disks over the section, tagged by aggregate, with air
// voids cut from the mastic (docs/method.md 5.2-5.4). Host-only; mm.
#include <vrut/specimen/placement.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vrut {

struct DiskPacking {
  double radius = 0.0;
  std::vector<Point> centers;
  std::vector<int> aggregate;                // index into Placement::aggregates, -1 for mastic
  std::vector<std::pair<int, int>> bonds;    // initially touching pairs, not across two aggregates
  int removed_for_voids = 0;                 // mastic disks deleted at random for the air voids
  int void_sites = 0;                        // sites the source itself marked void (an image's pores)
  double air_void_target = 0.0, air_void_achieved = 0.0;  // the random voids' fraction of the section
};

namespace detail {

// Puts a uniform random choice of `count` of the candidates first (a partial
// Fisher-Yates shuffle).
template <class Rng>
void choose_at_random(std::vector<int>& candidates, int count, Rng& rng) {
  for (int k = 0; k < count; ++k) {
    std::uniform_int_distribution<int> pick(k, static_cast<int>(candidates.size()) - 1);
    std::swap(candidates[k], candidates[pick(rng)]);
  }
}

}  // namespace detail

// What a lattice site holds, by its centre: a stone's index (>= 0), mastic,
// or nothing (a void the source shows, such as a pore in an image).
constexpr int mastic_site = -1, void_site = -2;

// Disks of one radius on a hexagonal close packing: rows y = r + k sqrt(3) r,
// odd rows shifted by r; `site_of(centre)` says what each site holds (a
// stone, mastic_site or void_site). Then mastic disks are deleted at random
// until the deleted area is `air_voids` of the section.
template <class SiteOf, class Rng>
DiskPacking pack_disks_by(SiteOf site_of, double width, double height, double radius, double air_voids, Rng& rng) {
  if (!(radius > 0.0)) throw std::invalid_argument("disk radius must be positive");
  if (!(air_voids >= 0.0 && air_voids <= 0.3))
    throw std::invalid_argument("air void fraction must lie within [0, 0.3], got " + std::to_string(air_voids));
  const double dy = std::sqrt(3.0) * radius;
  const int rows = static_cast<int>(std::floor((height - 2.0 * radius) / dy)) + 1;
  const int columns = static_cast<int>(std::floor((width - 2.0 * radius) / (2.0 * radius))) + 1;
  if (rows < 1 || columns < 1) throw std::invalid_argument("the disks are larger than the section");

  // Lattice slot -> disk (or -1 where the odd row has no room for its last disk).
  std::vector<int> slot(static_cast<std::size_t>(rows) * columns, -1);
  std::vector<Point> centers;
  std::vector<int> owner;
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < columns; ++col) {
      const Point c(radius + (row % 2 ? radius : 0.0) + 2.0 * radius * col, radius + dy * row);
      if (c.x() + radius > width + 1e-9) continue;
      slot[static_cast<std::size_t>(row) * columns + col] = static_cast<int>(centers.size());
      centers.push_back(c);
      owner.push_back(site_of(c));
    }

  // Air voids: a random choice of mastic disks.
  std::vector<int> mastic;
  for (std::size_t i = 0; i < centers.size(); ++i)
    if (owner[i] == mastic_site) mastic.push_back(static_cast<int>(i));
  const double disk_area = M_PI * radius * radius;
  const int remove = static_cast<int>(std::lround(air_voids * width * height / disk_area));
  if (remove > static_cast<int>(mastic.size()))
    throw std::invalid_argument("not enough mastic disks for the air voids: need " + std::to_string(remove) +
                                ", have " + std::to_string(mastic.size()));
  detail::choose_at_random(mastic, remove, rng);
  std::vector<char> gone(centers.size(), 0);
  for (int k = 0; k < remove; ++k) gone[mastic[k]] = 1;
  int void_sites = 0;
  for (std::size_t i = 0; i < centers.size(); ++i)
    if (owner[i] == void_site) gone[i] = 1, ++void_sites;

  DiskPacking out;
  out.radius = radius;
  out.removed_for_voids = remove;
  out.void_sites = void_sites;
  out.air_void_target = air_voids;
  out.air_void_achieved = remove * disk_area / (width * height);
  std::vector<int> index(centers.size(), -1);
  for (std::size_t i = 0; i < centers.size(); ++i)
    if (!gone[i]) {
      index[i] = static_cast<int>(out.centers.size());
      out.centers.push_back(centers[i]);
      out.aggregate.push_back(owner[i]);
    }
  // Touching pairs from the lattice: right neighbour, and the two above.
  auto at = [&](int row, int col) {
    if (row < 0 || row >= rows || col < 0 || col >= columns) return -1;
    const int s = slot[static_cast<std::size_t>(row) * columns + col];
    return s < 0 ? -1 : index[s];
  };
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < columns; ++col) {
      const int i = at(row, col);
      if (i < 0) continue;
      const int shift = row % 2;  // odd rows sit half a disk to the right
      for (int j : {at(row, col + 1), at(row + 1, col - 1 + shift), at(row + 1, col + shift)}) {
        if (j < 0) continue;
        const int a = out.aggregate[i], b = out.aggregate[j];
        if (a >= 0 && b >= 0 && a != b) continue;  // two aggregates: no bond
        out.bonds.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  std::sort(out.bonds.begin(), out.bonds.end());
  return out;
}

// The generator's packing: a site belongs to the placed aggregate whose
// polygon holds its centre, else to the mastic.
template <class Rng>
DiskPacking pack_disks(const Placement& placement, double width, double height, double radius, double air_voids,
                       Rng& rng) {
  detail::AggregateGrid grid(width, height, 4.0);
  for (std::size_t a = 0; a < placement.aggregates.size(); ++a)
    grid.insert(static_cast<int>(a), detail::bounds(placement.aggregates[a].polygon));
  auto site_of = [&](const Point& c) {
    int in = mastic_site;
    const Eigen::AlignedBox2d box(c, c);
    grid.any_in_box(box, [&](int id) {
      if (point_in_polygon(placement.aggregates[id].polygon, c)) in = id;
      return in >= 0;
    });
    return in;
  };
  return pack_disks_by(site_of, width, height, radius, air_voids, rng);
}

}  // namespace vrut
