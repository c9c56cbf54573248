// The 3D rutting run's own checks (rutting/run3.hpp).
#include "small_box3.hpp"

#include <vrut/rutting/run3.hpp>

#include <catch2/catch.hpp>

#include <vector>

// As in 2D ("a disk outside its mould stops the run, saying where"): a
// sphere that leaves its mould through a wall, or far over the top, stops
// the run as unstable, naming the sphere, its three coordinates and the
// time step.
TEST_CASE("3D: a sphere outside its mould stops the run, saying where", "[rutting3][instability]") {
  vrut::SpecimenSettings3 s = vrut_test::small_box3(1, 5, 40.0);
  s.sphere_radius = 2.0;
  const std::vector<vrut::Specimen3> specimens{vrut::generate_specimen3(s)};
  vrut::AssignmentTable<vrut::Linear> table(2);
  table.set_all(vrut::linear_params(1e5, 0.0, 0.0));
  vrut::SimulationSettings3 settings;
  vrut::Simulation3<vrut::Linear, Kokkos::DefaultHostExecutionSpace> sim(
      vrut::to_particle_set(specimens[0], 2400.0, 2700.0), table, settings, {0.0});
  const double dt = 0.3 * sim.critical_timestep();
  CHECK_NOTHROW(vrut::check_inside_moulds(sim, specimens, 7, dt));  // as generated: inside
  const int sphere = 5;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  const vrut::Vec3 was = x(sphere);
  // Beyond a radius past the walls x = 0 and x = 40 mm, over twice the 50 mm
  // height; the depth is periodic, so z is never outside.
  for (const vrut::Vec3 outside : {vrut::Vec3{-0.0025, 0.005, 0.01}, vrut::Vec3{0.0425, 0.005, 0.01},
                                   vrut::Vec3{0.02, 0.101, 0.01}}) {
    x(sphere) = outside;
    Kokkos::deep_copy(sim.particles().position, x);
    INFO("sphere at (" << outside.x << ", " << outside.y << ", " << outside.z << ") m");
    CHECK_THROWS_AS(vrut::check_inside_moulds(sim, specimens, 7, dt), vrut::SimulationUnstable);
    CHECK_THROWS_WITH(vrut::check_inside_moulds(sim, specimens, 7, dt),
                      Catch::Contains("by loading step 7") && Catch::Contains("sphere 5 of specimen 0") &&
                          Catch::Contains(", 10) mm") && Catch::Contains("outside its 40 x 50 mm mould") &&
                          Catch::Contains("0.3 of sqrt"));
  }
  x(sphere) = was;
  Kokkos::deep_copy(sim.particles().position, x);
  CHECK_NOTHROW(vrut::check_inside_moulds(sim, specimens, 7, dt));
}
