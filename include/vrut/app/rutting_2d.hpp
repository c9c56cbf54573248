#pragma once
// The 2D test (protocol/rutting/run.hpp) of one section or an ensemble (--seeds, or
// sections from images), shared among MPI ranks, with checkpoints, and its
// outputs: what vrut-rutting and the Python module run in 2D.
#include "cli.hpp"
#include "draw.hpp"
#include "image_cli.hpp"
#include "ranks.hpp"
#include "rutting_options.hpp"
#include "rutting_outcome.hpp"
#include "rutting_outputs.hpp"
#include "rutting_report.hpp"
#include "seeds.hpp"
#include "loading_bar.hpp"
#include "settling_bar.hpp"
#include "skeleton_report.hpp"
#include "specimen_cli.hpp"
#include "stop_signal.hpp"

#include <vrut/backend.hpp>
#include <vrut/io/checkpoint.hpp>
#include <vrut/io/memory_check.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/protocol/rutting.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut::app {

// o: the options as given, or as the checkpoint stored them on --resume;
// checkpoint: where this run's checkpoints go (or whence it resumes), or
// nullptr for none; config_text: config.ini. With o.out empty nothing is
// written (the Python module's default). Errors throw: std::invalid_argument
// for bad input, std::runtime_error where a specimen cannot be made.
inline RuttingOutcome run_rutting_2d(RunOptions o, vrut::CheckpointFile* checkpoint, const std::string& config_text,
                                     const ranks::Session& session, const RuttingHooks& hooks = {}) {
  namespace fs = std::filesystem;
  // By value: a config file (config.ini) holds every option, at its default.
  const specimen_cli::Specimen3Options defaults3;
  if (o.o3.depth_mm != defaults3.depth_mm) throw std::invalid_argument("--depth-mm is for the 3D test (--dim 3)");
  if (o.o3.sphere_radius_mm != defaults3.sphere_radius_mm)
    throw std::invalid_argument("--sphere-radius-mm is for the 3D test (--dim 3)");
  if (o.o3.stone_packing != defaults3.stone_packing)
    throw std::invalid_argument("--stone-packing is for the 3D test (--dim 3)");
  if (o.mastic_aggregate_factor_3d != RunOptions().mastic_aggregate_factor_3d)
    throw std::invalid_argument("--mastic-aggregate-factor-3d is for the 3D test (--dim 3)");
  if (o.plate != RunOptions().plate)
    throw std::invalid_argument("--plate patch is for the 3D test (--dim 3): a 2D section's plate spans its "
                                "thickness (see --section transverse)");
  resolve_model_options(o);
  o.convert();
  const auto& so = o.so;
  const auto& wt = o.wt;
  const auto& mat = o.mat;
  const auto& num = o.num;
  const std::string &backend = o.backend, &out = o.out, &conversion = o.conversion, &stone_film = o.stone_film,
                    &seeds_text = o.seeds_text;
  const std::vector<std::string>& images = o.io.images;
  const bool from_images = !images.empty();
  if (from_images && (!seeds_text.empty() || o.seed_given))
    throw std::invalid_argument("--image gives the specimens: --seed and --seeds do not go with it");
  vrut::SpecimenSettings ss = specimen_cli::to_settings(so);
  o.mat.least_film = binder_film_option_m("--least-film", o.least_film, ss.gradation, ss.mix);
  o.mat.stone_shear_film = binder_film_option_m("--stone-shear-film", o.stone_shear_film, ss.gradation, ss.mix);
  scale_mastic_by_filler(o, ss.gradation, ss.mix);
  // Everything checkable is checked before the specimen is made.
  mat.mastic.validate();
  vrut::validate_poisson(mat.mastic_nu);
  vrut::validate_poisson(mat.aggregate_nu);
  vrut::TimeShift{num.shift};
  // The contact table refuses what the materials cannot make (a least film
  // without the film per contact, say), before any output.
  vrut::rutting_table(mat, wt.wheel_width, num.shift, 1, 2e-3 * so.disk_radius_mm);
  if (!from_images) wt.validate(ss.placement.width * 1e-3);
  // The images are read, and their specimens made and checked, before the
  // output folder is: a bad image leaves nothing behind.
  std::vector<vrut::Specimen> image_specimens;
  if (from_images) {
    const vrut::ImageSettings is = image_cli::to_settings(o.io, so, o.width_given, o.voids_given);
    for (const std::string& path : images) {
      image_specimens.push_back(vrut::specimen_from_image(path, is));
      try {
        wt.validate(image_specimens.back().width * 1e-3);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("image " + path + ": " + e.what());
      }
    }
  }
  std::optional<vrut::OutputDir> output;  // rank 0 writes the results
  if (session.root() && !out.empty()) output.emplace(out, o.force);
  RuttingOutcome outcome;
  std::vector<std::uint64_t>& seeds = outcome.seeds;
  // An ensemble of images is numbered 1 .. N in the order given, as seeds are.
  if (from_images)
    for (std::size_t k = 1; k <= images.size(); ++k) seeds.push_back(k);
  else
    seeds = seeds_text.empty() ? std::vector<std::uint64_t>{so.seed} : cli::parse_seed_list(seeds_text);
  const bool ensemble = outcome.ensemble = !seeds_text.empty() || images.size() > 1;
  const std::vector<std::uint64_t> my_seeds = ranks::seeds_of_rank(seeds, session);
  if (output) output->write_text("config.ini", config_text);
  // Measured: 1.7 kB a disk in the run (16k to 66k disks), and a checkpoint
  // of 1.2 kB a disk is built in memory before it is written.
  std::size_t planned_disks = 0;
  for (std::uint64_t seed : my_seeds)
    planned_disks += from_images ? image_specimens[seed - 1].disks.centers.size()
                                 : vrut::hex_disks_in(so.width_mm, so.height_mm, so.disk_radius_mm);
  vrut::require_memory(planned_disks, 3072.0, 64e6, my_seeds.size() > 1 ? "this ensemble" : "this run");
  std::vector<vrut::Specimen> specimens;
  for (std::uint64_t seed : my_seeds) {
    if (from_images) {
      specimens.push_back(image_specimens[seed - 1]);
      continue;
    }
    ss.seed = seed;
    try {
      specimens.push_back(vrut::generate_specimen(ss));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("seed " + std::to_string(seed) + ": " + e.what());
    }
    if (my_seeds.size() > 1 && session.root())
      std::fprintf(stderr, "\rspecimens generated: %zu of %zu", specimens.size(), my_seeds.size());
  }
  if (my_seeds.size() > 1 && session.root()) std::fprintf(stderr, "\n");
  std::size_t my_disks = 0;
  for (const auto& sp : specimens) my_disks += sp.disks.centers.size();
  const vrut::Specimen& sp = specimens.front();
  if (session.root())
    std::fprintf(stderr, "specimen%s: %s, %zu disks%s, %zu aggregates%s; plate %.2f mm, loading %.1f s (%.4g s reduced)\n",
                 ensemble ? "s" : "", from_images ? (images.size() > 1 ? "from images" : sp.name.c_str())
                                                  : ("gradation " + ss.gradation.name).c_str(), my_disks,
                 session.size() > 1 ? (" on rank 0 of " + std::to_string(session.size())).c_str() : (ensemble ? " in all" : ""),
                 sp.placement.aggregates.size(), ensemble ? " in the first" : "",
                 wt.plate_length() * 1e3, wt.loading_time(), wt.loading_time() / num.shift);

  // The results, and two checkpoints (the old one stays until the new one is
  // whole) of about 1.2 kB per disk, must fit on the disk: checked now.
  if (output) output->require_space(4'000'000 + 200 * sp.disks.centers.size() + 2 * 1'200 * my_disks * session.size());
  std::optional<vrut::KokkosSession> kokkos;
  if (hooks.start_runtime) hooks.start_runtime(o.threads);
  else kokkos.emplace(o.threads);
  int used_threads = 1;
  // In minutes of the test a second; a resumed run says where it took up the test.
  vrut::app::LoadingBar bar(ensemble, seeds.size(), wt.minutes, checkpoint != nullptr && checkpoint->resuming(),
                             session.root() ? stderr : nullptr);
  std::optional<CatchStopSignals> catching(std::in_place);
  if (checkpoint != nullptr && checkpoint->resuming())
    std::fprintf(stderr, "resuming from %s\n", checkpoint->path().c_str());
  std::vector<vrut::RuttingResult> runs;
  SettlingBar settling(ensemble ? seeds.size() : 1, session.root() ? stderr : nullptr);
  try {
    runs = vrut::dispatch_backend(backend, [&](auto space) {
      used_threads = vrut::concurrency(space);
      return vrut::run_rutting_ensemble(
          specimens, wt, mat, num, space,
          [&](double fraction, long) {
            bar.update(fraction);
            if (hooks.progress) hooks.progress(fraction);
          },
          // Every rank stops at the same sample, so the curves stay the same length.
          [&] { return session.any(stop_signal != 0); }, checkpoint,
          [&](long done, long steps) { settling(done, steps); });
    });
  } catch (const vrut::SimulationUnstable&) {
    std::fprintf(stderr, "\n--timestep-safety sets the time-step safety (%g here)\n", num.timestep_safety);
    // The checkpoints before the blow-up stay, for a look at the state that led to it.
    if (checkpoint != nullptr && fs::exists(checkpoint->path()))
      std::fprintf(stderr, "\nthe last checkpoint before it is kept in %s\n", checkpoint->path().c_str());
    throw;
  }
  catching.reset();
  const bool interrupted = outcome.interrupted = runs.front().interrupted;
  if (interrupted) outcome.exit_code = 128 + static_cast<int>(stop_signal);
  // Rank 0 gathers every specimen's result, in the seeds' order.
  std::vector<ranks::SpecimenFacts> facts;
  for (const auto& one : specimens)
    facts.push_back({one.placement.aggregates.size(), one.placement.achieved_fraction, session.rank()});
  if (!ranks::gather_on_root(session, runs, facts)) return outcome;
  std::size_t disks = 0;
  double wall_seconds = 0.0;
  for (const auto& r : runs) disks += r.particles, wall_seconds = std::max(wall_seconds, r.wall_seconds);
  if (!interrupted) bar.finish();
  const double minutes_done = runs.front().samples.empty() ? 0.0 : runs.front().samples.back().minutes;
  if (interrupted)
    std::fprintf(stderr, "\n%s at %.1f of %.0f minutes: writing the results so far\n",
                 stop_signal == SIGTERM ? "terminated (SIGTERM)" : "interrupted (Ctrl-C)", minutes_done, wt.minutes);
  const vrut::RuttingResult& res = runs.front();
  const RuttingReport report = report_runs(runs, wt, ensemble, interrupted);
  // What was run, for the plot and the printout.
  const std::string what_was_run = from_images ? (images.size() > 1 ? "images" : "image " + images.front())
                                               : "gradation " + ss.gradation.name;
  if (output) {
    write_deformation(*output, runs, report, seeds, ensemble, "Virtual wheel-tracking test, " + what_was_run);
    write_skeleton_plot(*output, runs, "2D, " + what_was_run);
    // Pictures and VTK of the first specimen.
    draw::specimen_png(sp, output->file("specimen.png").string());
    rut_forming_png(sp, res, wt.minutes, output->file("rut_forming.png").string());
    displacement_png(sp, res, output->file("displacement.png").string());
    final_vtk(sp, res, output->file("final.vtk").string());
    if (ensemble)
      write_seeds_csv(*output, runs, report, seeds, facts, "disks,aggregates,aggregate_area_fraction", interrupted,
                      from_images ? images : std::vector<std::string>{});
  }

  nlohmann::json& j = outcome.summary;
  j["dimension"] = 2;
  j["gradation"] = ss.gradation.name;
  j["seed"] = seeds.front();
  if (from_images) j["images"] = images;  // specimen k (the "seed" k) is image k
  j["disk_radius_mm"] = sp.disks.radius;
  j["shift_factor"] = num.shift;
  j["timestep_safety"] = num.timestep_safety;  // as the dimension resolved it (resolve_model_options)
  j["settle_steps"] = num.settle_steps;        // as resolved (resolve_model_options)
  j["conversion"] = conversion;
  j["particles"] = disks;
  j["rigid_stones"] = mat.rigid_stones;
  j["stone_film"] = stone_film;
  j["mastic_aggregate_factor"] = mat.mastic_aggregate_factor;
  j["least_film_um"] = mat.least_film * 1e6;  // a candidate (docs/validation.md); 0 in the model
  j["stone_shear_film_um"] = mat.stone_shear_film * 1e6;  // an experiment (docs/validation.md); 0 in the model
  j["stone_friction"] = vrut::stone_friction_of(mat);
  j["mastic_by_filler"] = o.mastic_by_filler;  // a candidate in 2D (docs/validation.md); none in the model
  j["mastic_scale"] = o.mastic_scale;
  // Whether this run is the 2D model fitted on 2# (docs/validation.md, "The
  // 2D model, calibrated on 2#"): its fitted factor and its stones' film as
  // the model has them.
  const vrut::RuttingMaterials model;
  j["calibrated"] = mat.mastic_aggregate_factor == model.mastic_aggregate_factor && mat.stone_film == model.stone_film;
  j["wall_seconds"] = wall_seconds;
  j["mpi_ranks"] = session.size();
  j["backend"] = backend;
  j["threads"] = used_threads;
  j["particle_steps_per_second"] = disks * static_cast<double>(res.steps) / wall_seconds;
  j["contact_length_mm"] = wt.contact_length() * 1e3;
  j["section"] = wt.transverse ? "transverse" : "longitudinal";
  // Along the section, and across it: the section's thickness, the wheel's width.
  j["plate_mm"] = {wt.plate_length() * 1e3, wt.wheel_width * 1e3};
  j["plate"] = "strip";
  j["loading_time_s"] = wt.loading_time();
  // For an ensemble: the first specimen's bonds, contacts and description.
  add_shared_summary(j, res, report, interrupted, minutes_done);
  j["specimen"] = specimen_cli::specimen_summary(sp);
  if (ensemble) j["ensemble"] = ensemble_json(runs, report, seeds, facts, interrupted, "disks");
  j["skeleton"] = skeleton_summary_json(runs);
  if (output) {
    output->write_text("summary.json", j.dump(2) + '\n');
    // The checkpoint of a stopped run goes with its partial results; a run
    // that ended needs none.
    if (interrupted && checkpoint != nullptr) ranks::keep_checkpoints(out, *output, session.size());
    output->commit();
  }
  outcome.runs = std::move(runs);
  outcome.report = report;
  if (interrupted) {
    if (hooks.print && !out.empty())
      std::printf("partial results (%.1f of %.0f minutes, no dynamic stability) in %s\ngo on with: %s\n", minutes_done,
                  wt.minutes, out.c_str(), ranks::resume_command(session.size(), out).c_str());
    return outcome;
  }
  if (hooks.print) {
    char speed[128];
    std::snprintf(speed, sizeof speed, "%zu disks, %ld steps, %.0f s, %.3g particle-steps/s", disks, outcome.runs.front().steps,
                  wall_seconds, j["particle_steps_per_second"].get<double>());
    print_result(what_was_run, outcome.runs, report, wt, ensemble, speed, out);
  }
  return outcome;
}

}  // namespace vrut::app
