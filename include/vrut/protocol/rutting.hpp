#pragma once
// The virtual wheel-tracking (rutting) test, docs/method.md sections 1, 5 and 6:
// specimen -> DE model with the four interactions -> mould (bottom and side
// walls) -> settling under gravity -> a loading plate of contact length
// l = m g / (p d) at mid-span, servo-controlled to the pressure p -> loading
// for the cumulative time T = 60 min * l / travel, reduced by alpha_T ->
// deformation curve, rut depth, dynamic stability.
#include <vrut/contact/choice.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/contact/film.hpp>
#include <vrut/core/simulation.hpp>
#include <vrut/protocol/energy_check.hpp>
#include <vrut/material/burgers_parameters.hpp>
#include <vrut/specimen/colouring.hpp>
#include <vrut/specimen/specimen.hpp>
#include <vrut/specimen/stone_reach.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace vrut {

// The laboratory test (docs/method.md section 1); SI units.
struct WheelTracking {
  double wheel_mass = 78.0;          // kg
  double gravity = 9.81;             // m/s^2
  double pressure = 0.7e6;           // Pa
  double wheel_width = 0.05;         // m, = the disk thickness t
  double travel = 0.230;             // m, back and forth
  double passes_per_minute = 42.0;
  double minutes = 60.0;
  double ds_from_minute = 45.0;      // DS between this minute and the end

  double contact_length() const { return wheel_mass * gravity / (pressure * wheel_width); }
  double loading_time() const { return minutes * 60.0 * contact_length() / travel; }  // s, cumulative under the wheel
  // The passes of the DS window, (t2 - t1) N C1 C2 with C1 = C2 = 1.
  double ds_window_passes() const { return (minutes - ds_from_minute) * passes_per_minute; }
  double plate_force() const { return pressure * contact_length() * wheel_width; }

  void validate(double section_width_m) const {
    auto positive = [](double v, const char* what) {
      if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be positive");
    };
    positive(wheel_mass, "wheel mass");
    positive(gravity, "gravity");
    positive(pressure, "contact pressure");
    positive(wheel_width, "wheel width");
    positive(travel, "wheel travel");
    positive(passes_per_minute, "passes per minute");
    positive(minutes, "test duration");
    if (!(ds_from_minute > 0.0 && ds_from_minute < minutes))
    {
      char text[160];
      std::snprintf(text, sizeof text, "the test (%g min) must last longer than minute %g, where the window of the "
                    "dynamic stability starts", minutes, ds_from_minute);
      throw std::invalid_argument(text);
    }
    if (!(contact_length() < section_width_m))
      throw std::invalid_argument("the loading plate (" + std::to_string(contact_length() * 1e3) +
                                  " mm) is longer than the specimen (" + std::to_string(section_width_m * 1e3) + " mm)");
  }
};

// How two stones meet: see RuttingMaterials::stone_film.
enum class StoneFilm { none, mean, per_contact };

struct RuttingMaterials {
  BurgersMacro mastic;                  // at the test temperature, 60 C
  double mastic_nu = 0.35;
  bool calibrated_conversion = false;   // MicroConversion::calibrated instead of the method's rules
  // The calibration on mix 2# (docs/validation.md, "The frozen model of
  // 2026-12-02"): with the film per contact, 4 brings 2# to the
  // laboratory's rut. It is a fitted constant, declared as such. (2, the
  // value frozen before with no film, reads the micro parameters as two
  // Burger's disks in series, one of them rigid: docs/method.md section 6;
  // the source's value is 1.)
  double mastic_aggregate_factor = 4.0;
  double aggregate_modulus = 55.5e9;    // Pa
  double aggregate_nu = 0.25;
  double mastic_density = 2400.0, aggregate_density = 2700.0;  // kg/m^3
  double friction = 1.0;                // disk-disk, where no bond holds (calibrated, crushed stone)
  // Aggregate on aggregate only, where no bond holds; < 0: `friction`. A
  // candidate of the gradation study: stone on stone against contacts
  // through mastic (docs/validation.md).
  double stone_friction = -1.0;
  // How two stones meet (docs/validation.md, the gradation study): the
  // contact between disks of two different aggregates.
  //   none: method.md's rigid linear stone law (the model until 2026-12-02);
  //   mean: a mastic film of film_gap diameters (contact/film.hpp; no bond,
  //         stone friction) that squeezes out to the stone law;
  //   per_contact (the default since 2026-12-02): each pair of stones meets
  //         through its own film: one diameter less the reaches of its two
  //         disks, how far each centre lies inside its stone's outline
  //         towards the other stone (specimen/stone_reach.hpp), in
  //         film_reach_classes bins. Nothing in it is fitted.
  StoneFilm stone_film = StoneFilm::per_contact;
  // The mean film's thickness, as a fraction of the disk diameter. Where two
  // stones' disks (1 mm radius) are neighbours, the stones' true outlines lie
  // 0.40 diameters apart on average in 2# (0.42 in 1#, 0.375 in 3#;
  // benchmarks/film_gaps.cpp): mastic that the disks cannot show. The film's
  // Burger's law is the mastic's over that length (factor 1 / film_gap), and
  // the stones' linear springs, normal and shear, bear once the overlap
  // exceeds it.
  double film_gap = 0.40;
  // The mean film never squeezes out: no stone spring (the study's first
  // film, not adopted: it creeps without end).
  bool film_endless = false;
  bool films() const { return stone_film != StoneFilm::none; }
  bool film_per_contact() const { return stone_film == StoneFilm::per_contact; }
  double wall_friction = 0.0;           // mould walls and plate
  // Rigid stones (data/bodies.hpp), the default: each aggregate moves as one
  // body instead of method.md's bonded disks on the stone's 2 t E springs
  // (rigid_stones = false, --exact-stones). Stone on stone, and any disk on
  // a wall, meet on a linear spring of stone_contact_ratio times the
  // mastic's normal spring E1 t, a numerical stiffness: the rut depth is the
  // same from 30 to 1,000 and moves at 10 (docs/validation.md, "Rigid stones
  // and the time step"), and 100 takes a fifteenth of the exact model's
  // steps. Beside it a dashpot of stone_damping of the pair's critical
  // damping: real stone rings down, and the exact model's stones, undamped
  // on springs 12,000 times the mastic's, ring and shake the skeleton. The
  // time step follows from these springs and the bodies' masses
  // (Simulation::contact_timestep). A departure from the method, in
  // numerics, chosen by that study.
  bool rigid_stones = true;
  double stone_contact_ratio = 100.0;
  double stone_damping = 0.05;
};

// The normal spring between two rigid stones and of the walls, N/m.
inline double rigid_stone_stiffness(const RuttingMaterials& m, double thickness) {
  if (!(m.stone_contact_ratio > 0.0) || !std::isfinite(m.stone_contact_ratio))
    throw std::invalid_argument("the stone contact ratio must be positive and finite");
  if (!(m.stone_damping >= 0.0 && m.stone_damping < 1.0))
    throw std::invalid_argument("the stone damping must lie in [0, 1) of critical");
  return m.stone_contact_ratio * m.mastic.E1 * thickness;
}

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
};

struct RuttingSample {
  double minutes = 0.0, reduced_time = 0.0, deformation = 0.0 /* m */;
  double plate_pressure = 0.0;  // Pa, mean over the interval since the previous sample
};

struct RuttingSnapshot {
  double fraction = 0.0;             // of the loading time
  std::vector<double> x, y, dx, dy;  // m: positions and displacement since loading began
};

struct RuttingResult {
  std::vector<RuttingSample> samples;
  std::vector<RuttingSnapshot> snapshots;  // at 1/3, 2/3 and the end of the loading
  std::vector<double> vx, vy;              // final velocities
  std::vector<int> group;
  double deformation_at_ds_start = 0.0, deformation_final = 0.0;  // m
  double dynamic_stability = 0.0;          // passes / mm
  // The smallest deformation change over the DS window that the curve
  // resolves (m; finish_deformation). Where the change is below it, the DS
  // is reported as a lower bound, as a laboratory reports a DS past its
  // gauge: dynamic_stability is then the DS that change would give.
  double deformation_resolution = 0.0;
  bool dynamic_stability_is_lower_bound = false;
  double plate_x0 = 0.0, plate_x1 = 0.0, plate_y_final = 0.0;     // m
  std::size_t particles = 0;
  int contacts = 0, bonds = 0;
  // At the end: the stones holding disks, and the pairs of them that touch
  // (some disk of one overlaps some disk of the other): the skeleton.
  int stones = 0, stone_pairs_touching = 0;
  bool interrupted = false;                // stopped early on request: the samples so far, no DS
  long steps = 0;
  double dt = 0.0, wall_seconds = 0.0;
};

using RuttingLaw = Choice<BurgersFilmBonded, DampedLinearBonded>;
using RuttingWallLaw = DampedLinear;

// The stone law: the method's aggregate spring (2 t E, undamped), or the
// rigid stones' contact spring with its dashpot.
inline DampedLinearBonded::params_type stone_law_params(const RuttingMaterials& m, double thickness, double friction) {
  const auto exact = aggregate_params(m.aggregate_modulus, thickness, m.aggregate_nu, friction);
  DampedLinearBonded::params_type p;
  p.normal.stiffness = exact.normal.stiffness;
  p.shear.stiffness = exact.shear.stiffness;
  p.bond = exact.bond;
  p.friction = exact.friction;
  if (m.rigid_stones) {
    p.normal.stiffness = rigid_stone_stiffness(m, thickness);
    p.shear.stiffness = p.normal.stiffness / (2.0 * (1.0 + m.aggregate_nu));
    p.normal.damping_ratio = m.stone_damping;
  }
  return p;
}

// The mould's and the plate's law: as stiff as the stones' (and as damped).
inline RuttingWallLaw::params_type rutting_wall_params(const RuttingMaterials& m, double thickness) {
  const auto stone = stone_law_params(m, thickness, m.wall_friction);
  return damped_linear_params(stone.normal.stiffness, stone.normal.stiffness / (2.0 * (1.0 + m.aggregate_nu)),
                              m.wall_friction, stone.normal.damping_ratio);
}

// The film per contact sorts the stone disks' reaches into this many bins
// of 0.2 diameters: its thickness is resolved to 0.2 diameters, about the
// spread of the reach over the lines of one disk's neighbours.
inline constexpr int film_reach_classes = 5;
// Below half a bin the film is thinner than the bins resolve: its Burger's
// element is taken over that length, and the stones' spring bears at once.
inline constexpr double film_least_gap = 0.5 / film_reach_classes;

// The contact table's group of a stone disk: each stone colour holds one
// group per reach bin where the film is per contact, one otherwise.
inline int stone_group(const RuttingMaterials& m, int colour, double reach) {
  if (!m.film_per_contact()) return aggregate_group + colour;
  return aggregate_group + colour * film_reach_classes + reach_class(reach, film_reach_classes);
}

// Each disk's group in the contact table: the mastic's, or its stone's
// (`colour`, one per aggregate, from colour_aggregates), and the bin of its
// reach where the film is per contact.
inline std::vector<int> rutting_groups(const Specimen& sp, const RuttingMaterials& m, const std::vector<int>& colour) {
  const std::size_t n = sp.disks.centers.size();
  const std::vector<double> reach = m.film_per_contact() ? stone_reach(sp.disks, sp.placement) : std::vector<double>(n, 0.0);
  std::vector<int> group(n, mastic_group);
  for (std::size_t i = 0; i < n; ++i)
    if (sp.disks.aggregate[i] >= 0) group[i] = stone_group(m, colour[sp.disks.aggregate[i]], reach[i]);
  return group;
}

// Rigid stones: each aggregate that holds a disk becomes one body, numbered
// in the aggregates' order; mastic disks are free (-1). (A stone too small
// to hold a disk's centre is mastic, as the method's packing has it.)
inline std::vector<int> stone_bodies(const Specimen& sp) {
  std::vector<int> body_of(sp.placement.aggregates.size(), -1), body(sp.disks.aggregate.size(), -1);
  for (int a : sp.disks.aggregate)
    if (a >= 0) body_of[a] = 0;
  int bodies = 0;
  for (int& b : body_of)
    if (b == 0) b = bodies++;
  for (std::size_t i = 0; i < body.size(); ++i)
    if (sp.disks.aggregate[i] >= 0) body[i] = body_of[sp.disks.aggregate[i]];
  return body;
}

// Group 0 is the mastic; the aggregates are groups 1 .. stone_colours, one
// per colour (specimen/colouring.hpp), so that the table can tell two stones
// from one; with the film per contact, one per colour and reach bin
// (stone_group). With one colour that is the method's two-group table.
// disk_diameter (m) sizes the film between stones; only the film needs it.
inline AssignmentTable<RuttingLaw> rutting_table(const RuttingMaterials& m, double thickness, double shift,
                                                 int stone_colours = 1, double disk_diameter = 0.0) {
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(shift));
  const MicroConversion conv = m.calibrated_conversion ? MicroConversion::calibrated(m.mastic_nu) : MicroConversion::seed();
  const double stone_friction = m.stone_friction < 0.0 ? m.friction : m.stone_friction;
  const bool films = m.films();
  const int bins = m.film_per_contact() ? film_reach_classes : 1;
  AssignmentTable<RuttingLaw> table(1 + stone_colours * bins);
  table.set(mastic_group, mastic_group,
            RuttingLaw::make_first(film_params(mastic_params(reduced, thickness, m.mastic_nu, conv, 1.0, m.friction))));
  const auto mastic_stone = RuttingLaw::make_first(
      film_params(mastic_params(reduced, thickness, m.mastic_nu, conv, m.mastic_aggregate_factor, m.friction)));
  const auto stone_params = stone_law_params(m, thickness, stone_friction);
  const auto stone = RuttingLaw::make_second(stone_params);
  if (films) {
    if (!m.film_per_contact() && !(m.film_gap > 0.0 && m.film_gap < 1.0))
      throw std::invalid_argument("the film between stones must be thinner than a disk and positive (film gap in (0, 1))");
    if (m.film_per_contact() && m.film_endless)
      throw std::invalid_argument("a film per contact is sized by where the stones touch: it cannot be endless");
    if (!(disk_diameter > 0.0)) throw std::invalid_argument("the film between stones needs the disk diameter");
  } else if (m.film_endless) {
    throw std::invalid_argument("an endless film is a film between stones: it needs the mean film (stone film 'mean')");
  }
  // A film `gap` diameters thick: the mastic's Burger's law over that length
  // (per contact, never thinner than film_least_gap), the stones' springs
  // beyond it.
  auto film = [&](double gap) {
    const double length = m.film_per_contact() ? std::max(gap, film_least_gap) : gap;
    const auto mastic = mastic_params(reduced, thickness, m.mastic_nu, conv, 1.0 / length, stone_friction);
    return RuttingLaw::make_first(m.film_endless ? film_params(mastic)
                                                 : film_params(mastic, gap * disk_diameter,
                                                               stone_params.normal.stiffness,
                                                               stone_params.shear.stiffness));
  };
  auto film_between_bins = [&](int p, int q) {
    return film(std::max(0.0, 1.0 - reach_class_middle(p, bins) - reach_class_middle(q, bins)));
  };
  const auto mean_film = films && !m.film_per_contact() ? film(m.film_gap) : RuttingLaw::params_type{};
  for (int a = 1; a < table.groups(); ++a) {
    table.set(mastic_group, a, mastic_stone);
    const int colour_a = (a - 1) / bins, bin_a = (a - 1) % bins;
    for (int b = a; b < table.groups(); ++b) {
      const int colour_b = (b - 1) / bins, bin_b = (b - 1) % bins;
      if (colour_a == colour_b || !films)
        table.set(a, b, stone);
      else
        table.set(a, b, m.film_per_contact() ? film_between_bins(bin_a, bin_b) : mean_film);
    }
  }
  return table;
}

// Deformation at the DS start minute (interpolated), at the end, and the DS
// (method.md section 1: the passes between the DS start and the end over the
// deformation between them).
//
// The resolution: the plate jitters about the curve's trend (its dead load
// and the disks under it vibrate a little). The DS is a difference of two
// points of the curve, each off the trend by about s, the residual standard
// deviation of a least-squares line through the samples in the DS window; so
// a change below 2 sqrt(2) s (two standard deviations of a difference) is
// not resolved, and the DS is reported as above the value such a change
// gives. Fewer than three samples in the window: no resolution is known (0).
inline void finish_deformation(RuttingResult& res, const WheelTracking& wt) {
  auto deformation_at = [&](double minute) {
    for (std::size_t k = 1; k < res.samples.size(); ++k)
      if (res.samples[k].minutes >= minute) {
        const auto& a = res.samples[k - 1];
        const auto& b = res.samples[k];
        return a.deformation + (minute - a.minutes) / (b.minutes - a.minutes) * (b.deformation - a.deformation);
      }
    return res.samples.back().deformation;
  };
  res.dynamic_stability_is_lower_bound = false;
  res.deformation_resolution = 0.0;
  if (res.samples.empty()) {
    res.deformation_at_ds_start = res.deformation_final = 0.0;
    res.dynamic_stability = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  res.deformation_at_ds_start = deformation_at(wt.ds_from_minute);
  res.deformation_final = res.samples.back().deformation;
  // A run stopped before the end of the test has no DS.
  if (res.interrupted) {
    res.dynamic_stability = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  double n = 0.0, st = 0.0, sd = 0.0;
  for (const auto& smp : res.samples)
    if (smp.minutes >= wt.ds_from_minute * (1.0 - 1e-9)) n += 1.0, st += smp.minutes, sd += smp.deformation;
  if (n >= 3.0) {
    const double t_mean = st / n, d_mean = sd / n;
    double stt = 0.0, std_ = 0.0;
    for (const auto& smp : res.samples)
      if (smp.minutes >= wt.ds_from_minute * (1.0 - 1e-9)) {
        stt += (smp.minutes - t_mean) * (smp.minutes - t_mean);
        std_ += (smp.minutes - t_mean) * (smp.deformation - d_mean);
      }
    const double slope = stt > 0.0 ? std_ / stt : 0.0;
    double residuals = 0.0;
    for (const auto& smp : res.samples)
      if (smp.minutes >= wt.ds_from_minute * (1.0 - 1e-9)) {
        const double r = smp.deformation - (d_mean + slope * (smp.minutes - t_mean));
        residuals += r * r;
      }
    res.deformation_resolution = 2.0 * std::sqrt(2.0) * std::sqrt(residuals / (n - 2.0));
  }
  const double passes = wt.ds_window_passes();
  const double dd_mm = (res.deformation_final - res.deformation_at_ds_start) * 1e3;
  const double resolution_mm = res.deformation_resolution * 1e3;
  if (resolution_mm > 0.0 && dd_mm < resolution_mm) {
    res.dynamic_stability_is_lower_bound = true;
    res.dynamic_stability = passes / resolution_mm;
  } else {
    res.dynamic_stability = dd_mm > 0.0 ? passes / dd_mm : std::numeric_limits<double>::infinity();
  }
}

// Throws SimulationUnstable when a disk has left its mould (through a wall or
// over the top): a run with too large a time step can push disks through the
// stiff walls without any single step jumping far enough for the engine's own
// check. Called at every sample.
template <class Sim>
void check_inside_moulds(Sim& sim, const std::vector<Specimen>& specimens, long step, double dt) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  for (int e = 0; e < static_cast<int>(specimens.size()); ++e) {
    const double w = specimens[e].width * 1e-3, h = specimens[e].height * 1e-3;
    const double r = specimens[e].disks.radius * 1e-3;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      const Vec2 p = x(i);
      if (!(p.x > -r && p.x < w + r && p.y > -r && p.y < 2.0 * h)) {
        char where[400];
        std::snprintf(where, sizeof where, "disk %d of specimen %d (%.200s) is at (%.4g, %.4g) mm, outside its %g x %g mm mould",
                      i - first, e, specimens[e].name.c_str(), p.x * 1e3, p.y * 1e3, w * 1e3, h * 1e3);
        char text[700];
        std::snprintf(text, sizeof text,
                      "vrut: the rutting run became unstable by loading step %ld: %s. The time step is %.3g of "
                      "sqrt(m_min / k_max); lower --timestep-safety (default 0.3).",
                      step, where, dt / sim.critical_timestep());
        throw SimulationUnstable(text, step);
      }
    }
  }
}

// The pairs of stones of specimen e that touch at the end, found in the
// contact list (every overlapping disk pair is in it), and the stones.
template <class Sim>
std::pair<int, int> touching_stones(const Sim& sim, const Specimen& sp, int e) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().radius);
  auto partner = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.contacts().partner);
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.contacts().count);
  const auto [first, last] = sim.specimen_range(e);
  const std::vector<int>& stone = sp.disks.aggregate;
  std::vector<std::pair<int, int>> pairs;
  std::vector<char> holds(sp.placement.aggregates.size(), 0);
  for (int i = first; i < last; ++i) {
    if (stone[i - first] >= 0) holds[stone[i - first]] = 1;
    for (int k = 0; k < count(i); ++k) {
      const int j = partner(i, k);
      const int a = stone[i - first], b = stone[j - first];
      if (a >= 0 && b >= 0 && a != b && norm(x(j) - x(i)) < r(i) + r(j)) pairs.emplace_back(std::min(a, b), std::max(a, b));
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
                                                Checkpoints* checkpoints = nullptr) {
  const bool resuming = checkpoints != nullptr && checkpoints->resuming();
  if (specimens.empty()) throw std::invalid_argument("an ensemble needs at least one specimen");
  if (!(num.timestep_safety > 0.0 && num.timestep_safety <= 1.0)) throw std::invalid_argument("time-step safety must lie in (0, 1]");
  if (num.samples < 10) throw std::invalid_argument("at least 10 samples");
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

  // Settling under gravity (a resumed run reads where it had got to instead).
  // The energy check (energy_check.hpp) counts the loads' work from here.
  auto energy_reference = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  std::vector<double> plate_work(count, 0.0);
  constexpr long energy_check_every = 500;  // settling steps
  for (long done_settling = 0; !resuming && done_settling < num.settle_steps; done_settling += energy_check_every) {
    sim.run(std::min(energy_check_every, num.settle_steps - done_settling), dt);
    check_energy(sim, energy_reference, {}, sim.steps(), dt);
  }

  // The plates, each on the highest disk under it; the load brings it down.
  const double l = wt.contact_length();
  const double t_load = wt.loading_time() / num.shift;
  const long steps = static_cast<long>(std::ceil(t_load / dt));
  const long ramp_steps = std::max(1L, static_cast<long>(num.ramp_fraction * steps));
  auto host_x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  std::vector<double> top(count, 0.0);
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
  auto ramp_to = [&](double fraction) {
    const double stress = wt.plate_force() * fraction / (l * t);
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
  const auto begin = std::chrono::steady_clock::now();
  int next_sample = 1, next_snapshot = 1;
  std::vector<Vec2> last_impulse(count), last_plate_position(count);
  for (int e = 0; e < count; ++e) last_plate_position[e] = sim.wall(plate[e]).start;
  double last_time = 0.0, seconds_before = 0.0, checkpoint_seconds = 0.0;  // wall time of the run before this process
  long done = steps, last_done = 0;
  // The whole state of the run between two steps, item by item (Simulation::visit_state).
  auto visit = [&](auto& archive) {
    sim.visit_state(archive);
    archive.view("loading_start", start);
    archive.value("loading_steps_done", last_done);
    archive.value("next_sample", next_sample);
    archive.value("next_snapshot", next_snapshot);
    archive.value("last_sample_time", last_time);
    archive.vector("last_plate_impulse", last_impulse);
    archive.vector("plate_start_height", top);
    archive.view("energy_reference", energy_reference);
    archive.vector("plate_work", plate_work);
    archive.vector("last_plate_position", last_plate_position);
    checkpoint_seconds = seconds_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    archive.value("wall_seconds", checkpoint_seconds);
    for (int e = 0; e < count; ++e) {
      const std::string id = "specimen_" + std::to_string(e) + "_";
      archive.vector(id + "samples", results[e].samples);
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
  if (resuming) {
    checkpoints->load(visit);
    seconds_before = checkpoint_seconds;
  }
  for (long s = last_done + 1; s <= steps; ++s) {
    if (s <= ramp_steps && (s % 50 == 1 || s == ramp_steps))
      ramp_to(std::min(1.0, static_cast<double>(s) / ramp_steps));
    sim.step(dt);
    const double time = s * dt;
    if (next_snapshot <= 3 && (s >= steps * next_snapshot / 3)) {
      snapshot(next_snapshot / 3.0);
      ++next_snapshot;
    }
    if (next_sample <= num.samples && (time >= t_load * next_sample / num.samples - 0.5 * dt || s == steps)) {
      check_inside_moulds(sim, specimens, s, dt);
      const std::vector<Wall>& walls = sim.all_walls();
      const std::vector<Vec2> impulse = sim.all_wall_impulses();
      for (int e = 0; e < count; ++e) {
        const Wall& w = walls[plate[e]];
        RuttingSample smp;
        smp.reduced_time = time;
        smp.minutes = time * to_minutes;
        smp.deformation = top[e] - w.start.y;
        // Mean pressure since the last sample, from the impulse on the plate.
        smp.plate_pressure = -dot(impulse[plate[e]] - last_impulse[e], inward_normal(w)) / (time - last_time) / (l * t);
        // The plate's work on the disks: its mean force on them times its travel.
        plate_work[e] -= dot(impulse[plate[e]] - last_impulse[e], w.start - last_plate_position[e]) / (time - last_time);
        last_plate_position[e] = w.start;
        last_impulse[e] = impulse[plate[e]];
        results[e].samples.push_back(smp);
      }
      check_energy(sim, energy_reference, plate_work, s, dt);
      last_time = time;
      ++next_sample;
      if (progress) progress(time / t_load, s);
      const bool stopping = stop && s < steps && stop();
      if (checkpoints != nullptr && s < steps && (stopping || checkpoints->due())) {
        last_done = s;
        checkpoints->save(visit);
      }
      if (stopping) {
        done = s;
        if (next_snapshot <= 3) snapshot(time / t_load);
        for (auto& r : results) r.interrupted = true;
        break;
      }
    }
  }
  Kokkos::fence();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  const std::vector<Wall>& walls = sim.all_walls();
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().velocity);
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().group);
  for (int e = 0; e < count; ++e) {
    RuttingResult& res = results[e];
    res.wall_seconds = seconds_before + seconds;
    res.steps = done;
    res.contacts = sim.active_contacts(e);
    std::tie(res.stones, res.stone_pairs_touching) = touching_stones(sim, specimens[e], e);
    res.plate_y_final = walls[plate[e]].start.y;
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
