// The binder film from a mix's volumetrics (specimen/binder_film.hpp), and
// the least film between stones it sets (protocol/rutting/materials.hpp).
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/specimen/binder_film.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

TEST_CASE("the binder film of 2#, worked by hand with MS-2's surface area factors", "[unit][binder_film]") {
  // 2#: 48 % passing 4.75 mm and 34 % 2.36 mm; below, 34 (d / 2.36)^0.45:
  // 24.89, 18.36, 13.44, 9.84 and 7.20 % at 1.18, 0.6, 0.3, 0.15 and
  // 0.075 mm. SA = 0.41 + 0.0041 P4.75 + 0.0082 P2.36 + 0.0164 P1.18 +
  // 0.0287 P0.6 + 0.0614 P0.3 + 0.1229 P0.15 + 0.3277 P0.075 = 6.2150 m^2/kg;
  // T = 4.8 / (95.2 x 1.03 x 6.2150) x 1000 = 7.876 micrometres.
  const vrut::BinderFilm f = vrut::binder_film(vrut::builtin_gradation(2), vrut::MixVolumetrics{});
  CHECK(f.passing[2] == Approx(24.89).epsilon(2e-4));
  CHECK(f.passing[6] == Approx(7.20).epsilon(1e-3));
  CHECK(f.surface_area == Approx(6.2150).epsilon(1e-4));
  CHECK(f.thickness_um == Approx(7.876).epsilon(2e-4));
}

TEST_CASE("the binder film: fewer fines, a thicker film, and a table's own fine sieves used", "[unit][binder_film]") {
  const vrut::MixVolumetrics mix;
  const double t1 = vrut::binder_film(vrut::builtin_gradation(1), mix).thickness_um;
  const double t2 = vrut::binder_film(vrut::builtin_gradation(2), mix).thickness_um;
  const double t3 = vrut::binder_film(vrut::builtin_gradation(3), mix).thickness_um;
  CHECK(t1 < t2);
  CHECK(t2 < t3);
  // A gradation given down to 0.075 mm: its own values, no power line.
  // SA = 0.41 + 0.0041 60 + 0.0082 40 + 0.0164 30 + 0.0287 20 + 0.0614 12 +
  // 0.1229 8 + 0.3277 5 = 0.41 + 0.246 + 0.328 + 0.492 + 0.574 + 0.7368 + 0.9832 +
  // 1.6385 = 5.4085 m^2/kg.
  vrut::Gradation g{"fine", {9.5, 4.75, 2.36, 1.18, 0.6, 0.3, 0.15, 0.075}, {100, 60, 40, 30, 20, 12, 8, 5}};
  const vrut::BinderFilm f = vrut::binder_film(g, mix);
  CHECK(f.surface_area == Approx(5.4085).epsilon(1e-9));
  CHECK(f.thickness_um == Approx(4.8 / (95.2 * 1.03 * 5.4085) * 1000.0).epsilon(1e-9));
  // A gradation that stops above 2.36 mm cannot give the fines' area.
  vrut::Gradation coarse{"coarse", {19.0, 9.5, 4.75}, {100, 60, 30}};
  CHECK_THROWS_WITH(vrut::binder_film(coarse, mix), Catch::Contains("down to 2.36 mm"));
}

TEST_CASE("a least film between stones (thinner than 0.1 d): every stone pair's film at least that thick, nothing else",
          "[unit][binder_film]") {
  vrut::RuttingMaterials m;
  const double t = 0.05, d = 2e-3, least = 20e-6;
  const auto before = vrut::rutting_table(m, t, 1e4, 2, d);
  m.least_film = least;
  const auto after = vrut::rutting_table(m, t, 1e4, 2, d);
  int raised = 0;
  for (int a = 0; a < before.groups(); ++a)
    for (int b = 0; b < before.groups(); ++b) {
      const auto &p = before(a, b), &q = after(a, b);
      REQUIRE(p.use_second == q.use_second);
      const bool stone_film = a != vrut::mastic_group && b != vrut::mastic_group && !p.use_second;
      if (stone_film) {
        CHECK(q.first.normal.thickness == Approx(std::max(p.first.normal.thickness, least)).epsilon(1e-12));
        raised += p.first.normal.thickness < least;
      } else {
        CHECK(q.first.normal.thickness == p.first.normal.thickness);
      }
      // The film's Burger's element (over at least 0.1 d, film_least_gap,
      // which a least film under that leaves alone) and the springs are the same.
      CHECK(q.first.normal.film.maxwell_stiffness == p.first.normal.film.maxwell_stiffness);
      CHECK(q.first.normal.stone_stiffness == p.first.normal.stone_stiffness);
    }
  CHECK(raised > 0);  // the pairs of bins that met bare
  vrut::RuttingMaterials none;
  none.stone_film = vrut::StoneFilm::none;
  none.least_film = least;
  CHECK_THROWS_WITH(vrut::rutting_table(none, t, 1e4, 2, d), Catch::Contains("film per contact"));
}
