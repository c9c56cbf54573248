#pragma once
// Pictures of a 3D specimen with cairo: its section at mid-depth and its
// surface seen from above (draw.hpp's canvas and colours).
#include "draw.hpp"

#include <vrut/specimen/specimen3.hpp>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

namespace vrut::app::draw {

// The section at mid-depth: the spheres of the two lattice layers on
// either side of it (together a square grid), in their stone's colour or
// mastic dark grey (air voids white), and the outline of each stone where
// the plane cuts it. `moved`: the spheres' places after a run (mm, in the
// specimen's order), drawn without the outlines, which are the stones'
// places before it; the spheres are chosen by where they started.
inline void section3_png(const vrut::Specimen3& sp, const std::string& path, double scale = 6.0,
                         const std::vector<vrut::Point3>* moved = nullptr) {
  Canvas c(sp.width, sp.height * (moved ? 1.3 : 1.0), scale);
  c.rectangle(0, 0, sp.width, sp.height, {1, 1, 1});
  const double r = sp.spheres.radius, layer = 0.5 * vrut::fcc_cell(r);
  // The layers lie at z = layer (k + 1/2): the plane between the two nearest the middle.
  const double mid = layer * std::round(0.5 * sp.depth / layer);
  for (std::size_t i = 0; i < sp.spheres.centers.size(); ++i) {
    const vrut::Point3& x = sp.spheres.centers[i];
    if (std::abs(x.z() - mid) > 0.75 * layer) continue;
    const int s = sp.spheres.stone[i];
    const vrut::Point3& at = moved ? (*moved)[i] : x;
    c.disk(at.x(), at.y(), r, s >= 0 ? stone(s) : Rgb{0.22, 0.22, 0.22});
  }
  if (moved) {
    c.save(path);
    return;
  }
  for (const auto& s : sp.placement.stones)
    for (double image : {0.0, -sp.depth, sp.depth}) {
      const vrut::Polygon cut = vrut::section_at_z(s.shape, mid - image);
      if (!cut.vertices.empty()) c.polygon(cut, {0.35, 0.25, 0.15}, 0.8);
    }
  c.save(path);
}

// The surface from above: the specimen's width across, its depth up the
// picture; each place shows the highest sphere there, coloured by the
// height of its top, blue 12 mm below the specimen's height to red 3 mm
// above it (a rut shows blue, the heave beside it red). `moved`: the
// spheres' places after a run (mm; their depth is taken back into the
// specimen's).
inline void surface3_png(const vrut::Specimen3& sp, const std::string& path, double scale = 6.0,
                         const std::vector<vrut::Point3>* moved = nullptr) {
  const double caption = 5.0;  // mm of picture for the scale's words
  Canvas c(sp.width, sp.depth + caption, scale);
  c.rectangle(0, 0, sp.width, sp.depth + caption, {1, 1, 1});
  std::vector<vrut::Point3> x = moved ? *moved : sp.spheres.centers;
  for (auto& p : x) p.z() -= sp.depth * std::floor(p.z() / sp.depth);
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a].y() < x[b].y(); });
  const double r = sp.spheres.radius, low = sp.height - 12.0, high = sp.height + 3.0;
  for (std::size_t i : order) c.disk(x[i].x(), x[i].z(), r, heat((x[i].y() + r - low) / (high - low)));
  char words[160];
  std::snprintf(words, sizeof words, "top of the spheres: blue %.0f mm, red %.0f mm (the specimen %.0f mm high)", low,
                high, sp.height);
  c.text(0.0, sp.depth + 1.5, words, 2.2 * scale);
  c.save(path);
}

}  // namespace vrut::app::draw
