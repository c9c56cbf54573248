// The 3D specimen (specimen/stone3.hpp, placement3.hpp, specimen3.hpp):
// convex hulls against solids worked by hand, the overlap test against an
// independent one, and placed stones that share no point.
#include "band_checks.hpp"
#include "separating_axes.hpp"
#include "small_box3.hpp"

#include <vrut/io/stones3_state.hpp>
#include <vrut/specimen/specimen3.hpp>
#include <vrut/specimen/specimens3.hpp>

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using vrut::Point3;

// The stones (and their images across the periodic depth) that hold x.
int stones_holding(const vrut::Placement3& p, const Point3& x) {
  int n = 0;
  for (const auto& s : p.stones)
    for (double image : {0.0, -p.depth, p.depth}) n += s.shape.contains(x + Point3(0.0, 0.0, image));
  return n;
}

// No two stones share a point, across the periodic depth too, decided
// exactly for every pair (separating_axes.hpp, not the library's test); and
// points at random in the box fall in a stone as often as the stones' volume
// fraction says, within four standard errors (a check on the volumes that
// does not use them).
void check_points_in_stones(const vrut::Placement3& p, const vrut::PlacementSettings3& ps, std::mt19937_64& rng) {
  const vrut_test::OverlapCount overlaps = vrut_test::overlapping_pairs(p);
  INFO(overlaps.pairs_near << " pairs of stones near each other; " << overlaps.overlapping
                           << " overlap, the deepest by " << overlaps.deepest << " mm");
  CHECK(overlaps.pairs_near > 0);
  CHECK(overlaps.overlapping == 0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 20000;
  int in = 0;
  for (int i = 0; i < n; ++i) in += stones_holding(p, Point3(ps.width * u(rng), ps.height * u(rng), ps.depth * u(rng))) > 0;
  const double f = p.achieved_fraction, se = std::sqrt(f * (1.0 - f) / n);
  CHECK(std::abs(static_cast<double>(in) / n - f) < 4.0 * se);
}

// The stones of 2.36 to 4.75 mm alone, at `fraction` of the box.
vrut::Stereology small_stones(double fraction) {
  vrut::Stereology st;
  st.classes = {{2.36, 4.75}};
  st.volume_fraction = {fraction};
  st.coarse_volume_fraction = fraction;
  return st;
}

vrut::PlacementSettings3 box3(double width, double height, double depth) {
  vrut::PlacementSettings3 ps;
  ps.width = width;
  ps.height = height;
  ps.depth = depth;
  return ps;
}

}  // namespace

TEST_CASE("3D stones: the hull of a cube's and an octahedron's corners, by hand", "[specimen3][unit]") {
  // A cube of side 2 with points inside it, which the hull drops.
  std::vector<Point3> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 3.0 : 1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  cube.emplace_back(2.0, 0.1, 0.2);
  cube.emplace_back(2.5, -0.3, 0.0);
  const vrut::Stone3 c = vrut::convex_hull_stone(cube);
  CHECK(c.vertices.size() == 8);
  CHECK(c.volume == Approx(8.0).epsilon(1e-12));
  CHECK((c.centroid - Point3(2.0, 0.0, 0.0)).norm() < 1e-12);
  CHECK(c.reach == Approx(std::sqrt(3.0)).epsilon(1e-12));
  CHECK(c.contains(Point3(2.9, 0.9, -0.9)));
  CHECK_FALSE(c.contains(Point3(3.01, 0.0, 0.0)));
  CHECK_FALSE(c.contains(Point3(2.0, 0.0, -1.01)));
  // Every face plane holds three corners and has all of them on its inner side.
  for (const auto& p : c.planes) {
    int on = 0;
    for (const auto& v : cube) {
      CHECK(p.head<3>().dot(v) <= p[3] + 1e-12);
      on += std::abs(p.head<3>().dot(v) - p[3]) < 1e-12;
    }
    CHECK(on >= 3);
  }
  // Its section at any height inside is the 2 x 2 square; none outside.
  CHECK(vrut::section_at_z(c, 0.3).area() == Approx(4.0).epsilon(1e-12));
  CHECK(vrut::section_at_z(c, 1.2).vertices.empty());
  // The octahedron |x| + |y| + |z| <= a: volume 4 a^3 / 3.
  const double a = 1.5;
  const std::vector<Point3> octa{{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
  const vrut::Stone3 o = vrut::convex_hull_stone(octa);
  CHECK(o.volume == Approx(4.0 * a * a * a / 3.0).epsilon(1e-12));
  CHECK(o.centroid.norm() < 1e-12);
  CHECK(vrut::section_at_z(o, 0.5 * a).area() == Approx(0.5 * a * a).epsilon(1e-12));  // |x| + |y| <= a / 2
  CHECK(o.contains(Point3(0.49 * a, 0.49 * a, 0.0)));
  CHECK_FALSE(o.contains(Point3(0.4 * a, 0.4 * a, 0.3 * a)));
}

TEST_CASE("3D stones: a random stone's volume against Monte Carlo, and its shape's bounds", "[specimen3][unit]") {
  std::mt19937_64 rng(5);
  vrut::StoneShape3 shape;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 5; ++k) {
    const double r0 = 4.0;
    const vrut::Stone3 s = vrut::random_stone3(r0, shape, rng);
    CHECK(s.centroid.norm() < 1e-12);
    CHECK(s.vertices.size() >= 4);
    CHECK(s.vertices.size() <= static_cast<std::size_t>(shape.max_vertices));
    // The vertices were drawn at r0 (1 +- R/R0) from the point the stone
    // was built about, which lies inside it: no two are farther apart than
    // twice the largest radius.
    for (const auto& v : s.vertices)
      for (const auto& w : s.vertices) CHECK((v - w).norm() <= 2.0 * r0 * (1.0 + shape.radius_fluctuation) + 1e-9);
    // Points in the bounding cube: the fraction inside is the volume's share,
    // to within four standard errors.
    const double half = s.reach, box = 8.0 * half * half * half;
    const int n = 200000;
    int in = 0;
    for (int i = 0; i < n; ++i) in += s.contains(Point3(half * u(rng), half * u(rng), half * u(rng)));
    const double f = s.volume / box, se = std::sqrt(f * (1.0 - f) / n);
    CHECK(std::abs(static_cast<double>(in) / n - f) < 4.0 * se);
    // And the sections' areas summed through the stone (midpoint rule, 4000
    // slices: the area is piecewise quadratic in z, error below 1e-6).
    double by_slices = 0.0;
    const int slices = 4000;
    for (int k = 0; k < slices; ++k) by_slices += vrut::section_at_z(s, -half + (k + 0.5) * 2.0 * half / slices).area();
    CHECK(by_slices * 2.0 * half / slices == Approx(s.volume).epsilon(1e-5));
  }
}

// Against an independent test on the same stones: a face plane of either
// that has the whole other stone beyond it separates them (no overlap); a
// point inside both proves an overlap. Pairs that neither decides (those
// parted only across edges) are left out. The exact separating-axis test
// that the placement checks use (separating_axes.hpp) must agree with both,
// and with the library's test on every pair not within rounding of touching.
TEST_CASE("3D stones: the overlap test agrees with separating planes and shared points", "[specimen3][unit]") {
  std::mt19937_64 rng(9);
  vrut::StoneShape3 shape;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int apart = 0, overlapping = 0;
  for (int k = 0; k < 400; ++k) {
    const vrut::Stone3 a = vrut::random_stone3(2.0, shape, rng), b = vrut::random_stone3(1.5, shape, rng);
    const Point3 shift = 3.2 * Point3(u(rng), u(rng), u(rng));
    vrut::Stone3 moved = b;
    moved.translate(shift);
    auto separates = [](const vrut::Stone3& s, const vrut::Stone3& t) {
      for (const auto& p : s.planes) {
        bool all_beyond = true;
        for (const auto& v : t.vertices) all_beyond = all_beyond && p.head<3>().dot(v) > p[3];
        if (all_beyond) return true;
      }
      return false;
    };
    bool shared = false;
    for (int i = 0; i < 4000 && !shared; ++i) {
      const Point3 x = 2.5 * Point3(u(rng), u(rng), u(rng));
      shared = a.contains(x) && moved.contains(x);
    }
    const bool found = vrut::stones_overlap(a, b, shift);
    CHECK(found == vrut::stones_overlap(a, moved));  // the shift is the same as a move
    // The exact test that the placements' checks use (separating_axes.hpp)
    // agrees, wherever the pair is not within rounding of touching.
    const double apart_by = vrut_test::separation(a, moved);
    if (std::abs(apart_by) > 1e-9) CHECK(found == (apart_by < 0.0));
    if (separates(a, moved) || separates(moved, a)) {
      ++apart;
      CHECK_FALSE(found);
      CHECK(apart_by >= 0.0);
    } else if (shared) {
      ++overlapping;
      CHECK(found);
      CHECK(apart_by < 0.0);
    }
  }
  CHECK(apart > 50);
  CHECK(overlapping > 50);
}

TEST_CASE("3D placement: stones share no point, across the periodic depth too", "[specimen3][placement]") {
  for (int mix : {1}) {
    const auto s = vrut_test::small_box3(mix, 3);
    std::mt19937_64 rng(s.seed);
    vrut::PlacementSettings3 ps = s.placement;
    const vrut::Placement3 p = vrut::place_stones3(vrut::stereology(s.gradation, s.mix), ps, rng);
    CHECK(p.achieved_fraction == Approx(p.target_fraction).margin(0.01));
    INFO("mix " << mix << "#: " << p.stones.size() << " stones, " << p.jammed << " jammed");
    check_points_in_stones(p, ps, rng);
    for (const auto& st : p.stones) {
      const auto b = st.shape.bounds();
      CHECK(b.min().x() >= 0.0);
      CHECK(b.max().x() <= ps.width);
      CHECK(b.min().y() >= 0.0);
      CHECK(b.max().y() <= ps.height);
      CHECK(st.shape.centroid.z() >= 0.0);
      CHECK(st.shape.centroid.z() < ps.depth);
    }
  }
}

TEST_CASE("3D specimen: a sphere belongs to the stone that holds its centre", "[specimen3][placement]") {
  auto s = vrut_test::small_box3(1, 4);
  s.sphere_radius = 1.0;
  const vrut::Specimen3 sp = vrut::generate_specimen3(s);
  CHECK(sp.depth == Approx(vrut::fcc_cells_deep(40.0, 1.0) * vrut::fcc_cell(1.0)));
  for (std::size_t i = 0; i < sp.spheres.centers.size(); ++i) {
    const Point3& c = sp.spheres.centers[i];
    int holder = vrut::mastic_site;
    for (std::size_t k = 0; k < sp.placement.stones.size() && holder < 0; ++k)
      for (double image : {0.0, -sp.depth, sp.depth})
        if (sp.placement.stones[k].shape.contains(c + Point3(0.0, 0.0, image))) holder = static_cast<int>(k);
    CHECK(sp.spheres.stone[i] == holder);
  }
  const auto set = vrut::to_particle_set(sp, 2400.0, 2700.0);
  CHECK(set.size() == sp.spheres.centers.size());
}

// A resumed 3D run takes its stones from the checkpoint (io/stones3_state.hpp)
// instead of placing them again; the specimen built on them must be the one
// generate_specimen3 builds, bit for bit, after the trip through CBOR that
// the checkpoint file makes.
TEST_CASE("3D specimen: built on its stones read back from a checkpoint item, the same specimen bit for bit",
          "[specimen3][checkpoint]") {
  auto s = vrut_test::small_box3(1, 4);
  s.sphere_radius = 1.0;
  const vrut::Specimen3 sp = vrut::generate_specimen3(s);
  const nlohmann::json state = nlohmann::json::from_cbor(nlohmann::json::to_cbor(vrut::stones3_state(sp.placement)));
  const vrut::Specimen3 again = vrut::specimen3_on_stones(s, vrut::placement_from_stones3_state(state, "test"));
  REQUIRE(again.placement.stones.size() == sp.placement.stones.size());
  for (std::size_t k = 0; k < sp.placement.stones.size(); ++k) {
    const auto& a = sp.placement.stones[k];
    const auto& b = again.placement.stones[k];
    CHECK(a.size_class == b.size_class);
    CHECK(a.diameter == b.diameter);
    CHECK(a.shape.vertices == b.shape.vertices);
    CHECK(a.shape.planes == b.shape.planes);
    CHECK(a.shape.centroid == b.shape.centroid);
    CHECK(a.shape.volume == b.shape.volume);
    CHECK(a.shape.reach == b.shape.reach);
  }
  CHECK(again.placement.achieved_fraction == sp.placement.achieved_fraction);
  CHECK(again.placement.jammed == sp.placement.jammed);
  CHECK(again.spheres.centers == sp.spheres.centers);
  CHECK(again.spheres.stone == sp.spheres.stone);
  CHECK(again.spheres.bonds == sp.spheres.bonds);
  CHECK(again.spheres.stone_pairs == sp.spheres.stone_pairs);
  CHECK(again.spheres.removed_for_voids == sp.spheres.removed_for_voids);

  SECTION("stones of another box, or items that do not agree, are refused") {
    auto deeper = s;
    deeper.placement.depth = 60.0;
    CHECK_THROWS_AS(vrut::specimen3_on_stones(deeper, vrut::placement_from_stones3_state(state, "test")),
                    std::invalid_argument);
    nlohmann::json short_of_one = state;
    short_of_one.erase("reach");
    CHECK_THROWS_AS(vrut::placement_from_stones3_state(short_of_one, "test"), vrut::CheckpointError);
    vrut::Placement3 fewer = sp.placement;
    fewer.stones.front().shape.planes.pop_back();
    nlohmann::json mixed = vrut::stones3_state(fewer);
    mixed["planes"] = state["planes"];  // the counts of one placement, the planes of another
    CHECK_THROWS_AS(vrut::placement_from_stones3_state(mixed, "test"), vrut::CheckpointError);
  }
}

// An ensemble's specimens placed two at a time (specimen/specimens3.hpp):
// each must be the specimen its seed gives alone, and a seed whose
// specimen cannot be made must be named.
TEST_CASE("3D specimens of an ensemble placed two at a time: each is its seed's, and a failure names its seed",
          "[specimen3][placement]") {
  auto s = vrut_test::small_box3(1, 1);
  s.sphere_radius = 1.5;
  const std::vector<std::uint64_t> seeds = {11, 12, 13};
  std::vector<int> started(seeds.size(), 0), done(seeds.size(), 0);
  const auto together = vrut::generate_specimens3(
      s, seeds, 2, [&](std::size_t i) { ++started[i]; }, [&](std::size_t i) { ++done[i]; });
  REQUIRE(together.size() == seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    INFO("seed " << seeds[i]);
    CHECK(started[i] == 1);
    CHECK(done[i] == 1);
    auto one = s;
    one.seed = seeds[i];
    const vrut::Specimen3 alone = vrut::generate_specimen3(one);
    CHECK(together[i].settings.seed == seeds[i]);
    REQUIRE(together[i].placement.stones.size() == alone.placement.stones.size());
    for (std::size_t k = 0; k < alone.placement.stones.size(); ++k)
      CHECK(together[i].placement.stones[k].shape.vertices == alone.placement.stones[k].shape.vertices);
    CHECK(together[i].spheres.centers == alone.spheres.centers);
    CHECK(together[i].spheres.stone == alone.spheres.stone);
  }

  SECTION("a specimen whose stones find no room: its seed is named") {
    auto cramped = s;
    cramped.packing = vrut::StonePacking3::random_addition;  // no compaction to fall back on
    cramped.placement.attempts = 1;
    cramped.placement.jiggle_rounds = 0;
    try {
      vrut::generate_specimens3(cramped, {21, 22, 23}, 2);
      FAIL("one try per stone and no jiggling placed a whole 1# specimen");
    } catch (const vrut::SpecimenSeedError& e) {
      CHECK(e.seed() == 21);  // every seed fails so; the first in the list is the one told
      CHECK(std::string(e.what()).rfind("seed 21: cannot reach the stones' volume fraction", 0) == 0);
    }
  }
}

namespace {

// The stones' volume fraction in each of `bands` equal slabs across the
// height (by_height) or the width, by points drawn at random in each.
std::vector<double> band_fractions3(const vrut::Specimen3& sp, int bands, bool by_height, std::mt19937_64& rng) {
  vrut::StoneLocator3 locate(sp.placement, sp.width, sp.height);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int points = 20000;
  std::vector<double> out(bands);
  for (int b = 0; b < bands; ++b) {
    int in = 0;
    for (int i = 0; i < points; ++i) {
      const double across = (b + u(rng)) / bands;
      const Point3 x(by_height ? u(rng) * sp.width : across * sp.width, by_height ? across * sp.height : u(rng) * sp.height,
                     u(rng) * sp.depth);
      in += locate(x) >= 0;
    }
    out[b] = static_cast<double>(in) / points;
  }
  return out;
}

// As the 2D test (test_specimen.cpp, "the jiggling placement fills the
// section evenly"): over several specimens, the stones' volume fraction of
// each interior band (those not touching the mould) equals the interior's
// mean within four standard errors of the band's mean; the bands at the
// mould, lower, are the wall effect, printed. Uniform placement fails a band
// at odds of about 1 in 220 (the 2D test's reckoning: 6 specimens).
void check_even_fill(int mix, double width,
                     vrut::StonePacking3 packing = vrut::StonePacking3::automatic) {
  constexpr int seeds = 6, bands = 5;
  std::vector<std::vector<double>> rows(bands), columns(bands);
  std::mt19937_64 points(77);
  int jammed = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    auto s = vrut_test::small_box3(mix, seed);
    s.placement.width = width;
    s.sphere_radius = 2.0;  // the lattice is not looked at here
    s.packing = packing;
    const vrut::Specimen3 sp = vrut::generate_specimen3(s);
    jammed += sp.placement.jammed;
    const auto r = band_fractions3(sp, bands, true, points), c = band_fractions3(sp, bands, false, points);
    for (int b = 0; b < bands; ++b) rows[b].push_back(r[b]), columns[b].push_back(c[b]);
  }
  std::printf("mix %d#, 3D, %g x 50 x 40 mm: %d stones jammed over %d specimens\n", mix, width, jammed, seeds);
  const std::string mix_name = "mix " + std::to_string(mix) + "#, 3D, ";
  vrut_test::check_interior_bands(rows, mix_name + "height");
  vrut_test::check_interior_bands(columns, mix_name + "width");
}

}  // namespace

TEST_CASE("3D placement: the stones fill the box evenly (1#)", "[specimen3][placement]") { check_even_fill(1, 100.0); }

// The same for 2#, whose stones jam and are jiggled into place: 110 s for
// the six specimens on one core, so it is hidden ([.]) and left out of the
// default suite (tests/CMakeLists.txt lists no hidden test).
// Run it with: vrut-tests "[specimen3-slow]"
TEST_CASE("3D placement: the stones fill the box evenly (2#)", "[.][specimen3-slow][placement]") {
  check_even_fill(2, 100.0);
}

// And for 3#, whose stones random addition cannot place: compacted
// (compaction3.hpp), about 2.5 minutes a specimen on one core.
TEST_CASE("3D placement: the compacted stones fill the box evenly (3#)", "[.][specimen3-slow][placement]") {
  check_even_fill(3, 100.0, vrut::StonePacking3::compaction);
}

// The compaction's cheap test before MPR (compaction3.hpp, gap_along): the
// gap along a direction between two cubes worked by hand, across the
// periodic depth too; and on random stones, a positive gap along any
// direction is a true separation by the exact test (separating_axes.hpp).
// That the slack and the directions kept pass by no pair that MPR would
// find touching rests on the compaction pin and the threads test below.
TEST_CASE("3D compaction: the gap along a direction, by hand and against separating axes", "[specimen3][unit]") {
  vrut::detail::CompactedStone a, b;
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) a.vertices.emplace_back(x, y, z);  // a cube of side 2 about its centre
  // b the same cube with its vertices 0.5 mm off its centre along x (so a
  // gap that took a's nearest and b's farthest would differ), centred at x 3:
  // it spans x 2.5 to 4.5, a -1 to 1.
  for (const Point3& v : a.vertices) b.vertices.push_back(v + Point3(0.5, 0.0, 0.0));
  b.centre = Point3(3.0, 0.0, 0.0);
  CHECK(vrut::detail::gap_along(a, b, Point3::Zero(), Point3::UnitX()) == Approx(1.5));
  CHECK(vrut::detail::gap_along(a, b, Point3::Zero(), -Point3::UnitX()) == Approx(-5.5));  // b is not beyond a that way
  // Along the diagonal (1, 1, 0)/sqrt 2: a reaches 2/sqrt 2, b begins at (3 - 1.5)/sqrt 2.
  CHECK(vrut::detail::gap_along(a, b, Point3::Zero(), Point3(1.0, 1.0, 0.0).normalized()) ==
        Approx(-0.5 / std::sqrt(2.0)));
  // b 37 mm along the depth, its image one depth of 40 mm back: 3 mm apart, a gap of 1.
  b.centre = Point3(0.0, 0.0, 37.0);
  CHECK(vrut::detail::gap_along(a, b, Point3(0.0, 0.0, -40.0), -Point3::UnitZ()) == Approx(1.0));

  std::mt19937_64 rng(11);
  vrut::StoneShape3 shape;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int apart = 0;
  for (int k = 0; k < 2000; ++k) {
    const vrut::Stone3 sa = vrut::random_stone3(2.0, shape, rng), sb = vrut::random_stone3(1.5, shape, rng);
    vrut::detail::CompactedStone ca, cb;
    ca.vertices = sa.vertices, cb.vertices = sb.vertices;  // centroids at the origin
    cb.centre = 3.5 * Point3(u(rng), u(rng), u(rng));
    const Point3 along = Point3(u(rng), u(rng), u(rng)).normalized();
    if (vrut::detail::gap_along(ca, cb, Point3::Zero(), along) <= 1e-9) continue;
    ++apart;
    vrut::Stone3 moved = sb;
    moved.translate(cb.centre);
    CHECK(vrut_test::separation(sa, moved) > 0.0);
  }
  CHECK(apart > 100);
}

// Compaction (compaction3.hpp) of stones of two classes, 2.36-4.75 and
// 4.75-9.5 mm, to 0.60 of a 30 x 25 x 20 mm box. What it must give, checked
// by means it does not use: no point in two stones (its own check is
// libccd's overlap test), every stone inside the box, and the share of
// random points in a stone equal to the stones' volume fraction within four
// standard errors (so the moved stones keep their volumes). And each stone
// is its loose self moved as a rigid body: the distances between its
// vertices are those of the stone random addition placed.
TEST_CASE("3D compaction: the stones reach 0.60 of a small box and share no point", "[specimen3][placement]") {
  vrut::Stereology st;
  st.classes = {{2.36, 4.75}, {4.75, 9.5}};
  st.volume_fraction = {0.20, 0.40};
  st.coarse_volume_fraction = 0.60;
  const vrut::PlacementSettings3 ps = box3(30.0, 25.0, 20.0);
  const vrut::CompactionSettings3 cs;  // about 11,000 steps, 10 s
  std::mt19937_64 rng(5), loose_rng(5);
  const vrut::Placement3 p = vrut::compact_stones3(st, ps, cs, rng);
  INFO(p.stones.size() << " stones, " << p.compaction_steps << " steps");
  CHECK(p.compaction_steps > cs.lid_steps);
  CHECK(p.achieved_fraction == Approx(0.60).margin(0.01));
  check_points_in_stones(p, ps, rng);
  // The loose placement that the compaction began from, drawn again from the same stream.
  vrut::Stereology loose = st;
  const double loose_height = ps.height * st.coarse_volume_fraction / cs.loose_fraction;
  for (double& v : loose.volume_fraction) v *= ps.height / loose_height;
  loose.coarse_volume_fraction *= ps.height / loose_height;
  vrut::PlacementSettings3 tall = ps;
  tall.height = loose_height;
  const vrut::Placement3 before = vrut::place_stones3(loose, tall, loose_rng);
  REQUIRE(before.stones.size() == p.stones.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < p.stones.size(); ++k) {
    const auto& a = before.stones[k].shape.vertices;
    const auto& b = p.stones[k].shape.vertices;
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = i + 1; j < a.size(); ++j)
        worst = std::max(worst, std::abs((b[i] - b[j]).norm() - (a[i] - a[j]).norm()));
    const auto box = p.stones[k].shape.bounds();
    CHECK(box.min().x() >= 0.0);
    CHECK(box.max().x() <= ps.width);
    CHECK(box.min().y() >= 0.0);
    CHECK(box.max().y() <= ps.height);
  }
  CHECK(worst < 1e-9);  // mm: rounding of the turns, on stones of a few mm
  // A regression pin of the packing (renewed only on purpose, as the
  // rutting pins): the steps, and where three stones came to rest, bit for
  // bit. The compaction of 3# is this code on 3#'s classes; its smallest box
  // that compacts (40 x 50 x 39.6 mm) takes about a minute, and smaller ones
  // jam (30 x 30 x 38 and 26 x 26 x 38 mm: 60,000 steps without settling),
  // so the pin is on this box. Pinned 2026-12-04.
  const std::size_t middle = p.stones.size() / 2, last = p.stones.size() - 1;
  for (std::size_t k : {std::size_t{0}, middle, last})
    std::printf("compaction pin: stone %zu of %zu at (%.17g, %.17g, %.17g), %ld steps\n", k, p.stones.size(),
                p.stones[k].shape.centroid.x(), p.stones[k].shape.centroid.y(), p.stones[k].shape.centroid.z(),
                p.compaction_steps);
  REQUIRE(p.stones.size() == 408);
  CHECK(p.compaction_steps == 9288);
  CHECK(p.stones[0].shape.centroid == Point3(22.680493672239297, 18.931146446602419, 18.276917903520062));
  CHECK(p.stones[middle].shape.centroid == Point3(8.8316167691918004, 13.823233599891875, 15.744388010091631));
  CHECK(p.stones[last].shape.centroid == Point3(19.967914640648289, 5.0367512690355758, 2.2175685715586146));
}

// A stone whose centre wraps across the periodic depth keeps its contacts
// with the stones across it. Until 2026-12-03 a pair kept the image it was
// found with until the next search, so a stone that wrapped between two
// searches went through its neighbours across the depth unseen: in this
// shallow box at 0.60, seeds 1, 2 and 5 ended with 2 to 5 pairs overlapping
// and the compaction threw (5 of seeds 1-12), as did two of 3#'s five
// specimens of 300 x 50 x 42 mm. The packing is checked by means the
// compaction does not use (random points, as above).
TEST_CASE("3D compaction: a stone that wraps across the depth keeps its contacts", "[specimen3][placement]") {
  const vrut::Stereology st = small_stones(0.60);
  const vrut::PlacementSettings3 ps = box3(15.0, 12.0, 10.0);
  const vrut::CompactionSettings3 cs;  // about 9,000 steps, 5 s a seed
  for (const unsigned seed : {1u, 2u, 5u}) {
    INFO("seed " << seed);
    std::mt19937_64 rng(seed);
    vrut::Placement3 p;
    REQUIRE_NOTHROW(p = vrut::compact_stones3(st, ps, cs, rng));
    CHECK(p.compaction_steps > cs.lid_steps);
    check_points_in_stones(p, ps, rng);
  }
}

// A packing that jams under the lid keeps some pairs nearer than the
// compaction's clearance (0.001 mm) for good: 3#'s seed 2 in the whole
// 300 x 50 x 39.6 mm box did, after its 60,000 settling steps, with none
// overlapping, and was refused after 25 minutes. Such a packing is kept
// where the placement's own test passes, the pairs counted. Here a jam is
// made by cutting the settling short: the wrapping test's box and seed 1,
// which settles after 3,921 steps (its packing as the pin's code makes it:
// a new packing on purpose may move that). At 3,800 it stops with pairs
// within the clearance and none overlapping; at 3,920 the last step's move
// has settled it, which one more look finds.
TEST_CASE("3D compaction: a packing jammed within the clearance is kept, its pairs counted", "[specimen3][placement]") {
  const vrut::Stereology st = small_stones(0.60);
  const vrut::PlacementSettings3 ps = box3(15.0, 12.0, 10.0);
  vrut::CompactionSettings3 cs;
  cs.settle_steps = 3800;
  std::mt19937_64 rng(1);
  vrut::Placement3 p;
  REQUIRE_NOTHROW(p = vrut::compact_stones3(st, ps, cs, rng));
  CHECK(p.compaction_steps == cs.lid_steps + cs.settle_steps);  // it did not settle
  CHECK(p.pairs_within_clearance + p.stones_within_clearance_of_a_wall > 0);
  check_points_in_stones(p, ps, rng);  // yet no two share a point
  for (const auto& stone : p.stones) {
    const auto box = stone.shape.bounds();
    CHECK((box.min().x() >= 0.0 && box.max().x() <= ps.width && box.min().y() >= 0.0 && box.max().y() <= ps.height));
  }
  cs.settle_steps = 3920;
  std::mt19937_64 rng_again(1);
  const vrut::Placement3 settled = vrut::compact_stones3(st, ps, cs, rng_again);
  CHECK(settled.compaction_steps == cs.lid_steps + cs.settle_steps);
  CHECK(settled.pairs_within_clearance == 0);
  CHECK(settled.stones_within_clearance_of_a_wall == 0);
}

// The compaction on several threads (each pair's contact found alone, the
// forces added in the pairs' order) is the one-thread compaction, bit for
// bit: the same steps, the same stones where they came to rest.
TEST_CASE("3D compaction: three threads give the one-thread packing, bit for bit", "[specimen3][placement]") {
  const vrut::Stereology st = small_stones(0.50);
  const vrut::PlacementSettings3 ps = box3(12.0, 10.0, 10.0);
  vrut::CompactionSettings3 one;
  one.lid_steps = 2000;
  vrut::CompactionSettings3 three = one;
  three.threads = 3;
  std::mt19937_64 rng_one(8), rng_three(8);
  const vrut::Placement3 a = vrut::compact_stones3(st, ps, one, rng_one);
  const vrut::Placement3 b = vrut::compact_stones3(st, ps, three, rng_three);
  INFO(a.stones.size() << " stones, " << a.compaction_steps << " steps");
  REQUIRE(a.compaction_steps > one.lid_steps);  // it compacted
  CHECK(b.compaction_steps == a.compaction_steps);
  REQUIRE(b.stones.size() == a.stones.size());
  bool same = true;
  for (std::size_t k = 0; k < a.stones.size(); ++k)
    same = same && a.stones[k].shape.vertices == b.stones[k].shape.vertices;
  CHECK(same);
  CHECK(rng_one() == rng_three());  // the streams went on alike
  one.threads = 0;
  CHECK_THROWS_AS(vrut::compact_stones3(st, ps, one, rng_one), std::invalid_argument);
}

