#pragma once
// The loading that the 2D and 3D rutting runs share (driver.hpp): the
// numerics (RuttingNumerics), the plan of the loading's steps;
// the plates' load ramped up over the first steps, then the steps, with a
// sample of the curve at each of `samples` even times, the progress, a stop
// asked at each sample, and the checkpoints; and the state of all that
// between two steps, which every checkpoint holds.
#include <vrut/protocol/rutting/test.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

namespace vrut {

struct LoadingPlan {
  double dt = 0.0, t_load = 0.0;  // s, reduced
  long steps = 0, ramp_steps = 1;
  int samples = 0;
};

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
    // Above 2 the stiffest spring alone, on the mass it meets, is past the
    // leapfrog scheme's limit (omega dt < 2); from 1 to 2 only for studies of that limit.
    if (!(timestep_safety > 0.0 && timestep_safety <= 2.0)) throw std::invalid_argument("time-step safety must lie in (0, 2]");
    if (samples < 10) throw std::invalid_argument("at least 10 samples");
  }
};

// The 3D test's time-step safety (vrut-rutting --dim 3 at
// its defaults; RuttingNumerics' 0.3 stays 2D's and the library's). In 3D
// the step is set by one stiff spring on a light mass (the mould's and the
// plate's stone spring on a mastic sphere, or two stones' on a small
// stone's felt mass) among springs a hundred times softer, where the
// leapfrog scheme is stable up to 1.4 to 2 times sqrt(m / k). Every mix
// ran stably at 1.0 (3# not at 1.2: a compacted small stone meets several
// at once), and at 0.5 the rut moved by -0.03 % (1#, 2#) and -0.6 % (3#),
// within what the chaos control moves or just past it (docs/validation.md,
// "The 3D time step's safety factor"). 0.5 is half the largest safety
// that ran on every mix.
inline constexpr double timestep_safety_3d = 0.5;

// The settling's steps that last as long as the method's 4,000 at the
// safety 0.3 (RuttingNumerics{}): a larger step settles in fewer, the same
// time under gravity. vrut-rutting's --settle-steps -1, its default
// (resolve_model_options): 4,000 in 2D, 2,400 at the 3D step's 0.5.
inline long settle_steps_at_safety(double timestep_safety) {
  const RuttingNumerics method;
  return std::lround(static_cast<double>(method.settle_steps) * method.timestep_safety / timestep_safety);
}

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

// Vector: the dimension's (Vec2, Vec3). One entry a specimen in each list.
template <class Vector>
struct LoadingState {
  double dt = 0.0;     // the loading's step, s, reduced: a resumed run must take the one it was written at
  long last_done = 0;  // the steps done when the last checkpoint was written
  int next_sample = 1;
  double last_time = 0.0;                          // of the last sample, s
  std::vector<double> top, plate_work;             // the plate's start height; its work on the particles so far
  std::vector<Vector> last_impulse, last_plate_position;  // at the last sample
  double seconds_before = 0.0, checkpoint_seconds = 0.0;  // wall time of the run before this process
  std::chrono::steady_clock::time_point begin = std::chrono::steady_clock::now();

  LoadingState(int specimens, double step)
      : dt(step), top(specimens, 0.0), plate_work(specimens, 0.0), last_impulse(specimens),
        last_plate_position(specimens) {}

  double seconds() const {
    return seconds_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  }
  template <class Archive>
  void visit(Archive& archive) {
    archive.value("loading_dt", dt);
    archive.value("loading_steps_done", last_done);
    archive.value("next_sample", next_sample);
    archive.value("last_sample_time", last_time);
    archive.vector("last_plate_impulse", last_impulse);
    archive.vector("plate_start_height", top);
    archive.vector("plate_work", plate_work);
    archive.vector("last_plate_position", last_plate_position);
    checkpoint_seconds = seconds();
    archive.value("wall_seconds", checkpoint_seconds);
  }
  // After a checkpoint was read: its wall time counts as this run's. Its
  // step must be the one this run computes: the same steps at another step
  // would be another run (the engine or a default changed between the build
  // that wrote it and this one), so that is refused.
  void resumed(double computed_dt) {
    if (dt != computed_dt) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "the checkpoint was written at a time step of %.10g s; this build computes %.10g s for the same "
                    "run (its engine or defaults differ from those of the build that began it): resume with that "
                    "build, or run the test again from the start",
                    dt, computed_dt);
      throw std::invalid_argument(text);
    }
    seconds_before = checkpoint_seconds;
  }
  // At a sample at `time`: plate e's mean pressure since the last sample (its
  // impulse over the time, along its inward normal, on `area`), returned;
  // and its work on the particles, its mean force times its travel.
  double plate_sample(int e, const Vector& impulse, const Vector& position, const Vector& inward, double time,
                      double area) {
    const Vector pushed = impulse - last_impulse[e];
    const double pressure = -dot(pushed, inward) / (time - last_time) / area;
    plate_work[e] -= dot(pushed, position - last_plate_position[e]) / (time - last_time);
    last_plate_position[e] = position;
    last_impulse[e] = impulse;
    return pressure;
  }
};

// Runs steps state.last_done + 1 .. plan.steps: ramp_to(fraction) sets the
// plates' load while it rises, after_step(s) follows every step, and
// take_sample(s, time) takes each sample (state.last_time is still the last
// one's). At each sample, progress(fraction of the loading, steps), then
// stop() is asked, and checkpoints->save(visit) writes the state when
// checkpoints->due() or when stopping. Returns the last step done:
// plan.steps, or the sample's step where stop() said true.
template <class Sim, class Vector, class Ramp, class AfterStep, class TakeSample, class Checkpoints, class Visit>
long run_loading(Sim& sim, const LoadingPlan& plan, LoadingState<Vector>& state, Ramp&& ramp_to,
                 AfterStep&& after_step, TakeSample&& take_sample, const std::function<void(double, long)>& progress,
                 const std::function<bool()>& stop, Checkpoints* checkpoints, Visit&& visit) {
  for (long s = state.last_done + 1; s <= plan.steps; ++s) {
    if (s <= plan.ramp_steps && (s % 50 == 1 || s == plan.ramp_steps))
      ramp_to(std::min(1.0, static_cast<double>(s) / plan.ramp_steps));
    sim.step(plan.dt);
    const double time = s * plan.dt;
    after_step(s);
    const bool sample_due = time >= plan.t_load * state.next_sample / plan.samples - 0.5 * plan.dt || s == plan.steps;
    if (state.next_sample > plan.samples || !sample_due) continue;
    take_sample(s, time);
    state.last_time = time;
    ++state.next_sample;
    if (progress) progress(time / plan.t_load, s);
    const bool stopping = stop && s < plan.steps && stop();
    if (checkpoints != nullptr && s < plan.steps && (stopping || checkpoints->due())) {
      state.last_done = s;
      checkpoints->save(visit);
    }
    if (stopping) return s;
  }
  return plan.steps;
}

}  // namespace vrut
