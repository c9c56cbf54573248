// The engine's contact list in 3D, with periodic axes (core/contact_list.hpp)
// against brute force over every pair by the nearest image, on every
// backend; a pair seen across a periodic face, and the inputs refused.
#include "spaces.hpp"

#include <vrut/contact/composite.hpp>
#include <vrut/core/contact_list.hpp>
#include <vrut/neighbor/periodic_box3.hpp>

#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

using Pairs = std::set<std::pair<int, int>>;

template <class Space>
Pairs found(const std::vector<vrut::Vec3>& centres, const std::vector<double>& radii, const vrut::PeriodicBox3& box,
            double skin) {
  const int n = static_cast<int>(centres.size());
  vrut::Particles<typename Space::memory_space, vrut::Dim3> ps(n);
  auto hx = Kokkos::create_mirror_view(ps.position);
  auto hr = Kokkos::create_mirror_view(ps.radius);
  for (int i = 0; i < n; ++i) hx(i) = centres[i], hr(i) = radii[i];
  Kokkos::deep_copy(ps.position, hx);
  Kokkos::deep_copy(ps.radius, hr);
  vrut::ContactList<vrut::in_dimension_t<vrut::Linear, vrut::Dim3>, Space, vrut::Dim3> list;
  list.box = box;
  list.rebuild(Space(), ps, skin);
  auto count = vrut_test::to_host(list.count);
  auto partner = vrut_test::to_host(list.partner);
  Pairs pairs;
  int misordered = 0;  // partners must exceed i, ascending
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < count(i); ++k) {
      misordered += partner(i, k) <= i || (k > 0 && partner(i, k) <= partner(i, k - 1));
      pairs.insert({i, partner(i, k)});
    }
  CHECK(misordered == 0);
  return pairs;
}

Pairs brute_force(const std::vector<vrut::Vec3>& c, const std::vector<double>& r, const vrut::PeriodicBox3& box,
                  double skin) {
  Pairs pairs;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j) {
      const vrut::Vec3 d = box.separation(c[i], c[j]);
      const double reach = r[i] + r[j] + skin;
      if (vrut::dot(d, d) < reach * reach) pairs.insert({static_cast<int>(i), static_cast<int>(j)});
    }
  return pairs;
}

}  // namespace

// 3,000 spheres of 0.8 to 1.2 mm at random in a 30 x 20 x 15 mm box (some
// a little outside it along the walled axes), every choice of periodic
// axes: the cell list finds exactly the pairs brute force finds.
TEMPLATE_LIST_TEST_CASE("the 3D cell list finds every pair brute force finds, periodic or not", "[unit][neighbor3]",
                        vrut_test::ExecutionSpaces) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  vrut::PeriodicBox3 box;
  box.low = {0.0, 0.0, 0.0};
  box.high = {0.030, 0.020, 0.015};
  std::vector<vrut::Vec3> c;
  std::vector<double> r;
  for (int i = 0; i < 3000; ++i) {
    c.push_back({-0.001 + 0.032 * u(rng), -0.001 + 0.022 * u(rng), 0.015 * u(rng)});
    r.push_back(0.0008 + 0.0004 * u(rng));
  }
  for (int mask = 0; mask < 8; ++mask) {
    for (int k = 0; k < 3; ++k) box.periodic[k] = (mask >> k) & 1;
    // Along a periodic axis the spheres lie inside the box.
    std::vector<vrut::Vec3> inside = c;
    for (auto& p : inside) p = box.wrapped(p);
    const Pairs expected = brute_force(inside, r, box, 1e-4);
    INFO("periodic axes mask " << mask << ": " << expected.size() << " pairs");
    REQUIRE(expected.size() > 3000);
    CHECK(found<TestType>(inside, r, box, 1e-4) == expected);
  }
}

TEMPLATE_LIST_TEST_CASE("a pair is seen across a periodic face, and not across a wall", "[unit][neighbor3]",
                        vrut_test::ExecutionSpaces) {
  vrut::PeriodicBox3 box;
  box.low = {0.0, 0.0, -0.005};
  box.high = {0.010, 0.010, 0.005};
  box.periodic[2] = true;
  const std::vector<vrut::Vec3> c{{0.005, 0.005, -0.0049}, {0.005, 0.005, 0.0049}, {0.0001, 0.005, 0.0},
                                  {0.0099, 0.005, 0.0}};
  const std::vector<double> r{0.001, 0.001, 0.001, 0.001};
  const Pairs pairs = found<TestType>(c, r, box, 0.0);
  CHECK(pairs == Pairs{{0, 1}});  // 0.2 mm apart through z; 2 and 3 lie 9.8 mm apart, x is walled
  const vrut::Vec3 d = box.separation(c[0], c[1]);
  CHECK(d.z == Approx(-0.0002).epsilon(1e-9));
  CHECK(d.x == 0.0);
  // Wrapping: a centre past the face comes back through the other.
  CHECK(box.wrapped({0.005, 0.005, 0.0062}).z == Approx(-0.0038).epsilon(1e-12));
  CHECK(box.wrapped({0.012, 0.005, 0.0}).x == 0.012);  // walled: left alone
  box.high.y = 0.0055;  // 5.5 mm along y, periodic: 3 reaches of 2 mm do not fit
  box.periodic[1] = true;
  const std::vector<vrut::Vec3> low{{0.005, 0.002, 0.0}};
  CHECK_THROWS_WITH(found<TestType>(low, {0.001}, box, 0.0), Catch::Contains("at least 3 contact reaches"));
}
