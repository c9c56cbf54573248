// The filler's stiffening of the binder by mix (specimen/filler_mastic.hpp),
// and the mastic scaled by it with the stones' spring kept
// (protocol/rutting/materials.hpp, scale_mastic).
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/specimen/filler_mastic.hpp>

#include <catch2/catch.hpp>

#include <cmath>

TEST_CASE("Krieger-Dougherty: Einstein's 1 + 2.5 phi when dilute, and no suspension at the maximum packing",
          "[physics][filler_mastic]") {
  // f = (1 - phi/phi_m)^(-2.5 phi_m) = 1 + 2.5 phi + O(phi^2), whatever phi_m:
  // at phi = 1e-4 the second-order term, 2.5 phi^2 (2.5 phi_m + 1) / (2 phi_m),
  // is under 1e-7, so the slope holds to 1e-3 of itself.
  for (double phi_m : {0.55, 0.65, 0.72, 1.0}) {
    const double phi = 1e-4;
    CHECK((vrut::krieger_dougherty(phi, phi_m) - 1.0) / phi == Approx(2.5).epsilon(1e-3));
  }
  CHECK(vrut::krieger_dougherty(0.0, 0.65) == 1.0);
  // At half the maximum packing, 2^(2.5 phi_m).
  CHECK(vrut::krieger_dougherty(0.325, 0.65) == Approx(std::pow(2.0, 1.625)).epsilon(1e-12));
  CHECK_THROWS_WITH(vrut::krieger_dougherty(0.65, 0.65), Catch::Contains("jammed"));
}

TEST_CASE("the filler of 1#, 2# and 3#, worked by hand from the 0.45-power line and the volumetrics",
          "[unit][filler_mastic]") {
  // Passing 0.075 mm: P(2.36) (0.075 / 2.36)^0.45 = 0.21182 P(2.36): 10.167,
  // 7.2019 and 4.2364 % for 48, 34 and 20 %. Per unit mass of mix (asphalt
  // 4.8 %, G_sb 2.70, G_b 1.03): filler 0.952 P / 2.70, binder 0.048 / 1.03
  // = 0.046602; phi = 0.43479 (1#), 0.35271 (2#), 0.24273 (3#). At Rigden
  // voids 0.35 (phi_m 0.65), f = (1 - phi / 0.65)^-1.625: 6.0269, 3.5650,
  // 2.1376; over 2#'s: 1.6906 and 0.59960.
  const vrut::MixVolumetrics mix;
  const auto g1 = vrut::builtin_gradation(1), g2 = vrut::builtin_gradation(2), g3 = vrut::builtin_gradation(3);
  CHECK(vrut::fine_passing_percent(g2, 0.075) == Approx(7.2019).epsilon(1e-4));
  const vrut::FillerMastic m2 = vrut::filler_mastic(vrut::fine_passing_percent(g2, 0.075), mix, 0.35);
  CHECK(m2.phi == Approx(0.35271).epsilon(1e-4));
  CHECK(m2.phi_m == Approx(0.65).epsilon(1e-12));
  CHECK(m2.stiffening == Approx(3.5650).epsilon(1e-4));
  CHECK(m2.free_binder == Approx(1.0 - 0.35271 / 0.65).epsilon(1e-4));
  CHECK(vrut::mastic_scale_by_filler(g1, g2, mix, 0.35) == Approx(1.6906).epsilon(1e-4));
  CHECK(vrut::mastic_scale_by_filler(g3, g2, mix, 0.35) == Approx(0.59960).epsilon(1e-4));
  CHECK(vrut::mastic_scale_by_filler(g2, g2, mix, 0.35) == 1.0);
  // A gradation given down to 0.075 mm: its own filler, no power line.
  vrut::Gradation measured{"measured", {9.5, 4.75, 2.36, 0.6, 0.075}, {100, 60, 40, 20, 5}};
  CHECK(vrut::filler_mastic(vrut::fine_passing_percent(measured, 0.075), mix, 0.35).filler_percent == 5.0);
  // A filler that fills its dry-compacted voids is no suspension.
  CHECK_THROWS_WITH(vrut::filler_mastic(60.0, mix, 0.45), Catch::Contains("jammed"));
  CHECK_THROWS_WITH(vrut::filler_mastic(7.2, mix, 1.2), Catch::Contains("Rigden"));
}

TEST_CASE("a mastic scaled by k: every Burger's constant times k, the stones' and walls' springs where they were",
          "[unit][filler_mastic]") {
  const double t = 0.05, d = 2e-3, k = 1.6906;
  const vrut::RuttingMaterials m;
  vrut::RuttingMaterials scaled = m;
  vrut::scale_mastic(scaled, k);
  const auto before = vrut::rutting_table(m, t, 1e4, 2, d), after = vrut::rutting_table(scaled, t, 1e4, 2, d);
  int films = 0;
  for (int a = 0; a < before.groups(); ++a)
    for (int b = 0; b < before.groups(); ++b) {
      const auto &p = before(a, b), &q = after(a, b);
      REQUIRE(p.use_second == q.use_second);
      if (p.use_second) {  // two parts of one stone: the stones' own spring
        CHECK(q.second.normal.stiffness == Approx(p.second.normal.stiffness).epsilon(1e-12));
        continue;
      }
      const auto &e = p.first.normal.film, &f = q.first.normal.film;
      CHECK(f.maxwell_stiffness == Approx(k * e.maxwell_stiffness).epsilon(1e-12));
      CHECK(f.maxwell_viscosity == Approx(k * e.maxwell_viscosity).epsilon(1e-12));
      CHECK(f.kelvin_stiffness == Approx(k * e.kelvin_stiffness).epsilon(1e-12));
      CHECK(f.kelvin_viscosity == Approx(k * e.kelvin_viscosity).epsilon(1e-12));
      CHECK(q.first.normal.stone_stiffness == Approx(p.first.normal.stone_stiffness).epsilon(1e-12));
      films += p.first.normal.stone_stiffness > 0.0;
    }
  CHECK(films > 0);  // the stone pairs that meet through a film
  const auto wall = vrut::rutting_wall_params(m, t), scaled_wall = vrut::rutting_wall_params(scaled, t);
  CHECK(scaled_wall.normal.stiffness == Approx(wall.normal.stiffness).epsilon(1e-12));
  CHECK_THROWS(vrut::scale_mastic(scaled, 0.0));
}
