#pragma once
// vrut-rutting --dim 3: the 3D test (protocol/rutting/run3.hpp) of one specimen or an
// ensemble (--seeds, shared among MPI ranks), with checkpoints and --resume, and its outputs. What
// 3D does not have (images, the method's bonded stones, the mean film, the
// 2D conversions) is refused by name.
#include "cli.hpp"
#include "ranks.hpp"
#include "draw3.hpp"
#include "seeds.hpp"
#include "specimen3_cli.hpp"
#include "rutting_options.hpp"
#include "rutting_outcome.hpp"
#include "rutting_outputs.hpp"
#include "rutting_report.hpp"
#include "loading_bar.hpp"
#include "settling_bar.hpp"
#include "stop_signal.hpp"

#include <vrut/analysis/standard_ds.hpp>
#include <vrut/backend.hpp>
#include <vrut/io/checkpoint.hpp>
#include <vrut/io/memory_check.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/io/stones3_state.hpp>
#include <vrut/io/vtk.hpp>
#include <vrut/protocol/rutting/run3.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut::app {

// The first specimen's final state for ParaView.
inline void final_vtk3(const vrut::Specimen3& sp, const vrut::RuttingResult3& run, const std::string& path) {
  std::vector<double> x, y, z, radius, group, stone, dx, dy, dz;
  for (std::size_t i = 0; i < run.final_positions.size(); ++i) {
    x.push_back(run.final_positions[i].x());
    y.push_back(run.final_positions[i].y());
    z.push_back(run.final_positions[i].z());
    radius.push_back(sp.spheres.radius);
    group.push_back(run.result.group[i]);
    stone.push_back(sp.spheres.stone[i]);
    dx.push_back(run.displacement[i].x());
    dy.push_back(run.displacement[i].y());
    dz.push_back(run.displacement[i].z());
  }
  vrut::VtkPointData data;
  data.scalars = {{"radius", radius}, {"group", group}, {"stone", stone}, {"dx", dx}, {"dy", dy}, {"dz", dz}};
  vrut::write_vtk_points(path, "vrut 3D rutting, the end of the loading (mm, y up, z periodic); displacement while loading",
                         x, y, z, data);
}

// o: the options as given, or as the checkpoint stored them on --resume;
// checkpoint: where this run's checkpoints go (or whence it resumes), or
// nullptr for none; config_text: config.ini. With o.out empty nothing is
// written (the Python module's default). Errors throw: std::invalid_argument
// for bad input, std::runtime_error where a specimen cannot be made.
// Under mpirun -np K the seeds are shared out in blocks as in 2D
// (rutting_2d.hpp); each rank places and runs its own, rank 0 gathers the
// results and writes them.
inline RuttingOutcome run_rutting_3d(RunOptions o, vrut::CheckpointFile* checkpoint, const std::string& config_text,
                                     const ranks::Session& session, const RuttingHooks& hooks = {}) {
  namespace fs = std::filesystem;
  // By value, not by what was typed: a config file (config.ini) holds every option.
  const RunOptions defaults;
  auto not_in_3d = [](const std::string& option, const std::string& why) {
    throw std::invalid_argument(option + " is not in the 3D test: " + why);
  };
  if (!o.io.images.empty()) not_in_3d("--image", "its specimens are generated");
  if (o.exact_stones) not_in_3d("--exact-stones", "its stones are rigid");
  if (o.conversion != defaults.conversion) not_in_3d("--conversion " + o.conversion, "it takes the FCC lattice's rule");
  auto only_2d = [](const std::string& option) {
    throw std::invalid_argument(option + " is for 2D sections; a 3D specimen has --sphere-radius-mm and --depth-mm, "
                                "and places its stones by --stone-packing");
  };
  if (o.so.disk_radius_mm != defaults.so.disk_radius_mm) only_2d("--disk-radius-mm");
  if (o.so.placement != defaults.so.placement) only_2d("--placement");
  if (o.so.binder_film_mm != defaults.so.binder_film_mm) only_2d("--binder-film-mm");
  if (o.section == "transverse" && o.plate == "patch")
    throw std::invalid_argument("--section transverse and --plate patch are two plates: the strip across the "
                                "travel (the wheel's width, the depth along the travel) or the tyre's patch");
  if (o.mat.mastic_aggregate_factor != defaults.mat.mastic_aggregate_factor)
    throw std::invalid_argument("--mastic-aggregate-factor is the 2D model's (fitted on 2# with the films between "
                                "stones); in 3D give --mastic-aggregate-factor-3d");
  o.mat.mastic_aggregate_factor = o.mastic_aggregate_factor_3d;
  resolve_model_options(o);
  o.convert();
  const auto& wt = o.wt;
  const auto& mat = o.mat;
  const auto& num = o.num;
  mat.mastic.validate();
  vrut::validate_poisson(mat.mastic_nu);
  vrut::validate_poisson(mat.aggregate_nu);
  vrut::TimeShift{num.shift};
  vrut::SpecimenSettings3 ss = specimen_cli::to_settings3(o.so, o.o3);
  o.mat.least_film = binder_film_option_m("--least-film", o.least_film, ss.gradation, ss.mix);
  o.mat.stone_shear_film = binder_film_option_m("--stone-shear-film", o.stone_shear_film, ss.gradation, ss.mix);
  scale_mastic_by_filler(o, ss.gradation, ss.mix);
  wt.validate(ss.placement.width * 1e-3);
  if (wt.patch)
    vrut::check_patch_depth("--plate patch",
                            vrut::fcc_cells_deep(ss.placement.depth, ss.sphere_radius) * vrut::fcc_cell(ss.sphere_radius),
                            o.wheel_width_mm, ss.sphere_radius);
  vrut::rutting_table3(mat, 2e-3 * ss.sphere_radius, num.shift);  // refuses what 3D cannot run, before any output
  const std::vector<std::uint64_t> seeds =
      o.seeds_text.empty() ? std::vector<std::uint64_t>{ss.seed} : cli::parse_seed_list(o.seeds_text);
  const bool ensemble = !o.seeds_text.empty();
  const std::vector<std::uint64_t> my_seeds = ranks::seeds_of_rank(seeds, session);
  const double spheres = 4.0 / std::pow(vrut::fcc_cell(ss.sphere_radius), 3) * ss.placement.width *
                         ss.placement.height * ss.placement.depth;
  // Measured: about 2 kB a sphere in the run (95k spheres).
  vrut::require_memory(spheres * my_seeds.size(), 3072.0, 64e6, ensemble ? "this 3D ensemble" : "this 3D run");
  std::optional<vrut::OutputDir> output;  // rank 0 writes the results
  if (session.root() && !o.out.empty()) output.emplace(o.out, o.force);
  if (output) output->write_text("config.ini", config_text);
  // The results, and two checkpoints (the old one stays until the new one
  // is whole) of about 2.5 kB a sphere.
  if (output) output->require_space(4'000'000 + 400 * static_cast<std::size_t>(spheres) +
                       2 * 2'500 * static_cast<std::size_t>(spheres * my_seeds.size()) * session.size());

  // The stones go into the checkpoint's header: a resumed run takes them
  // from there rather than placing them again (a compacted 3# specimen
  // takes about 18 minutes to place). Checkpoints written before they were
  // kept have none: those runs place their stones again, the same stones.
  const nlohmann::json* stones_kept =
      checkpoint != nullptr && checkpoint->resuming() && checkpoint->header().contains("stones3")
          ? &checkpoint->header().at("stones3")
          : nullptr;
  nlohmann::json stones_to_keep = nlohmann::json::object();
  // Kokkos first: an ensemble places its specimens on as many host threads
  // as the run has.
  std::optional<vrut::KokkosSession> kokkos;
  if (hooks.start_runtime) hooks.start_runtime(o.threads);
  else kokkos.emplace(o.threads);
  std::vector<vrut::Specimen3> specimens;
  if (stones_kept != nullptr) {
    for (std::uint64_t seed : my_seeds) {
      ss.seed = seed;
      const std::string key = std::to_string(seed);
      if (!stones_kept->contains(key))
        throw vrut::CheckpointError(checkpoint->path().string() + " keeps no stones for seed " + key +
                                    ": it is of another run");
      specimens.push_back(vrut::specimen3_on_stones(
          ss, vrut::placement_from_stones3_state(stones_kept->at(key), checkpoint->path().string())));
      std::fprintf(stderr, "seed %s: the stones placed when the run began, from the checkpoint\n", key.c_str());
    }
  } else {
    try {
      if (my_seeds.size() > 1) {
        specimens = specimen_cli::generate_specimens3_showing_progress(
            ss, my_seeds, vrut::concurrency(Kokkos::DefaultHostExecutionSpace()));
      } else {
        vrut::SpecimenSettings3 alone = ss;  // one specimen: its compaction (3#) on all the run's threads
        alone.seed = my_seeds.front();
        alone.compaction.threads = vrut::concurrency(Kokkos::DefaultHostExecutionSpace());
        specimens.push_back(specimen_cli::generate_specimen3_showing_progress(alone, "placing stones"));
      }
    } catch (const std::runtime_error& e) {  // the stones' fraction could not be reached
      throw std::runtime_error((my_seeds.size() > 1 ? "" : "seed " + std::to_string(my_seeds.front()) + ": ") + e.what());
    }
    for (std::size_t e = 0; e < my_seeds.size(); ++e) {
      stones_to_keep[std::to_string(my_seeds[e])] = vrut::stones3_state(specimens[e].placement);
      const std::string jammed = specimen_cli::jammed_compaction_note(specimens[e].placement);
      if (!jammed.empty()) std::fprintf(stderr, "seed %llu: %s\n", static_cast<unsigned long long>(my_seeds[e]), jammed.c_str());
    }
  }
  if (stones_kept == nullptr && checkpoint != nullptr) checkpoint->add_to_header("stones3", std::move(stones_to_keep));
  const vrut::Specimen3& sp = specimens.front();
  std::size_t all_spheres = 0;
  for (const auto& one : specimens) all_spheres += one.spheres.centers.size();
  std::FILE* const screen = session.root() ? stderr : nullptr;  // rank 0 speaks for all
  if (screen != nullptr)
    std::fprintf(screen, "specimen%s: gradation %s, 3D, %.0f x %.0f x %.2f mm, %zu spheres%s, %zu stones%s; plate "
                 "%.2f x %.2f mm, loading %.1f s (%.4g s reduced)\n",
                 ensemble ? "s" : "", ss.gradation.name.c_str(), sp.width, sp.height, sp.depth, all_spheres,
                 session.size() > 1 ? (" on rank 0 of " + std::to_string(session.size())).c_str()
                                    : (ensemble ? " in all" : ""),
                 sp.placement.stones.size(), ensemble ? " in the first" : "", wt.plate_length() * 1e3,
                 wt.patch ? wt.wheel_width * 1e3 : sp.depth,
                 wt.loading_time(), wt.loading_time() / num.shift);
  int used_threads = 1;
  // In minutes of the test a second; a resumed run says where it took up the test.
  vrut::app::LoadingBar bar(ensemble, seeds.size(), wt.minutes, checkpoint != nullptr && checkpoint->resuming(),
                             screen);
  if (checkpoint != nullptr && checkpoint->resuming())
    std::fprintf(stderr, "resuming from %s\n", checkpoint->path().c_str());
  std::vector<vrut::RuttingResult3> runs3;
  {
    CatchStopSignals catching;
    SettlingBar settling(ensemble ? seeds.size() : 1, screen);
    try {
      runs3 = vrut::dispatch_backend(o.backend, [&](auto space) {
        used_threads = vrut::concurrency(space);
        return vrut::run_rutting_ensemble3(
            specimens, wt, mat, num, space,
            [&](double fraction, long) {
              bar.update(fraction);
              if (hooks.progress) hooks.progress(fraction);
            },
            // Every rank stops at the same sample, so the curves stay the same length.
            [&] { return session.any(stop_signal != 0); }, checkpoint, [&](long done, long steps) { settling(done, steps); });
      });
    } catch (const vrut::SimulationUnstable&) {
      std::fprintf(stderr, "\n--timestep-safety sets the time-step safety (%g here)\n", num.timestep_safety);
      if (checkpoint != nullptr && fs::exists(checkpoint->path()))
        std::fprintf(stderr, "\nthe last checkpoint before it is kept in %s\n", checkpoint->path().c_str());
      throw;
    }
  }
  std::vector<vrut::RuttingResult> runs;
  std::vector<ranks::SpecimenFacts> facts;
  for (std::size_t e = 0; e < runs3.size(); ++e) {
    runs.push_back(runs3[e].result);
    facts.push_back({specimens[e].placement.stones.size(), specimens[e].placement.achieved_fraction, session.rank()});
  }
  // Rank 0 gathers every specimen's result, in the seeds' order.
  if (!ranks::gather_on_root(session, runs, facts)) {
    RuttingOutcome outcome;
    outcome.seeds = seeds;
    outcome.ensemble = ensemble;
    outcome.interrupted = runs.front().interrupted;
    if (outcome.interrupted) outcome.exit_code = 128 + static_cast<int>(stop_signal);
    return outcome;
  }
  all_spheres = 0;
  for (const auto& r : runs) all_spheres += r.particles;
  const vrut::RuttingResult& res = runs.front();
  const bool interrupted = res.interrupted;
  const double minutes_done = res.samples.empty() ? 0.0 : res.samples.back().minutes;
  if (interrupted)
    std::fprintf(stderr, "\n%s at %.1f of %.0f minutes: writing the results so far\n",
                 stop_signal == SIGTERM ? "terminated (SIGTERM)" : "interrupted (Ctrl-C)", minutes_done, wt.minutes);
  else
    bar.finish();

  const RuttingReport report = report_runs(runs, wt, ensemble, interrupted);
  const std::string what_was_run = "gradation " + ss.gradation.name + ", 3D";
  if (output) {
    write_deformation(*output, runs, report, seeds, ensemble,
                      "Virtual wheel-tracking test in 3D, gradation " + ss.gradation.name);
    write_skeleton_plot(*output, runs, "3D, gradation " + ss.gradation.name);
    if (ensemble)
      write_seeds_csv(*output, runs, report, seeds, facts, "spheres,placed_stones,stone_volume_fraction", interrupted);
    // Pictures and VTK of the first specimen.
    draw::section3_png(sp, output->file("specimen_mid_depth.png").string());
    draw::section3_png(sp, output->file("section_mid_depth.png").string(), 6.0, &runs3.front().final_positions);
    draw::surface3_png(sp, output->file("surface.png").string(), 6.0, &runs3.front().final_positions);
    final_vtk3(sp, runs3.front(), output->file("final.vtk").string());
  }

  double wall_seconds = 0.0;
  for (const auto& r : runs) wall_seconds = std::max(wall_seconds, r.wall_seconds);
  const double speed = all_spheres * static_cast<double>(res.steps) / wall_seconds;
  RuttingOutcome outcome;
  nlohmann::json& j = outcome.summary;
  j["dimension"] = 3;
  j["gradation"] = ss.gradation.name;
  j["seed"] = seeds.front();
  j["sphere_radius_mm"] = sp.spheres.radius;
  j["shift_factor"] = num.shift;
  j["timestep_safety"] = num.timestep_safety;  // as the dimension resolved it (resolve_model_options)
  j["settle_steps"] = num.settle_steps;        // as resolved (resolve_model_options)
  j["conversion"] = "fcc_lattice";
  j["particles"] = all_spheres;
  j["mpi_ranks"] = session.size();
  j["rigid_stones"] = true;
  j["stone_film"] = o.stone_film;
  j["mastic_aggregate_factor"] = mat.mastic_aggregate_factor;
  j["least_film_um"] = mat.least_film * 1e6;  // a candidate (docs/validation.md); 0 in the model
  j["stone_shear_film_um"] = mat.stone_shear_film * 1e6;  // an experiment (docs/validation.md); 0 in the model
  j["stone_friction"] = mat.stone_friction;  // the 3D model's one constant, fitted on 2# (stone_friction_3d)
  j["mastic_by_filler"] = o.mastic_by_filler;  // the filler's Rigden voids, 0.35 in the model (mastic_by_filler_3d)
  j["mastic_scale"] = o.mastic_scale;
  // Whether this run is the 3D model fitted on 2# (docs/validation.md, "The
  // frozen 3D model"): its friction and filler as the model has them.
  const bool calibrated = mat.stone_friction == stone_friction_3d &&
                          whole_number(o.mastic_by_filler) == vrut::RuttingModel3::filler_rigden_voids;  // .35 too
  j["calibrated"] = calibrated;
  j["wall_seconds"] = wall_seconds;
  j["backend"] = o.backend;
  j["threads"] = used_threads;
  j["particle_steps_per_second"] = speed;
  j["contact_length_mm"] = wt.contact_length() * 1e3;
  j["section"] = wt.transverse ? "transverse" : "longitudinal";  // transverse: the strip across the travel
  j["plate_mm"] = {wt.plate_length() * 1e3, wt.patch ? wt.wheel_width * 1e3 : sp.depth};
  j["plate"] = wt.patch ? "patch" : "strip";  // a patch is a candidate (docs/validation.md); the strip the model
  j["loading_time_s"] = wt.loading_time();
  add_shared_summary(j, res, report, interrupted, minutes_done);
  j["specimen"] = specimen_cli::specimen3_summary(sp);
  if (ensemble) j["ensemble"] = ensemble_json(runs, report, seeds, facts, interrupted, "spheres");
  j["skeleton"] = skeleton_summary_json(runs);
  if (output) {
    output->write_text("summary.json", j.dump(2) + '\n');
    // Every rank's checkpoint of a stopped run goes with its partial results.
    if (interrupted && checkpoint != nullptr) ranks::keep_checkpoints(o.out, *output, session.size());
    output->commit();
  }
  outcome.runs = std::move(runs);
  outcome.seeds = seeds;
  outcome.report = report;
  outcome.ensemble = ensemble;
  outcome.interrupted = interrupted;
  if (interrupted) {
    outcome.exit_code = 128 + static_cast<int>(stop_signal);
    if (hooks.print && output)
      std::printf("partial results (%.1f of %.0f minutes, no dynamic stability) in %s\ngo on with: %s\n", minutes_done,
                  wt.minutes, o.out.c_str(), ranks::resume_command(session.size(), o.out).c_str());
    return outcome;
  }
  if (hooks.print) {
    char speed_text[128];
    std::snprintf(speed_text, sizeof speed_text, "%zu spheres, %ld steps, %.0f s, %.3g particle-steps/s", all_spheres,
                  outcome.runs.front().steps, wall_seconds, speed);
    print_result(what_was_run, outcome.runs, report, wt, ensemble, speed_text, o.out,
                 calibrated ? "; the 3D model, its stones' friction fitted on 2#: docs/validation.md"
                            : "; not the 3D model fitted on 2# (its --stone-friction or --mastic-by-filler): "
                              "docs/validation.md");
  }
  return outcome;
}

}  // namespace vrut::app
