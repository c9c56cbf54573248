// The film between stones in 3D (protocol/rutting/run3.hpp, the 2D film per contact
// carried into 3D): the distance to a stone's surface against a cube worked
// by hand, each stone sphere's reach against an independent measure, and
// the 3D contact table against the mastic's and the stones' rules.
#include "small_box3.hpp"

#include <vrut/protocol/rutting/run3.hpp>
#include <vrut/specimen/stone_reach3.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {

using vrut::Point3;

// A cube of side 2 centred on c.
vrut::Stone3 cube_at(const Point3& c) {
  std::vector<Point3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back(c + Point3(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0));
  return vrut::convex_hull_stone(corners);
}

vrut::Specimen3 small_specimen(int mix, std::uint64_t seed) {
  vrut::SpecimenSettings3 s = vrut_test::small_box3(mix, seed, 40.0);
  s.sphere_radius = 1.5;
  return vrut::generate_specimen3(s);
}

}  // namespace

// From a point inside a cube along a direction: the face it leaves through,
// worked by hand.
TEST_CASE("3D stones: the distance to the surface along a ray, by hand", "[film3][unit]") {
  const vrut::Stone3 c = cube_at(Point3(5.0, 0.0, 0.0));
  const Point3 p(5.7, 0.2, -0.5);
  CHECK(vrut::distance_to_surface(c, p, Point3::UnitX()) == Approx(0.3).epsilon(1e-12));
  CHECK(vrut::distance_to_surface(c, p, -Point3::UnitZ()) == Approx(0.5).epsilon(1e-12));
  // Along (1, 1, 0)/sqrt 2 it meets x = 6 after 0.3 sqrt 2 (y = 0.5 < 1).
  CHECK(vrut::distance_to_surface(c, p, Point3(1.0, 1.0, 0.0).normalized()) == Approx(0.3 * std::sqrt(2.0)).epsilon(1e-12));
  // Along (-1, 1, 1)/sqrt 3 it meets y = 1 after 0.8 sqrt 3 (x = 4.9, z = 0.3).
  CHECK(vrut::distance_to_surface(c, p, Point3(-1.0, 1.0, 1.0).normalized()) == Approx(0.8 * std::sqrt(3.0)).epsilon(1e-12));
}

// Each stone sphere's reach, measured independently: its lattice neighbours
// found by distance (nearest image along the depth), not by the lattice's
// indices, and the distance to the stone's surface along each line of
// centres by bisection on the stone's inside test, not by its face planes.
TEST_CASE("3D specimen: each stone sphere's reach against an independent measure", "[film3][specimen3]") {
  const vrut::Specimen3 sp = small_specimen(1, 5);
  const auto& s = sp.spheres;
  const double d = 2.0 * s.radius, depth = sp.depth;
  const std::vector<double> reach = vrut::stone_reach3(sp);
  auto image_near = [&](Point3 x, double z) {
    x.z() += depth * std::round((z - x.z()) / depth);
    return x;
  };
  auto along = [&](int from, int to) {  // in diameters, at most 1
    const vrut::Stone3& stone = sp.placement.stones[s.stone[from]].shape;
    const Point3 p = image_near(s.centers[from], stone.centroid.z());
    const Point3 u = (image_near(s.centers[to], p.z()) - p).normalized();
    if (stone.contains(p + d * u)) return 1.0;
    double in = 0.0, out = d;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (in + out);
      (stone.contains(p + mid * u) ? in : out) = mid;
    }
    return in / d;
  };
  const std::size_t n = s.centers.size();
  std::vector<double> to_stones(n, 0.0), to_mastic(n, 0.0);
  std::vector<int> stones_count(n, 0), mastic_count(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (s.stone[i] < 0) continue;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || s.stone[j] == s.stone[i]) continue;
      if (std::abs((image_near(s.centers[j], s.centers[i].z()) - s.centers[i]).norm() - d) > 1e-9 * d) continue;
      if (s.stone[j] >= 0)
        to_stones[i] += along(i, j), ++stones_count[i];
      else
        to_mastic[i] += along(i, j), ++mastic_count[i];
    }
  }
  int checked_stones = 0, checked_mastic = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (s.stone[i] < 0) {
      CHECK(reach[i] == -1.0);
      continue;
    }
    const double expected = stones_count[i] > 0   ? to_stones[i] / stones_count[i]
                            : mastic_count[i] > 0 ? to_mastic[i] / mastic_count[i]
                                                  : 1.0;
    INFO("sphere " << i);
    CHECK(reach[i] == Approx(expected).margin(1e-9));
    checked_stones += stones_count[i] > 0;
    checked_mastic += stones_count[i] == 0 && mastic_count[i] > 0;
  }
  CHECK(checked_stones > 50);  // both rules exercised
  CHECK(checked_mastic > 50);
}

// The 3D table: the 2D table's rules on the FCC lattice. Any two stone
// spheres that touch belong to two stones (a rigid stone's members never
// touch), so every pair of reach bins, the same bin too, meets through the
// mastic over the film's thickness (1 - both bins' middles, at least 0.1
// diameters), with the stone friction, then on the stones' spring,
// stone_contact_ratio E1 d / c (c = 2 sqrt 2 (1 + 3b) / (3 + b),
// docs/burgers.md). Without the film, on that spring alone.
TEST_CASE("3D table: the film per contact over the FCC lattice's rules", "[film3][rutting][unit]") {
  vrut::RuttingMaterials m;
  m.stone_film = vrut::StoneFilm::per_contact;
  m.stone_friction = 0.6;
  const double d = 3e-3, shift = 1e4;
  const int bins = vrut::film_reach_classes;
  const auto table = vrut::rutting_table3(m, d, shift);
  REQUIRE(table.groups() == 1 + bins);
  const double beta = 1.0 / (2.0 * (1.0 + m.mastic_nu));
  const double c = 2.0 * std::sqrt(2.0) * (1.0 + 3.0 * beta) / (3.0 + beta);
  const double k_stone = m.stone_contact_ratio * m.mastic.E1 * d / c;
  const auto& mastic = table(0, 0).first;
  // The mastic's own rule: E1 d / c on the Maxwell spring (factor 1).
  CHECK(mastic.normal.film.maxwell_stiffness == Approx(m.mastic.E1 * d / c).epsilon(1e-12));
  for (int p = 0; p < bins; ++p)
    for (int q = 0; q < bins; ++q) {
      const int a = vrut::stone_group(m, 0, (p + 0.5) / bins), b = vrut::stone_group(m, 0, (q + 0.5) / bins);
      INFO("bins " << p << ", " << q);
      REQUIRE(table(a, b).use_second == 0);
      const double gap = 1.0 - (p + 0.5) / bins - (q + 0.5) / bins;
      const auto& film = table(a, b).first;
      CHECK(film.normal.thickness == Approx(std::max(gap, 0.0) * d).margin(1e-15));
      CHECK(film.normal.film.maxwell_stiffness ==
            Approx(mastic.normal.film.maxwell_stiffness / std::max(gap, 0.1)).epsilon(1e-12));
      CHECK(film.shear.film.kelvin_viscosity ==
            Approx(mastic.shear.film.kelvin_viscosity / std::max(gap, 0.1)).epsilon(1e-12));
      CHECK(film.normal.stone_stiffness == Approx(k_stone).epsilon(1e-12));
      CHECK(film.shear.stone_stiffness == Approx(k_stone / (2.0 * (1.0 + m.aggregate_nu))).epsilon(1e-12));
      CHECK(film.friction == 0.6);
      CHECK(table(0, a).first.normal.film.maxwell_stiffness ==
            Approx(m.mastic_aggregate_factor * mastic.normal.film.maxwell_stiffness).epsilon(1e-12));
    }
  m.stone_film = vrut::StoneFilm::mean;
  CHECK_THROWS_WITH(vrut::rutting_table3(m, d, shift), Catch::Contains("film per contact, or through none"));
  m.stone_film = vrut::StoneFilm::none;
  const auto none = vrut::rutting_table3(m, d, shift);
  REQUIRE(none.groups() == 2);
  REQUIRE(none(1, 1).use_second == 1);
  CHECK(none(1, 1).second.normal.stiffness == Approx(k_stone).epsilon(1e-12));
}
