#pragma once
// Checks every generated specimen in the suite must pass: every polygon has
// 4 to 10 vertices, is simple, lies inside the section and overlaps no other.
#include <vrut/specimen/specimen.hpp>

#include <catch2/catch.hpp>

namespace vrut_test {

inline void check_polygons(const vrut::Specimen& sp) {
  const auto& aggs = sp.placement.aggregates;
  const double W = sp.settings.placement.width, H = sp.settings.placement.height;
  for (std::size_t a = 0; a < aggs.size(); ++a) {
    const auto& poly = aggs[a].polygon;
    REQUIRE(poly.vertices.size() >= 4);
    REQUIRE(poly.vertices.size() <= 10);
    REQUIRE(vrut::is_simple(poly));
    REQUIRE(poly.area() > 0.0);
    for (const auto& v : poly.vertices) {
      REQUIRE(v.x() >= 0.0);
      REQUIRE(v.y() >= 0.0);
      REQUIRE(v.x() <= W);
      REQUIRE(v.y() <= H);
    }
    for (std::size_t b = a + 1; b < aggs.size(); ++b) REQUIRE_FALSE(vrut::polygons_overlap(poly, aggs[b].polygon));
  }
}


}  // namespace vrut_test
