#pragma once
// Spheres on a face-centred cubic packing over a 3D specimen, tagged by
// stone, with air voids cut from the mastic (docs/specimen.md, "In 3D").
// Host-only; mm.
//
// The cubic cell (edge a = 2 sqrt(2) r) is aligned with the axes: x along
// the section's width, y up, z along its depth. The sites are
// (r, r, a/4) + (a/2)(i, j, k) with i + j + k even: each inner sphere touches
// twelve neighbours, the layers of constant y are square grids of spacing
// 2 r, and the first layer lies on the floor (y = r). The depth is a whole
// number of cells, so that it can be periodic: the sites of the last and
// the first half-layer in z touch across it.
#include <vrut/specimen/packing.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

struct SpherePacking {
  double radius = 0.0;
  double depth = 0.0;                          // whole cells: 2 sqrt(2) r times cells_deep
  int cells_deep = 0;
  std::vector<Eigen::Vector3d> centers;
  std::vector<int> stone;                      // the stone holding the centre, or mastic_site
  std::vector<std::pair<int, int>> bonds;      // touching pairs, across the periodic depth too, not across two stones
  std::vector<std::pair<int, int>> stone_pairs;  // touching pairs of two different stones (where a film goes)
  int removed_for_voids = 0;                   // mastic spheres deleted at random for the air voids
  double air_void_target = 0.0, air_void_achieved = 0.0;  // the deleted spheres' volume over the box's
};

// The FCC cell edge for spheres of radius r, and the whole number of cells
// that comes nearest to a wanted depth (at least one).
inline double fcc_cell(double radius) { return 2.0 * std::sqrt(2.0) * radius; }
inline int fcc_cells_deep(double depth, double radius) {
  return std::max(1, static_cast<int>(std::lround(depth / fcc_cell(radius))));
}

// Spheres of one radius on the FCC packing of a width x height box, as deep
// as `cells_deep` cells; `site_of(centre)` says what each site holds (a
// stone's index, mastic_site or void_site). Then mastic spheres are deleted
// at random until their volume is `air_voids` of the box.
template <class SiteOf, class Rng>
SpherePacking pack_spheres_by(SiteOf site_of, double width, double height, int cells_deep, double radius,
                              double air_voids, Rng& rng) {
  if (!(radius > 0.0)) throw std::invalid_argument("sphere radius must be positive");
  if (cells_deep < 1) throw std::invalid_argument("the packing needs at least one cell of depth");
  if (!(air_voids >= 0.0 && air_voids <= 0.3))
    throw std::invalid_argument("air void fraction must lie within [0, 0.3], got " + std::to_string(air_voids));
  const double half = 0.5 * fcc_cell(radius);
  const int nx = static_cast<int>(std::floor((width - 2.0 * radius) / half + 1e-9)) + 1;
  const int ny = static_cast<int>(std::floor((height - 2.0 * radius) / half + 1e-9)) + 1;
  const int nz = 2 * cells_deep;
  if (!(width >= 2.0 * radius) || !(height >= 2.0 * radius))
    throw std::invalid_argument("the spheres are larger than the section");

  auto site = [&](int i, int j, int k) -> long {
    return (static_cast<long>(k) * ny + j) * nx + i;
  };
  std::vector<int> slot(static_cast<std::size_t>(nx) * ny * nz, -1);
  std::vector<Eigen::Vector3d> centers;
  std::vector<int> owner;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if ((i + j + k) % 2 != 0) continue;
        const Eigen::Vector3d c(radius + half * i, radius + half * j, 0.5 * half + half * k);
        slot[site(i, j, k)] = static_cast<int>(centers.size());
        centers.push_back(c);
        owner.push_back(site_of(c));
      }

  std::vector<int> mastic;
  for (std::size_t i = 0; i < centers.size(); ++i)
    if (owner[i] == mastic_site) mastic.push_back(static_cast<int>(i));
  const double depth = half * nz;
  const double sphere_volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  const int remove = static_cast<int>(std::lround(air_voids * width * height * depth / sphere_volume));
  if (remove > static_cast<int>(mastic.size()))
    throw std::invalid_argument("not enough mastic spheres for the air voids: need " + std::to_string(remove) +
                                ", have " + std::to_string(mastic.size()));
  detail::choose_at_random(mastic, remove, rng);
  std::vector<char> gone(centers.size(), 0);
  for (int k = 0; k < remove; ++k) gone[mastic[k]] = 1;
  for (std::size_t i = 0; i < centers.size(); ++i)
    if (owner[i] == void_site) gone[i] = 1;

  SpherePacking out;
  out.radius = radius;
  out.depth = depth;
  out.cells_deep = cells_deep;
  out.removed_for_voids = remove;
  out.air_void_target = air_voids;
  out.air_void_achieved = remove * sphere_volume / (width * height * depth);
  // The kept spheres in memory along the section: x outermost, the periodic
  // depth innermost (the sites were made depth-major, which the voids' draw
  // follows). A sphere's neighbours then lie a few thousand places away, not
  // a whole layer of the section (tens of thousands), so the force pass finds
  // them in the nearer caches: 1.18 times the loading's particle-steps a
  // second at 1 mm (docs/performance.md, "The spheres in section order").
  std::vector<int> index(centers.size(), -1);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const int s = slot[site(i, j, k)];
        if (s < 0 || gone[s]) continue;
        index[s] = static_cast<int>(out.centers.size());
        out.centers.push_back(centers[s]);
        out.stone.push_back(owner[s]);
      }
  // Touching pairs: the six of the twelve neighbours (a/2)(di, dj, dk), two
  // of them +-1 and one 0, that come after a site; z wraps.
  static constexpr int forward[6][3] = {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int s = slot[site(i, j, k)];
        if (s < 0 || index[s] < 0) continue;
        for (const auto& o : forward) {
          const int i2 = i + o[0], j2 = j + o[1], k2 = (k + o[2] + nz) % nz;
          if (i2 < 0 || i2 >= nx || j2 < 0 || j2 >= ny) continue;
          const int t = slot[site(i2, j2, k2)];
          if (t < 0 || index[t] < 0) continue;
          const int a = index[s], b = index[t];
          const bool two_stones = out.stone[a] >= 0 && out.stone[b] >= 0 && out.stone[a] != out.stone[b];
          (two_stones ? out.stone_pairs : out.bonds).emplace_back(std::min(a, b), std::max(a, b));
        }
      }
  // One cell deep, a site's neighbours before and behind are the same site.
  for (auto* pairs : {&out.bonds, &out.stone_pairs}) {
    std::sort(pairs->begin(), pairs->end());
    pairs->erase(std::unique(pairs->begin(), pairs->end()), pairs->end());
  }
  return out;
}

}  // namespace vrut
