// vrut::Choice, one of two laws per material pair: a slot keeps the state of
// the law that acts there only, and bonds asked for before the first force
// behave as if both halves had been bonded (contact/choice.hpp).
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/vrut.hpp>

#include <catch2/catch.hpp>

#include <algorithm>

namespace {

using vrut::Choice;
using vrut::ContactGeometry;

ContactGeometry at_overlap(double overlap, double shear_increment = 0.0) {
  ContactGeometry g;
  g.normal = {1.0, 0.0};
  g.overlap = overlap;
  g.shear_increment = shear_increment;
  g.dt = 1e-6;
  return g;
}

const double kn = 1.0e6, ks = 5.0e5, strength = 10.0;

}  // namespace

TEST_CASE("a choice's slot holds the state of one law, not of both", "[laws][unit]") {
  using Law3 = vrut::in_dimension_t<vrut::RuttingLaw, vrut::Dim3>;
  using Storage = Law3::state_type::Storage;
  const std::size_t first = sizeof(vrut::in_dimension_t<vrut::BurgersFilmBonded, vrut::Dim3>::state_type);
  const std::size_t second = sizeof(vrut::in_dimension_t<vrut::DampedLinearBonded, vrut::Dim3>::state_type);
  CHECK(sizeof(Storage) == std::max(first, second));
  // The tag and the waiting bond fit in the storage's alignment padding.
  CHECK(sizeof(Law3::state_type) <= std::max(first, second) + alignof(Law3::state_type));
  CHECK(sizeof(Law3::state_type) < first + second);
}

TEST_CASE("a bond asked for before the first force is made on the law that acts", "[laws][unit]") {
  using Law = Choice<vrut::Linear, vrut::LinearBonded>;
  const auto bonded_second = Law::make_second(vrut::linear_bonded_params(kn, ks, 0.5, strength, strength));
  const auto bare_first = Law::make_first(vrut::linear_params(kn, ks, 0.5));

  Law::state_type s{};
  CHECK_FALSE(Law::bonded(s));
  Law::bond(s);
  CHECK(Law::bonded(s));
  // Pulled apart by 1 um: the bonded law carries k * gap = 1 N of tension.
  const auto f = Law::force(bonded_second, s, at_overlap(-1e-6));
  CHECK(f.normal == Approx(-kn * 1e-6).epsilon(1e-12));
  CHECK(Law::bonded(s));

  // Where the law that acts holds no bond, the contact is bonded until its
  // first force (as when both halves were bonded) and then not, and it
  // carries no tension.
  Law::state_type t{};
  Law::bond(t);
  CHECK(Law::bonded(t));
  CHECK(Law::force(bare_first, t, at_overlap(-1e-6)).normal == 0.0);
  CHECK_FALSE(Law::bonded(t));
}

TEST_CASE("a choice of two laws without bonds is never bonded", "[laws][unit]") {
  using Law = Choice<vrut::Linear, vrut::Linear>;
  Law::state_type s{};
  Law::bond(s);
  CHECK_FALSE(Law::bonded(s));
}

TEST_CASE("a broken bond of a choice stays broken, and its law keeps its shear history until forgotten", "[laws][unit]") {
  using Law = Choice<vrut::Linear, vrut::LinearBonded>;
  const auto p = Law::make_second(vrut::linear_bonded_params(kn, ks, 0.5, strength, strength));
  Law::state_type s{};
  Law::bond(s);
  // Twice the strength in tension breaks it at once; afterwards no tension.
  CHECK(Law::force(p, s, at_overlap(-2.0 * strength / kn)).normal == 0.0);
  CHECK_FALSE(Law::bonded(s));
  CHECK(Law::force(p, s, at_overlap(-1e-6)).normal == 0.0);
  // In compression the shear spring accumulates over steps: two slips of
  // 1 um give k_s * 2 um (below the friction limit 0.5 * k_n * 10 um).
  Law::force(p, s, at_overlap(1e-5, 1e-6));
  const auto f = Law::force(p, s, at_overlap(1e-5, 1e-6));
  CHECK(std::abs(f.shear) == Approx(ks * 2e-6).epsilon(1e-12));
  // Forgotten (the pair was apart), it starts again from a fresh state.
  vrut::forget_contact<Law>(s);
  CHECK(std::abs(Law::force(p, s, at_overlap(1e-5, 1e-6)).shear) == Approx(ks * 1e-6).epsilon(1e-12));
}
