// The skeleton's diagnostics (protocol/rutting/skeleton.hpp) on a case worked by
// hand: three columns of 1 mm disks standing on the floor under gravity,
// cut between their second and third disks. At rest each column passes
// down, across the cut, the weight of what stands above the cut in it:
//   A: a free stone disk under a rigid stone of three disks (its centroid
//      above the cut, so the whole stone is above): 3 m_s g, through a film
//      of zero thickness, so on the stones' spring;
//   B: four stone disks meeting through films 0.4 diameters thick, far
//      thicker than their weight squeezes: 2 m_s g on the film alone;
//   C: four mastic disks: 2 m_m g through mastic.
// And again with A's stone of three free disks (the method's exact stone)
// and C's disks bonded across gaps, not touching.
// m_s, m_m: a stone's and a mastic disk's mass, density times pi r^2 t.
#include "spaces.hpp"

#include <vrut/core/simulation.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/skeleton.hpp>
#include <vrut/servo/servo.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace {

constexpr double r = 1e-3, t = 0.05, g = 9.81;

struct Columns {
  vrut::ParticleSet set;
  std::vector<int> stone;  // each particle's stone, -1 mastic
  vrut::AssignmentTable<vrut::RuttingLaw> table{5};
  double m_stone = 0.0, m_mastic = 0.0;
};

// exact_and_bonded: column A's upper stone three free disks of one stone
// meeting bare (the method's exact stone, whose contacts within the stone
// are listed, not a rigid body's), and column C's mastic disks stacked with
// a gap of gap_r radii, held across it by the mastic's bonds.
constexpr double gap_r = 0.02;
Columns three_columns(bool exact_and_bonded = false) {
  Columns c;
  vrut::RuttingMaterials m;
  // The mastic's viscosities a million times over: in the run's 0.1 s its
  // contacts are then its Maxwell spring alone, so the columns come to rest.
  // (The real mastic's Kelvin element, 12 s to respond, keeps them creeping,
  // and the damped creep keeps the forces off the weights by about 1e-5.)
  vrut::BurgersMacro stiff = m.mastic;
  stiff.eta1 *= 1e6;
  stiff.eta2 *= 1e6;
  const auto mastic = vrut::mastic_params(stiff, t, m.mastic_nu, vrut::MicroConversion::seed(), 1.0, m.friction);
  const auto stone = vrut::stone_law_params(m, t, m.friction);
  auto film = [&](double thickness) {
    return vrut::RuttingLaw::make_first(
        vrut::film_params(mastic, thickness, stone.normal.stiffness, stone.shear.stiffness));
  };
  // Groups: 0 mastic; 1, 2 column A's stones (no film); 3, 4 column B's (0.4 d).
  c.table.set_all(vrut::RuttingLaw::make_first(vrut::film_params(mastic)));
  c.table.set(1, 2, film(0.0));
  c.table.set(3, 4, film(0.4 * 2.0 * r));
  if (exact_and_bonded) c.table.set(2, 2, vrut::RuttingLaw::make_second(stone));
  const double pi = std::acos(-1.0);
  c.m_stone = m.aggregate_density * pi * r * r * t;
  c.m_mastic = m.mastic_density * pi * r * r * t;
  // A and C from the bottom up; B from the top down, so that in its
  // contacts the first particle (the list's i) is the upper one.
  for (int k = 0; k < 4; ++k) {
    const double y = (2 * k + 1) * r;
    const int body = k == 0 || exact_and_bonded ? -1 : 0;
    c.set.add(10e-3, y, r, m.aggregate_density, k == 0 ? 1 : 2, body);  // A: disks 2-4 one stone
    c.stone.push_back(k == 0 ? 0 : 1);
    c.set.add(30e-3, exact_and_bonded ? y + 2.0 * gap_r * r * k : y, r, m.mastic_density, vrut::mastic_group);  // C
    c.stone.push_back(-1);
  }
  for (int k = 3; k >= 0; --k) {
    c.set.add(20e-3, (2 * k + 1) * r, r, m.aggregate_density, k % 2 == 0 ? 3 : 4);  // B
    c.stone.push_back(2 + k);
  }
  return c;
}

// The cut between the columns' second and third particles, over all three.
vrut::SkeletonCut cut_across_columns() {
  vrut::SkeletonCut cut;
  cut.height = 4.0 * r;
  cut.x0 = 0.0;
  cut.x1 = 40e-3;
  cut.diameter = 2.0 * r;
  return cut;
}

// What each column passes across the cut at rest, to within 1e-8 of its
// weight (1e-10 seen: the damped columns ring down in a few thousand steps
// of the 40,000); and the stones' films: A's one contact between two
// stones bears at once (no film), B's three lie on films of 0.4 diameters
// and do not bear.
void check_columns_weights(const vrut::SkeletonSnapshot& all, const Columns& c) {
  CHECK(all.load.stone_spring == Approx(3.0 * c.m_stone * g).epsilon(1e-8));
  CHECK(all.load.stone_film == Approx(2.0 * c.m_stone * g).epsilon(1e-8));
  CHECK(all.load.mastic == Approx(2.0 * c.m_mastic * g).epsilon(1e-8));
  CHECK(all.films.contacts[0] == 1);
  CHECK(all.films.bearing[0] == 1);
  CHECK(all.films.contacts[2] == 3);
  CHECK(all.films.bearing[2] == 0);
}

template <class Space>
using ColumnsSimulation =
    vrut::Simulation<vrut::RuttingLaw, Space, vrut::CentralDifference, vrut::LoadControl, vrut::RuttingWallLaw>;

// The columns on the floor under gravity, damped so that they come to rest
// as they run.
template <class Space>
std::unique_ptr<ColumnsSimulation<Space>> columns_on_floor(const Columns& c) {
  vrut::SimulationSettings settings;
  settings.thickness = t;
  settings.gravity = {0.0, -g};
  vrut::CentralDifference::params_type settle;
  settle.damping = 0.7;
  auto sim = std::make_unique<ColumnsSimulation<Space>>(c.set, c.table, settings, settle, Space());
  sim->add_wall(vrut::Wall{{0.0, 0.0}, {40e-3, 0.0}, {}}, vrut::rutting_wall_params(vrut::RuttingMaterials{}, t), {}, 0);
  return sim;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("the load path across a cut: three columns at rest, worked by hand", "[physics][skeleton]",
                        vrut_test::ExecutionSpaces) {
  using Space = TestType;
  Columns c = three_columns();
  auto sim_on_floor = columns_on_floor<Space>(c);
  auto& sim = *sim_on_floor;
  sim.run(40000, 0.3 * sim.critical_timestep());

  vrut::SkeletonCut cut = cut_across_columns();
  const vrut::SkeletonSnapshot all = vrut::skeleton_snapshot(sim, c.table, 0, cut, c.stone);
  check_columns_weights(all, c);
  const double total = 5.0 * c.m_stone + 2.0 * c.m_mastic;
  CHECK(all.load.share(all.load.stone_spring) == Approx(3.0 * c.m_stone / total).epsilon(1e-8));

  CHECK(all.films.total_contacts() == 4);

  // Under a plate over column C alone only the mastic carries the load.
  cut.x0 = 25e-3;
  cut.x1 = 35e-3;
  const vrut::SkeletonSnapshot c_only = vrut::skeleton_snapshot(sim, c.table, 0, cut, c.stone);
  CHECK(c_only.load.stone_spring == 0.0);
  CHECK(c_only.load.stone_film == 0.0);
  CHECK(c_only.load.mastic == Approx(2.0 * c.m_mastic * g).epsilon(1e-8));
}

// The same columns with an exact stone in A and a bonded mastic column in C
// whose disks never touch: the load path counts a bonded contact across its
// gap (C's weight crosses the cut through one), and a stone's contacts
// within itself are no stone pair (the census holds A's one pair, not three).
TEST_CASE("the load path across a cut: a bonded mastic gap and an exact stone, worked by hand", "[physics][skeleton]") {
  using Space = Kokkos::DefaultHostExecutionSpace;
  Columns c = three_columns(true);
  auto sim_on_floor = columns_on_floor<Space>(c);
  auto& sim = *sim_on_floor;
  // C's disks (every other one of the first eight), each bonded to the next across its gap.
  REQUIRE(sim.bond_pairs({{1, 3}, {3, 5}, {5, 7}}) == 3);
  sim.run(40000, 0.3 * sim.critical_timestep());

  const vrut::SkeletonSnapshot all = vrut::skeleton_snapshot(sim, c.table, 0, cut_across_columns(), c.stone);
  check_columns_weights(all, c);
  CHECK(all.films.total_contacts() == 4);
  // The gaps held: C's weight crossed the cut where no disks touch.
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  CHECK(x(5).y - x(3).y > 2.0 * r * (1.0 + 0.5 * gap_r));
}

TEST_CASE("a contact's class: mastic, stones on their film, stones on their spring", "[unit][skeleton]") {
  vrut::RuttingMaterials m;
  const auto mastic = vrut::mastic_params(m.mastic, t, m.mastic_nu, vrut::MicroConversion::seed(), 1.0, m.friction);
  const auto stone = vrut::stone_law_params(m, t, m.friction);
  const auto film = vrut::RuttingLaw::make_first(vrut::film_params(mastic, 0.2e-3, stone.normal.stiffness));
  CHECK(vrut::classify_contact(film, vrut::mastic_group, 2, 1e-3) == vrut::ContactClass::mastic);
  CHECK(vrut::classify_contact(film, 1, 2, 0.1e-3) == vrut::ContactClass::stone_film);
  CHECK(vrut::classify_contact(film, 1, 2, 0.3e-3) == vrut::ContactClass::stone_spring);
  // Stones meeting bare (--stone-film none) bear on their spring from the first touch.
  CHECK(vrut::classify_contact(vrut::RuttingLaw::make_second(stone), 1, 2, 1e-9) == vrut::ContactClass::stone_spring);
  // An endless film (no stone spring) never bears on the stones' spring.
  const auto endless = vrut::RuttingLaw::make_first(vrut::film_params(mastic, 0.2e-3, 0.0));
  CHECK(vrut::classify_contact(endless, 1, 2, 0.5e-3) == vrut::ContactClass::stone_film);
  CHECK(vrut::film_thickness(film, 2e-3) == Approx(0.1));
}

TEMPLATE_LIST_TEST_CASE("3D: the load path across a cut, the same three columns of spheres at rest",
                        "[physics][skeleton]", vrut_test::ExecutionSpaces) {
  using Space = TestType;
  Columns c = three_columns();  // its table; the spheres replace the disks
  vrut::RuttingMaterials m;
  const double pi = std::acos(-1.0), depth = 10e-3;
  c.m_stone = m.aggregate_density * 4.0 / 3.0 * pi * r * r * r;
  c.m_mastic = m.mastic_density * 4.0 / 3.0 * pi * r * r * r;
  vrut::ParticleSet set;  // in the order of the disks of three_columns()
  for (int k = 0; k < 4; ++k) {
    const double y = (2 * k + 1) * r;
    set.add_sphere(10e-3, y, 0.5 * depth, r, m.aggregate_density, k == 0 ? 1 : 2, k == 0 ? -1 : 0);
    set.add_sphere(30e-3, y, 0.5 * depth, r, m.mastic_density, vrut::mastic_group);
  }
  for (int k = 3; k >= 0; --k) set.add_sphere(20e-3, (2 * k + 1) * r, 0.5 * depth, r, m.aggregate_density, k % 2 == 0 ? 3 : 4);
  vrut::SimulationSettings3 settings;
  settings.gravity = {0.0, -g, 0.0};
  settings.box.high = {40e-3, 20e-3, depth};
  settings.box.periodic[2] = true;  // as the 3D test's box
  vrut::CentralDifference::params_type settle;
  settle.damping = 0.7;
  vrut::Simulation3<vrut::RuttingLaw, Space, vrut::CentralDifference, vrut::LoadControl, vrut::RuttingWallLaw> sim(
      set, c.table, settings, settle, Space());
  sim.add_wall(vrut::Wall3{{20e-3, 0.0, 0.5 * depth}, {0.0, 0.0, depth}, {20e-3, 0.0, 0.0}, {}},
               vrut::rutting_wall_params(m, t), {}, 0);
  sim.run(40000, 0.3 * sim.critical_timestep());

  vrut::SkeletonCut cut = cut_across_columns();
  const vrut::SkeletonSnapshot all = vrut::skeleton_snapshot(sim, c.table, 0, cut, c.stone);
  check_columns_weights(all, c);

  // Under a patch plate (its band across the depth): the columns stand at
  // mid-depth, so a band about them, or about their image a period away,
  // takes all they carry; a band beside them takes none of it.
  for (const double centre : {0.5 * depth, 1.5 * depth}) {
    cut.depth = vrut::DepthBand{centre, 0.2 * depth, depth};
    check_columns_weights(vrut::skeleton_snapshot(sim, c.table, 0, cut, c.stone), c);
  }
  cut.depth = vrut::DepthBand{0.1 * depth, 0.2 * depth, depth};
  const vrut::SkeletonSnapshot beside = vrut::skeleton_snapshot(sim, c.table, 0, cut, c.stone);
  CHECK(beside.load.stone_spring == 0.0);
  CHECK(beside.load.stone_film == 0.0);
  CHECK(beside.load.mastic == 0.0);
}

// A contact counts where it acts, not where its particles are: two stone
// disks (two stones through a film of zero thickness, so on the stones'
// spring, which bears on the whole overlap from the first step) leaning at 45 degrees across the cut, overlapping by 0.09 mm, their
// centres 1.35 mm apart in x and in y, so the contact's point lies half way
// between them in x. A plate over that point takes the pair's whole load,
// and a plate over either centre alone, but not the point, takes none of it
// (filtering on a particle's position would give the reverse). In 3D the
// same holds across the periodic depth: two spheres near the box's two
// faces (0.3 mm from each, 1.35 mm apart in height, so overlapping by
// 0.52 mm) meet through the boundary, at depth 0, not at mid-depth, where
// the mean of their stored depths lies.
TEST_CASE("the load path across a cut counts a contact at its point: a leaning pair, and one across the "
          "periodic depth", "[physics][skeleton]") {
  using Space = Kokkos::DefaultHostExecutionSpace;
  Columns c = three_columns();  // its table alone: groups 1 and 2 meet on the stones' spring
  const double reach = 1.35e-3, base = 3e-3;  // |d| = 1.909 mm, two radii 2 mm
  vrut::RuttingMaterials m;
  vrut::SkeletonCut cut;
  cut.height = base + 0.5 * reach;
  cut.diameter = 2.0 * r;
  const std::vector<int> two_stones{0, 1};

  vrut::ParticleSet pair;
  pair.add(10e-3, base, r, m.aggregate_density, 1);
  pair.add(10e-3 + reach, base + reach, r, m.aggregate_density, 2);
  vrut::SimulationSettings flat;
  flat.thickness = t;
  flat.gravity = {0.0, 0.0};
  ColumnsSimulation<Space> leaning(pair, c.table, flat, {}, Space());
  leaning.run(1, 0.3 * leaning.critical_timestep());  // the contact's load, pushing the pair apart
  auto snapshot = [&](auto& sim, double x0, double x1, vrut::DepthBand band = {}) {
    cut.x0 = x0, cut.x1 = x1, cut.depth = band;
    return vrut::skeleton_snapshot(sim, c.table, 0, cut, two_stones).load.stone_spring;
  };
  const double whole = snapshot(leaning, 0.0, 40e-3);
  CHECK(whole > 0.0);  // the lower disk pushes the upper one up, as under a weight
  const double point = 10e-3 + 0.5 * reach;
  CHECK(snapshot(leaning, point - 0.2e-3, point + 0.2e-3) == whole);
  CHECK(snapshot(leaning, 10e-3 - 0.2e-3, 10e-3 + 0.2e-3) == 0.0);                  // the lower centre alone
  CHECK(snapshot(leaning, 10e-3 + reach - 0.2e-3, 10e-3 + reach + 0.2e-3) == 0.0);  // the upper centre alone

  const double depth = 10e-3, dz = 0.6 * r, near_face = 0.5 * dz;
  vrut::ParticleSet across;
  across.add_sphere(10e-3, base, near_face, r, m.aggregate_density, 1);
  across.add_sphere(10e-3, base + reach, depth - near_face, r, m.aggregate_density, 2);
  vrut::SimulationSettings3 box;
  box.gravity = {0.0, 0.0, 0.0};
  box.box.high = {40e-3, 20e-3, depth};
  box.box.periodic[2] = true;
  vrut::Simulation3<vrut::RuttingLaw, Space, vrut::CentralDifference, vrut::LoadControl, vrut::RuttingWallLaw> periodic(
      across, c.table, box, {}, Space());
  periodic.run(1, 0.3 * periodic.critical_timestep());
  const double all_depth = snapshot(periodic, 0.0, 40e-3);
  CHECK(all_depth > 0.0);
  // Bands narrower than the centres' 0.3 mm from the faces: each holds the
  // contact's point, and neither centre, nor the centres' mean.
  const double narrow = 0.2e-3;
  CHECK(snapshot(periodic, 0.0, 40e-3, vrut::DepthBand{0.0, narrow, depth}) == all_depth);
  CHECK(snapshot(periodic, 0.0, 40e-3, vrut::DepthBand{depth, narrow, depth}) == all_depth);
  CHECK(snapshot(periodic, 0.0, 40e-3, vrut::DepthBand{near_face, narrow, depth}) == 0.0);          // the lower centre
  CHECK(snapshot(periodic, 0.0, 40e-3, vrut::DepthBand{depth - near_face, narrow, depth}) == 0.0);  // the upper centre
  CHECK(snapshot(periodic, 0.0, 40e-3, vrut::DepthBand{0.5 * depth, 0.2 * depth, depth}) == 0.0);
}
