#pragma once
// Colours for the placed aggregates, such that any two pieces closer than a
// margin get different colours. Host-only; mm.
//
// Why: the contact table of the DEM is indexed by material group only, so it
// cannot tell two disks of one stone from two disks of two stones. Giving
// each stone a colour (a group of its own kind) lets the table do it without
// a per-contact lookup: same colour, same stone (bonded, rigid); different
// colours, two stones meeting (through a mastic film, where asked). The
// margin covers how far stones move towards each other during a test; two
// stones of one colour further apart than it that still meet get the stone
// law, the method's default.
#include <vrut/specimen/placement.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

namespace vrut {

// Greedy colouring, largest piece first (the large ones have the most
// neighbours): each piece takes the lowest colour none of its neighbours
// within `margin` holds. Returns one colour per aggregate, from 0.
inline std::vector<int> colour_aggregates(const Placement& p, double margin) {
  const std::size_t n = p.aggregates.size();
  struct Box { double x0, y0, x1, y1; };
  std::vector<Box> box(n);
  for (std::size_t a = 0; a < n; ++a) {
    Box b{1e300, 1e300, -1e300, -1e300};
    for (const Point& v : p.aggregates[a].polygon.vertices) {
      b.x0 = std::min(b.x0, v.x()), b.y0 = std::min(b.y0, v.y());
      b.x1 = std::max(b.x1, v.x()), b.y1 = std::max(b.y1, v.y());
    }
    box[a] = b;
  }
  auto near = [&](std::size_t a, std::size_t b) {
    if (box[a].x0 > box[b].x1 + margin || box[b].x0 > box[a].x1 + margin || box[a].y0 > box[b].y1 + margin ||
        box[b].y0 > box[a].y1 + margin)
      return false;
    return polygons_overlap(p.aggregates[a].polygon, p.aggregates[b].polygon) ||
           polygon_distance(p.aggregates[a].polygon, p.aggregates[b].polygon) < margin;
  };
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p.aggregates[a].area > p.aggregates[b].area; });
  std::vector<int> colour(n, -1);
  std::vector<char> taken;
  for (std::size_t a : order) {
    taken.assign(n + 1, 0);
    for (std::size_t b = 0; b < n; ++b)
      if (colour[b] >= 0 && near(a, b)) taken[colour[b]] = 1;
    int c = 0;
    while (taken[c]) ++c;
    colour[a] = c;
  }
  return colour;
}

}  // namespace vrut
