#pragma once
// Pictures of a 3D specimen with cairo: its section at mid-depth and its
// surface seen from above (draw.hpp's canvas and colours).
#include "draw.hpp"

#include <vrut/specimen/specimen3.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

namespace draw {

// The section at mid-depth: the spheres of the two lattice layers on
// either side of it (together a square grid), in their stone's colour or
// mastic dark grey (air voids white), and the outline of each stone where
// the plane cuts it.
inline void section3_png(const vrut::Specimen3& sp, const std::string& path, double scale = 6.0) {
  Canvas c(sp.width, sp.height, scale);
  c.rectangle(0, 0, sp.width, sp.height, {1, 1, 1});
  const double r = sp.spheres.radius, layer = 0.5 * vrut::fcc_cell(r);
  // The layers lie at z = layer (k + 1/2): the plane between the two nearest the middle.
  const double mid = layer * std::round(0.5 * sp.depth / layer);
  for (std::size_t i = 0; i < sp.spheres.centers.size(); ++i) {
    const vrut::Point3& x = sp.spheres.centers[i];
    if (std::abs(x.z() - mid) > 0.75 * layer) continue;
    const int s = sp.spheres.stone[i];
    c.disk(x.x(), x.y(), r, s >= 0 ? stone(s) : Rgb{0.22, 0.22, 0.22});
  }
  for (const auto& s : sp.placement.stones)
    for (double image : {0.0, -sp.depth, sp.depth}) {
      const vrut::Polygon cut = vrut::section_at_z(s.shape, mid - image);
      if (!cut.vertices.empty()) c.polygon(cut, {0.35, 0.25, 0.15}, 0.8);
    }
  c.save(path);
}

// The surface from above: the specimen's width across, its depth up the
// picture; each place shows the highest sphere there, its colour darker
// the lower it lies.
inline void surface3_png(const vrut::Specimen3& sp, const std::string& path, double scale = 6.0) {
  Canvas c(sp.width, sp.depth, scale);
  c.rectangle(0, 0, sp.width, sp.depth, {1, 1, 1});
  const auto& x = sp.spheres.centers;
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a].y() < x[b].y(); });
  for (std::size_t i : order) {
    const int s = sp.spheres.stone[i];
    const Rgb base = s >= 0 ? stone(s) : Rgb{0.45, 0.45, 0.45};
    const double light = 0.35 + 0.65 * std::clamp(x[i].y() / sp.height, 0.0, 1.0);
    c.disk(x[i].x(), x[i].z(), sp.spheres.radius, {base.r * light, base.g * light, base.b * light});
  }
  c.save(path);
}

}  // namespace draw
