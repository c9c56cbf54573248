#pragma once
// The virtual wheel-tracking (rutting) test run, docs/method.md sections 1,
// 5 and 6: specimen -> DE model with the four interactions -> mould (bottom
// and side walls) -> settling under gravity -> a loading plate of contact
// length l = m g / (p d) at mid-span, servo-controlled to the pressure p ->
// loading for the cumulative time T = 60 min * l / travel, reduced by
// alpha_T -> deformation curve, rut depth, dynamic stability. The test's
// definition is protocol/rutting/test.hpp, its materials protocol/rutting/materials.hpp, what
// it measures protocol/rutting/result.hpp.
#include <vrut/core/simulation.hpp>
#include <vrut/core/energy_check.hpp>
#include <vrut/protocol/rutting/loading.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/skeleton.hpp>
#include <vrut/protocol/rutting/test.hpp>
#include <vrut/protocol/rutting/timestep_report.hpp>
#include <vrut/servo/servo.hpp>
#include <vrut/specimen/colouring.hpp>
#include <vrut/specimen/specimen.hpp>
#include <vrut/specimen/stone_reach.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace vrut {

struct RuttingNumerics {
  double shift = 1e4;                // alpha_T
  double timestep_safety = 0.3;
  // Local damping while loading. 0: the mastic's viscosity is the physical damping, and
  // local damping would act as an extra dashpot that grows with alpha_T (docs/validation.md).
  double damping = 0.0;
  double settle_damping = 0.7;
  long settle_steps = 4000;          // under gravity, before the plate comes down
  double ramp_fraction = 0.02;       // of the loading time, for the plate force to rise
  int samples = 240;                 // points of the deformation curve

  void validate() const {
    if (!(timestep_safety > 0.0 && timestep_safety <= 1.0)) throw std::invalid_argument("time-step safety must lie in (0, 1]");
    if (samples < 10) throw std::invalid_argument("at least 10 samples");
  }
};

// The loading's time (the test's, reduced by alpha_T), its steps of dt, the
// plates' load rising over ramp_fraction of them, and the samples.
inline LoadingPlan loading_plan(const WheelTracking& wt, const RuttingNumerics& num, double dt) {
  LoadingPlan plan;
  plan.dt = dt;
  plan.t_load = wt.loading_time() / num.shift;
  plan.steps = static_cast<long>(std::ceil(plan.t_load / dt));
  plan.ramp_steps = std::max(1L, static_cast<long>(num.ramp_fraction * plan.steps));
  plan.samples = num.samples;
  return plan;
}

// What check_inside_moulds says of a 2D specimen's particles; run3.hpp adds
// the 3D ones (found at instantiation by their argument types).
inline double mould_particle_radius_mm(const Specimen& s) { return s.disks.radius; }
inline const char* mould_particle_word(const Specimen&) { return "disk"; }
inline std::string mould_position_text(const Vec2& p) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.4g, %.4g)", p.x * 1e3, p.y * 1e3);
  return text;
}

// Throws SimulationUnstable when a disk (a sphere in 3D) has left its mould
// (through a wall or over the top): a run with too large a time step can push
// disks through the stiff walls without any single step jumping far enough
// for the engine's own check. Called at every sample.
template <class Sim, class SpecimenT>
void check_inside_moulds(Sim& sim, const std::vector<SpecimenT>& specimens, long step, double dt) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  for (int e = 0; e < static_cast<int>(specimens.size()); ++e) {
    const double w = specimens[e].width * 1e-3, h = specimens[e].height * 1e-3;
    const double r = mould_particle_radius_mm(specimens[e]) * 1e-3;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      const auto p = x(i);
      const double px = p.x, py = p.y;
      if (!(px > -r && px < w + r && py > -r && py < 2.0 * h)) {
        char where[400];
        std::snprintf(where, sizeof where, "%s %d of specimen %d (%.200s) is at %s mm, outside its %g x %g mm mould",
                      mould_particle_word(specimens[e]), i - first, e, specimens[e].name.c_str(),
                      mould_position_text(p).c_str(), w * 1e3, h * 1e3);
        char text[700];
        std::snprintf(text, sizeof text,
                      "vrut: the rutting run became unstable by loading step %ld: %s. The time step is %.3g of "
                      "sqrt(m_min / k_max); lower the time-step safety (RuttingNumerics::timestep_safety, 0.3 by default).",
                      step, where, dt / sim.critical_timestep());
        throw SimulationUnstable(text, step);
      }
    }
  }
}

// The pairs of stones of specimen e that touch at the end, found in the
// contact list (every overlapping pair of particles is in it), and the
// stones that hold particles. stone[i]: particle i's stone in the specimen
// (-1 for mastic), of stone_count.
template <class Sim>
std::pair<int, int> touching_stones(const Sim& sim, const std::vector<int>& stone, std::size_t stone_count, int e) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().radius);
  auto partner = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.contacts().partner);
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.contacts().count);
  const auto box = sim.contacts().box;  // the nearest image across a periodic axis
  const auto [first, last] = sim.specimen_range(e);
  std::vector<std::pair<int, int>> pairs;
  std::vector<char> holds(stone_count, 0);
  for (int i = first; i < last; ++i) {
    if (stone[i - first] >= 0) holds[stone[i - first]] = 1;
    for (int k = 0; k < count(i); ++k) {
      const int j = partner(i, k);
      const int a = stone[i - first], b = stone[j - first];
      if (a >= 0 && b >= 0 && a != b && norm(box.separation(x(i), x(j))) < r(i) + r(j))
        pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  const int distinct = static_cast<int>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  int stones = 0;
  for (char h : holds) stones += h;
  return {stones, distinct};
}

// Runs the test on every specimen of an ensemble side by side in one
// Simulation: each kernel launch serves them all, and each specimen gets its
// own mould and plate and exactly the result of its own single run (the time
// step is the smallest any of them needs; with one disk radius it is the same
// for all). progress(fraction of the loading time done, steps done). stop()
// is asked at every sample: when it says true (Ctrl-C, say) the run ends
// there, with the samples so far, a last snapshot, and `interrupted` set.
//
// Checkpoints (io/checkpoint.hpp has CheckpointFile): checkpoints->due() is
// asked at every sample, and when it says true, or when the run is stopped,
// checkpoints->save(visit) writes the state. When checkpoints->resuming(), the
// run reads its state with checkpoints->load(visit) in place of settling and
// goes on from there, with the same results as a run never stopped.
//
// settling(steps done, settle steps) follows the settling under gravity,
// every 500 steps (a resumed run does not settle). stop() is first asked at
// the loading's first sample, so a stop asked for while settling takes
// effect there, with a checkpoint of the settled specimens.
struct NoCheckpoints {
  bool resuming() const { return false; }
  bool due() const { return false; }
  template <class Visit> void save(Visit&&) {}
  template <class Visit> void load(Visit&&) {}
};

template <class Space, class Checkpoints = NoCheckpoints>
std::vector<RuttingResult> run_rutting_ensemble(const std::vector<Specimen>& specimens, const WheelTracking& wt,
                                                const RuttingMaterials& mat, const RuttingNumerics& num,
                                                const Space& space = Space(),
                                                const std::function<void(double, long)>& progress = {},
                                                const std::function<bool()>& stop = {},
                                                Checkpoints* checkpoints = nullptr,
                                                const std::function<void(long, long)>& settling = {}) {
  const bool resuming = checkpoints != nullptr && checkpoints->resuming();
  if (specimens.empty()) throw std::invalid_argument("an ensemble needs at least one specimen");
  num.validate();
  const int count = static_cast<int>(specimens.size());
  for (const Specimen& sp : specimens) wt.validate(sp.width * 1e-3);
  const double t = wt.wheel_width;
  // Where stones meet through a film, each stone's disks get its colour's
  // group; the margin (two disk diameters) covers how far neighbours close in.
  std::vector<std::vector<int>> colours(count);
  int stone_colours = 1;
  const bool films = mat.films();
  if (films)
    for (int e = 0; e < count; ++e) {
      colours[e] = colour_aggregates(specimens[e].placement, 4.0 * specimens[e].disks.radius);
      for (int c : colours[e]) stone_colours = std::max(stone_colours, c + 1);
    }
  for (const Specimen& sp : specimens)
    if (sp.disks.radius != specimens[0].disks.radius)
      throw std::invalid_argument("an ensemble's specimens must share one disk size");
  const auto table = rutting_table(mat, t, num.shift, stone_colours, 2e-3 * specimens[0].disks.radius);
  SimulationSettings settings;
  settings.thickness = t;
  settings.gravity = {0.0, -wt.gravity};
  CentralDifference::params_type integrator;
  integrator.damping = num.settle_damping;
  ParticleSet all;
  std::vector<std::pair<int, int>> bonds;
  for (int e = 0; e < count; ++e) {
    const Specimen& sp = specimens[e];
    const int offset = static_cast<int>(all.size());
    ParticleSet set = to_particle_set(sp, mat.mastic_density, mat.aggregate_density);
    if (films) set.group = rutting_groups(sp, mat, colours[e]);
    if (mat.rigid_stones) set.body = stone_bodies(sp);
    all.append_specimen(set);
    for (const auto& [i, j] : sp.disks.bonds) bonds.emplace_back(i + offset, j + offset);
  }
  Simulation<RuttingLaw, Space, CentralDifference, LoadControl, RuttingWallLaw> sim(all, table, settings, integrator, space);
  std::vector<RuttingResult> results(count);
  sim.bond_pairs(bonds);
  for (int e = 0; e < count; ++e) {
    results[e].bonds = sim.intact_bonds(e);
    results[e].particles = specimens[e].disks.centers.size();
  }

  // Each mould: bottom and both sides, linear and (by default) frictionless.
  const auto wall_law = rutting_wall_params(mat, t);
  const double k_wall = wall_law.normal.stiffness;
  for (int e = 0; e < count; ++e) {
    const double width = specimens[e].width * 1e-3, height = specimens[e].height * 1e-3;
    sim.add_wall(Wall{{0.0, 0.0}, {width, 0.0}, {}}, wall_law, {}, e);
    sim.add_wall(Wall{{0.0, 2.0 * height}, {0.0, 0.0}, {}}, wall_law, {}, e);
    sim.add_wall(Wall{{width, 0.0}, {width, 2.0 * height}, {}}, wall_law, {}, e);
  }
  const double dt = num.timestep_safety * sim.critical_timestep();
  for (auto& res : results) res.time_step = timestep_report(sim, table);

  // Settling under gravity (a resumed run reads where it had got to instead).
  // The energy check (energy_check.hpp) counts the loads' work from here.
  auto energy_reference = host_positions_copy(sim);
  LoadingState<Vec2> state(count, dt);
  std::vector<double>& top = state.top;
  if (!resuming) run_checking_energy(sim, num.settle_steps, dt, energy_reference, settling);

  // The plates, each on the highest disk under it; the load brings it down.
  const double l = wt.plate_length();
  const LoadingPlan plan = loading_plan(wt, num, dt);
  const double t_load = plan.t_load;
  const long steps = plan.steps;
  auto host_x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  std::vector<int> plate(count);
  std::vector<double> plate_mass(count);
  for (int e = 0; e < count; ++e) {
    RuttingResult& res = results[e];
    res.dt = dt;
    const double width = specimens[e].width * 1e-3;
    res.plate_x0 = 0.5 * (width - l);
    res.plate_x1 = 0.5 * (width + l);
    const double r = specimens[e].disks.radius * 1e-3;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i)
      if (host_x(i).x + r > res.plate_x0 && host_x(i).x - r < res.plate_x1) top[e] = std::max(top[e], host_x(i).y + r);
    // The plate is loaded like the wheel itself: a dead load. A PFC servo
    // (ServoControl) sets its speed from the stiffness of the wall contacts; on
    // a flowing mastic under stiff aggregate contacts it lags far behind the
    // target (docs/rutting.md), while the dead load holds the pressure.
    // Its mass is numerical: ten times the least that keeps the plate stable on
    // stiff contacts with every disk under it (k N dt^2 / 4), so that its
    // inertia hardly shows in the measured pressure.
    plate_mass[e] = 10.0 * k_wall * (l / (2.0 * r)) * dt * dt / 4.0;
    plate[e] = sim.add_wall(Wall{{res.plate_x1, top[e]}, {res.plate_x0, top[e]}, {}}, wall_law,
                            LoadControl::for_stress(0.0, l, t, plate_mass[e], 0.0), e);
  }
  // The skeleton (protocol/rutting/skeleton.hpp): cut half way between the floor and
  // the plate where it is now (a deep rut brings the plate near the
  // specimen's first mid-height), under the plate.
  auto skeleton = [&](int e) {
    SkeletonCut cut;
    cut.height = 0.5 * sim.wall(plate[e]).start.y;
    cut.x0 = results[e].plate_x0;
    cut.x1 = results[e].plate_x1;
    cut.diameter = 2e-3 * specimens[e].disks.radius;
    return skeleton_snapshot(sim, table, e, cut, specimens[e].disks.aggregate);
  };
  for (int e = 0; e < count; ++e) results[e].skeleton.films_start = skeleton(e).films;
  auto ramp_to = [&](double fraction) {
    const double stress = wt.plate_force() * fraction / (wt.contact_length() * t);  // the pressure, either section
    for (int e = 0; e < count; ++e)
      sim.set_controller(plate[e], LoadControl::for_stress(stress, l, t, plate_mass[e], 0.0));
  };
  CentralDifference::params_type loading;
  loading.damping = num.damping;
  sim.set_integrator(loading);

  Kokkos::View<Vec2*, typename Space::memory_space> start("loading_start", all.size());
  Kokkos::deep_copy(start, sim.particles().position);
  auto snapshot = [&](double fraction) {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
    auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), start);
    for (int e = 0; e < count; ++e) {
      RuttingSnapshot s;
      s.fraction = fraction;
      const auto [first, last] = sim.specimen_range(e);
      for (int i = first; i < last; ++i) {
        s.x.push_back(x(i).x);
        s.y.push_back(x(i).y);
        s.dx.push_back(x(i).x - x0(i).x);
        s.dy.push_back(x(i).y - x0(i).y);
      }
      results[e].snapshots.push_back(std::move(s));
    }
  };

  const double to_minutes = wt.minutes / t_load;
  int next_snapshot = 1;
  for (int e = 0; e < count; ++e) state.last_plate_position[e] = sim.wall(plate[e]).start;
  // The whole state of the run between two steps, item by item (Simulation::visit_state).
  auto visit = [&](auto& archive) {
    sim.visit_state(archive);
    archive.view("loading_start", start);
    state.visit(archive);
    archive.value("next_snapshot", next_snapshot);
    archive.view("energy_reference", energy_reference);
    for (int e = 0; e < count; ++e) {
      const std::string id = "specimen_" + std::to_string(e) + "_";
      archive.vector(id + "samples", results[e].samples);
      results[e].skeleton.visit(archive, id);
      int shots = static_cast<int>(results[e].snapshots.size());
      archive.value(id + "snapshots", shots);
      results[e].snapshots.resize(shots);
      for (int k = 0; k < shots; ++k) {
        RuttingSnapshot& shot = results[e].snapshots[k];
        const std::string sid = id + "snapshot_" + std::to_string(k) + "_";
        archive.value(sid + "fraction", shot.fraction);
        archive.vector(sid + "x", shot.x);
        archive.vector(sid + "y", shot.y);
        archive.vector(sid + "dx", shot.dx);
        archive.vector(sid + "dy", shot.dy);
      }
    }
  };
  state.begin = std::chrono::steady_clock::now();
  if (resuming) {
    checkpoints->load(visit);
    state.resumed(dt);
  }
  auto take_snapshots = [&](long s) {
    if (next_snapshot <= 3 && (s >= steps * next_snapshot / 3)) {
      snapshot(next_snapshot / 3.0);
      ++next_snapshot;
    }
  };
  auto take_sample = [&](long s, double time) {
    check_inside_moulds(sim, specimens, s, dt);
    const std::vector<Wall>& walls = sim.all_walls();
    const std::vector<Vec2> impulse = sim.all_wall_impulses();
    for (int e = 0; e < count; ++e) {
      const Wall& w = walls[plate[e]];
      RuttingSample smp;
      smp.reduced_time = time;
      smp.minutes = time * to_minutes;
      smp.deformation = top[e] - w.start.y;
      smp.plate_pressure = state.plate_sample(e, impulse[plate[e]], w.start, inward_normal(w), time, l * t);
      results[e].samples.push_back(smp);
      LoadPath& early = results[e].skeleton.load_early;
      if (!early.measured() && smp.minutes >= SkeletonRecord::early_minute) {
        early = skeleton(e).load;
        early.minutes = smp.minutes;
      }
    }
    check_energy(sim, energy_reference, state.plate_work, s, dt);
  };
  const long done = run_loading(sim, plan, state, ramp_to, take_snapshots, take_sample, progress, stop, checkpoints, visit);
  if (done < steps) {
    if (next_snapshot <= 3) snapshot(static_cast<double>(done) * dt / t_load);
    for (auto& r : results) r.interrupted = true;
  }
  Kokkos::fence();
  const double seconds = state.seconds();
  const std::vector<Wall>& walls = sim.all_walls();
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().velocity);
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().group);
  for (int e = 0; e < count; ++e) {
    RuttingResult& res = results[e];
    res.wall_seconds = seconds;
    res.steps = done;
    res.contacts = sim.active_contacts(e);
    std::tie(res.stones, res.stone_pairs_touching) =
        touching_stones(sim, specimens[e].disks.aggregate, specimens[e].placement.aggregates.size(), e);
    res.plate_y_final = walls[plate[e]].start.y;
    const SkeletonSnapshot end = skeleton(e);
    res.skeleton.films_end = end.films;
    res.skeleton.load_end = end.load;
    res.skeleton.load_end.minutes = res.samples.empty() ? 0.0 : res.samples.back().minutes;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      res.vx.push_back(v(i).x);
      res.vy.push_back(v(i).y);
      res.group.push_back(g(i) == mastic_group ? mastic_group : aggregate_group);  // colours are stones
    }
    finish_deformation(res, wt);
  }
  return results;
}

template <class Space, class Checkpoints = NoCheckpoints>
RuttingResult run_rutting(const Specimen& sp, const WheelTracking& wt, const RuttingMaterials& mat,
                          const RuttingNumerics& num, const Space& space = Space(),
                          const std::function<void(double, long)>& progress = {},
                          const std::function<bool()>& stop = {}, Checkpoints* checkpoints = nullptr) {
  return run_rutting_ensemble(std::vector<Specimen>{sp}, wt, mat, num, space, progress, stop, checkpoints).front();
}

}  // namespace vrut
