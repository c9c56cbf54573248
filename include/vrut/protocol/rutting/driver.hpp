#pragma once
/// \file
/// The virtual wheel-tracking (rutting) test, one driver for 2D and 3D
/// (docs/method.md sections 1, 5 and 6): specimens -> DE model -> moulds ->
/// settling under gravity -> a loading plate on each, a dead load ramped up
/// to the wheel's pressure -> loading for the cumulative time under the wheel,
/// reduced by alpha_T -> deformation curves, rut depths, dynamic stability.
/// What differs between a 2D section and a 3D box is the Setup
/// (section.hpp, box.hpp): the particles, the law table, the moulds and the
/// plate; everything else is here. The test's definition is test.hpp, its
/// materials materials.hpp, what it measures result.hpp.
///
/// Every specimen of an ensemble runs side by side in one Simulation: each
/// kernel launch serves them all, and each specimen gets its own mould and
/// plate and exactly the result of its own single run (the time step is the
/// smallest any of them needs). progress(fraction of the loading time done,
/// steps done). stop() is asked at every sample: when it says true (Ctrl-C,
/// say) the run ends there, with the samples so far and `interrupted` set.
///
/// Checkpoints (io/checkpoint.hpp has CheckpointFile): checkpoints->due() is
/// asked at every sample, and when it says true, or when the run is stopped,
/// checkpoints->save(visit) writes the state. When checkpoints->resuming(), the
/// run reads its state with checkpoints->load(visit) in place of settling and
/// goes on from there, with the same results as a run never stopped.
///
/// settling(steps done, settle steps) follows the settling under gravity,
/// every 500 steps (a resumed run does not settle). stop() is first asked at
/// the loading's first sample, so a stop asked for while settling takes
/// effect there, with a checkpoint of the settled specimens.
#include <vrut/core/energy_check.hpp>
#include <vrut/core/simulation.hpp>
#include <vrut/protocol/rutting/checks.hpp>
#include <vrut/protocol/rutting/loading.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/skeleton.hpp>
#include <vrut/protocol/rutting/test.hpp>
#include <vrut/protocol/rutting/timestep_report.hpp>
#include <vrut/servo/servo.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

namespace vrut {

struct NoCheckpoints {
  bool resuming() const { return false; }
  bool due() const { return false; }
  template <class Visit> void save(Visit&&) {}
  template <class Visit> void load(Visit&&) {}
};

/// A 2D run's pictures of its particles (result.hpp, RuttingSnapshot), item
/// by item, for a checkpoint.
template <class Archive>
void visit_snapshots(Archive& archive, const std::string& id, std::vector<RuttingSnapshot>& snapshots) {
  int shots = static_cast<int>(snapshots.size());
  archive.value(id + "snapshots", shots);
  snapshots.resize(shots);
  for (int k = 0; k < shots; ++k) {
    RuttingSnapshot& shot = snapshots[k];
    const std::string sid = id + "snapshot_" + std::to_string(k) + "_";
    archive.value(sid + "fraction", shot.fraction);
    archive.vector(sid + "x", shot.x);
    archive.vector(sid + "y", shot.y);
    archive.vector(sid + "dx", shot.dx);
    archive.vector(sid + "dy", shot.dy);
  }
}

template <class Setup, class Space, class Checkpoints = NoCheckpoints>
std::vector<typename Setup::result_type> run_rutting_test(const Setup& setup, const WheelTracking& wt,
                                                          const RuttingNumerics& num, const Space& space,
                                                          const std::function<void(double, long)>& progress,
                                                          const std::function<bool()>& stop, Checkpoints* checkpoints,
                                                          const std::function<void(long, long)>& settling) {
  using vector = typename Setup::vector;
  const bool resuming = checkpoints != nullptr && checkpoints->resuming();
  const auto& specimens = setup.specimens;
  const int count = static_cast<int>(specimens.size());
  CentralDifference::params_type integrator;
  integrator.damping = num.settle_damping;
  Simulation<RuttingLaw, Space, CentralDifference, LoadControl, RuttingWallLaw, typename Setup::dimension> sim(
      setup.particles, setup.table, setup.settings, integrator, space);
  std::vector<typename Setup::result_type> out(count);
  auto result = [&](int e) -> RuttingResult& { return Setup::base(out[e]); };
  sim.bond_pairs(setup.bonds);
  for (int e = 0; e < count; ++e) {
    setup.begin(out[e], e);
    result(e).bonds = sim.intact_bonds(e);
    result(e).particles = setup.particle_count(e);
  }

  const auto wall_law = setup.wall_law();
  const double k_wall = wall_law.normal.stiffness;
  for (int e = 0; e < count; ++e) setup.add_mould(sim, wall_law, e);
  const double dt = num.timestep_safety * sim.critical_timestep();
  for (int e = 0; e < count; ++e) result(e).time_step = timestep_report(sim, setup.table);

  // Settling under gravity (a resumed run reads where it had got to instead).
  // The energy check (core/energy_check.hpp) counts the loads' work from here.
  auto energy_reference = host_positions_copy(sim);
  LoadingState<vector> state(count, dt);
  std::vector<double>& top = state.top;
  if (!resuming) run_checking_energy(sim, num.settle_steps, dt, energy_reference, settling);

  /// The plates, each on the highest particle under it; the load brings it
  /// down. It is loaded like the wheel itself: a dead load. A PFC servo
  /// (ServoControl) sets its speed from the stiffness of the wall contacts; on
  /// a flowing mastic under stiff aggregate contacts it lags far behind the
  /// target (docs/rutting.md), while the dead load holds the pressure.
  const double l = wt.plate_length();
  const LoadingPlan plan = loading_plan(wt, num, dt);
  const double t_load = plan.t_load;
  const long steps = plan.steps;
  std::vector<int> plate(count);
  std::vector<double> plate_mass(count);
  {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
    for (int e = 0; e < count; ++e) {
      RuttingResult& res = result(e);
      res.dt = dt;
      const double width = specimens[e].width * 1e-3;
      res.plate_x0 = 0.5 * (width - l);
      res.plate_x1 = 0.5 * (width + l);
      const double r = Setup::radius_mm(specimens[e]) * 1e-3;
      const auto [first, last] = sim.specimen_range(e);
      const DepthBand band = setup.plate_band();
      for (int i = first; i < last; ++i)
        if (x(i).x + r > res.plate_x0 && x(i).x - r < res.plate_x1 && in_depth_band(band, x(i), r))
          top[e] = std::max(top[e], x(i).y + r);
      plate_mass[e] = setup.plate_mass(k_wall, dt, e);
      res.plate_mass = plate_mass[e];
      plate[e] = sim.add_wall(setup.plate(e, top[e]), wall_law, setup.plate_load(0.0, plate_mass[e]), e);
    }
  }
  // The skeleton (skeleton.hpp): cut half way between the floor and the
  // plate where it is now (a deep rut brings the plate near the specimen's
  // first mid-height), under the plate.
  auto skeleton = [&](int e) {
    SkeletonCut cut;
    cut.height = 0.5 * Setup::plate_point(sim.wall(plate[e])).y;
    cut.x0 = result(e).plate_x0;
    cut.x1 = result(e).plate_x1;
    cut.depth = setup.plate_band();
    cut.diameter = 2e-3 * Setup::radius_mm(specimens[e]);
    return skeleton_snapshot(sim, setup.table, e, cut, Setup::stone_of(specimens[e]));
  };
  for (int e = 0; e < count; ++e) result(e).skeleton.films_start = skeleton(e).films;
  auto ramp_to = [&](double fraction) {
    for (int e = 0; e < count; ++e) sim.set_controller(plate[e], setup.plate_load(fraction, plate_mass[e]));
  };
  CentralDifference::params_type loading;
  loading.damping = num.damping;
  sim.set_integrator(loading);

  Kokkos::View<vector*, typename Space::memory_space> start("loading_start", setup.particles.size());
  Kokkos::deep_copy(start, sim.particles().position);
  /// Pictures at a third, two thirds and the end of the loading, where the setup keeps them.
  int next_snapshot = 1;
  auto snapshot = [&](double fraction) {
    if constexpr (Setup::snapshots) setup.snapshot(sim, start, fraction, out);
  };
  const double to_minutes = wt.minutes / t_load;
  for (int e = 0; e < count; ++e) state.last_plate_position[e] = Setup::plate_point(sim.wall(plate[e]));
  // The whole state of the run between two steps, item by item (Simulation::visit_state).
  auto visit = [&](auto& archive) {
    sim.visit_state(archive);
    archive.view("loading_start", start);
    state.visit(archive);
    if constexpr (Setup::snapshots) archive.value("next_snapshot", next_snapshot);
    archive.view("energy_reference", energy_reference);
    for (int e = 0; e < count; ++e) {
      const std::string id = "specimen_" + std::to_string(e) + "_";
      archive.vector(id + "samples", result(e).samples);
      result(e).skeleton.visit(archive, id);
      if constexpr (Setup::snapshots) visit_snapshots(archive, id, result(e).snapshots);
    }
  };
  state.begin = std::chrono::steady_clock::now();
  if (resuming) {
    checkpoints->load(visit);
    state.resumed(dt);
  }
  auto take_snapshots = [&](long s) {
    if constexpr (Setup::snapshots)
      if (next_snapshot <= 3 && (s >= steps * next_snapshot / 3)) {
        snapshot(next_snapshot / 3.0);
        ++next_snapshot;
      }
  };
  auto take_sample = [&](long s, double time) {
    check_inside_moulds(sim, specimens, s, dt);
    check_clear_of_plate_images(sim, specimens, setup.plate_band(), result(0).plate_x0, result(0).plate_x1, s);
    const auto& walls = sim.all_walls();
    const std::vector<vector> impulse = sim.all_wall_impulses();
    for (int e = 0; e < count; ++e) {
      const auto& w = walls[plate[e]];
      const vector at = Setup::plate_point(w);
      RuttingSample smp;
      smp.reduced_time = time;
      smp.minutes = time * to_minutes;
      smp.deformation = top[e] - at.y;
      smp.plate_pressure = state.plate_sample(e, impulse[plate[e]], at, inward_normal(w), time, setup.plate_area());
      smp.plate_speed = dot(w.velocity, inward_normal(w));
      result(e).samples.push_back(smp);
      LoadPath& early = result(e).skeleton.load_early;
      if (!early.measured() && smp.minutes >= SkeletonRecord::early_minute) {
        early = skeleton(e).load;
        early.minutes = smp.minutes;
      }
    }
    check_energy(sim, energy_reference, state.plate_work, s, dt);
  };
  const long done = run_loading(sim, plan, state, ramp_to, take_snapshots, take_sample, progress, stop, checkpoints, visit);
  if (done < steps) {
    if constexpr (Setup::snapshots)
      if (next_snapshot <= 3) snapshot(static_cast<double>(done) * dt / t_load);
    for (int e = 0; e < count; ++e) result(e).interrupted = true;
  }
  Kokkos::fence();
  const double seconds = state.seconds();
  const auto& walls = sim.all_walls();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), start);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().velocity);
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().group);
  for (int e = 0; e < count; ++e) {
    RuttingResult& res = result(e);
    res.wall_seconds = seconds;
    res.steps = done;
    res.contacts = sim.active_contacts(e);
    std::tie(res.stones, res.stone_pairs_touching) =
        touching_stones(sim, Setup::stone_of(specimens[e]), Setup::stone_count(specimens[e]), e);
    res.plate_y_final = Setup::plate_point(walls[plate[e]]).y;
    const SkeletonSnapshot end = skeleton(e);
    res.skeleton.films_end = end.films;
    res.skeleton.load_end = end.load;
    res.skeleton.load_end.minutes = res.samples.empty() ? 0.0 : res.samples.back().minutes;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      Setup::record_particle(out[e], x(i), x0(i), v(i));
      res.group.push_back(g(i) == mastic_group ? mastic_group : aggregate_group);  // colours and bins are stones
    }
    finish_deformation(res, wt);
  }
  return out;
}

}  // namespace vrut
