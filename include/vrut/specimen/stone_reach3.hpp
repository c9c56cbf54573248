#pragma once
// How far each stone sphere's centre lies inside its stone's surface: the 3D
// form of stone_reach.hpp, which says why the film between two stones is
// one diameter less the reaches of its two spheres. Host-only; lengths in
// mm, reaches as fractions of the sphere diameter.
#include <vrut/specimen/specimen3.hpp>
#include <vrut/specimen/stone3.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vrut {

// One value per sphere: -1 for a mastic sphere; for a stone sphere, the mean
// distance from its centre to its stone's surface, in diameters (at most 1),
// along the lines to its lattice neighbours in other stones; where it has
// none, along the lines to its mastic neighbours; where it has neither, 1.
inline std::vector<double> stone_reach3(const Specimen3& sp) {
  const SpherePacking& s = sp.spheres;
  const std::size_t n = s.centers.size();
  const double d = 2.0 * s.radius, depth = sp.depth;
  // The image of a point nearest a reference, along the periodic depth.
  auto near_image = [depth](Point3 x, double z_ref) {
    x.z() += depth * std::round((z_ref - x.z()) / depth);
    return x;
  };
  auto reach = [&](int from, int to) {
    const Stone3& stone = sp.placement.stones[s.stone[from]].shape;
    const Point3 p = near_image(s.centers[from], stone.centroid.z());
    const Point3 u = (near_image(s.centers[to], p.z()) - p).normalized();
    return std::min(distance_to_surface(stone, p, u) / d, 1.0);
  };
  std::vector<double> stones(n, 0.0), mastic(n, 0.0);
  std::vector<int> stones_count(n, 0), mastic_count(n, 0);
  for (const auto& [i, j] : s.stone_pairs) {
    stones[i] += reach(i, j), ++stones_count[i];
    stones[j] += reach(j, i), ++stones_count[j];
  }
  for (const auto& [i, j] : s.bonds) {
    if ((s.stone[i] >= 0) == (s.stone[j] >= 0)) continue;  // one stone, or two mastic spheres
    const int in = s.stone[i] >= 0 ? i : j, out = in == i ? j : i;
    mastic[in] += reach(in, out), ++mastic_count[in];
  }
  std::vector<double> out(n, -1.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (s.stone[i] < 0) continue;
    out[i] = stones_count[i] > 0   ? stones[i] / stones_count[i]
             : mastic_count[i] > 0 ? mastic[i] / mastic_count[i]
                                   : 1.0;
  }
  return out;
}

}  // namespace vrut
