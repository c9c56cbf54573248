#pragma once
// vrut-rutting --dim 3: the 3D test of one specimen (rutting/run3.hpp) and
// its outputs. What 3D does not have yet (ensembles, checkpoints, images,
// the films between stones, the method's stones) is refused by name.
#include "../common/cli.hpp"
#include "../common/draw3.hpp"
#include "../common/specimen3_cli.hpp"
#include "options.hpp"
#include "outputs.hpp"

#include <vrut/analysis/standard_ds.hpp>
#include <vrut/backend.hpp>
#include <vrut/io/memory_check.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/plot.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/io/vtk.hpp>
#include <vrut/rutting/run3.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

int run_rutting_3d(const CLI::App& app, RunOptions o) {
  // By value, not by what was typed: a config file (config.ini) holds every option.
  const RunOptions defaults;
  auto not_yet = [](const std::string& option) {
    throw std::invalid_argument(option + " is not in the 3D test yet (--dim 3 runs one generated specimen, rigid "
                                "stones, no film between stones, the FCC lattice's Burger's rule)");
  };
  if (!o.seeds_text.empty()) not_yet("--seeds");
  if (!o.io.images.empty()) not_yet("--image");
  if (o.exact_stones) not_yet("--exact-stones");
  if (o.mat.film_endless) not_yet("--film-endless");
  if (o.conversion != defaults.conversion) not_yet("--conversion " + o.conversion);
  if (o.checkpoint_every > 0.0) not_yet("--checkpoint-every");
  if (app.count("--stone-film") > 0 && o.stone_film != "none" && o.stone_film != defaults.stone_film)
    not_yet("--stone-film " + o.stone_film);
  auto only_2d = [](const std::string& option) {
    throw std::invalid_argument(option + " is for 2D sections; a 3D specimen has --sphere-radius-mm and --depth-mm, "
                                "and places its stones by jiggling");
  };
  if (o.so.disk_radius_mm != defaults.so.disk_radius_mm) only_2d("--disk-radius-mm");
  if (o.so.placement != defaults.so.placement) only_2d("--placement");
  if (o.so.binder_film_mm != defaults.so.binder_film_mm) only_2d("--binder-film-mm");
  o.stone_film = "none";
  if (o.mat.mastic_aggregate_factor != defaults.mat.mastic_aggregate_factor)
    throw std::invalid_argument("--mastic-aggregate-factor is the 2D model's (fitted on 2# with the films between "
                                "stones); in 3D give --mastic-aggregate-factor-3d");
  o.mat.mastic_aggregate_factor = o.mastic_aggregate_factor_3d;
  o.convert();
  const auto& wt = o.wt;
  const auto& mat = o.mat;
  const auto& num = o.num;
  mat.mastic.validate();
  vrut::validate_poisson(mat.mastic_nu);
  vrut::validate_poisson(mat.aggregate_nu);
  vrut::TimeShift{num.shift};
  const vrut::SpecimenSettings3 ss = specimen_cli::to_settings3(o.so, o.o3);
  wt.validate(ss.placement.width * 1e-3);
  vrut::rutting_table3(mat, 2e-3 * ss.sphere_radius, num.shift);  // refuses what 3D cannot run, before any output
  const double spheres = 4.0 / std::pow(vrut::fcc_cell(ss.sphere_radius), 3) * ss.placement.width *
                         ss.placement.height * ss.placement.depth;
  // Measured: about 2 kB a sphere in the run (95k spheres).
  vrut::require_memory(spheres, 3072.0, 64e6, "this 3D run");
  vrut::OutputDir output(o.out, o.force);
  output.write_text("config.ini", app.config_to_str(true, true));
  output.require_space(4'000'000 + 400 * static_cast<std::size_t>(spheres));

  vrut::Specimen3 sp;
  {
    std::unique_ptr<vrut::ProgressBar> placing;
    try {
      sp = vrut::generate_specimen3(ss, [&](std::size_t placed, std::size_t total) {
        if (!placing) placing = std::make_unique<vrut::ProgressBar>("placing stones", static_cast<long>(total), "stones");
        placing->update(static_cast<long>(placed));
        if (placed == total) placing->finish();
      });
    } catch (const std::runtime_error& e) {  // the stones' fraction could not be reached
      std::cerr << "error: " << e.what() << '\n';
      return 1;
    }
  }
  std::fprintf(stderr, "specimen: gradation %s, 3D, %.0f x %.0f x %.2f mm, %zu spheres, %zu stones; plate %.2f x %.2f mm, "
               "loading %.1f s (%.4g s reduced)\n",
               ss.gradation.name.c_str(), sp.width, sp.height, sp.depth, sp.spheres.centers.size(),
               sp.placement.stones.size(), wt.contact_length() * 1e3, sp.depth, wt.loading_time(),
               wt.loading_time() / num.shift);
  vrut::KokkosSession kokkos(o.threads);
  int used_threads = 1;
  vrut::ProgressBar bar("loading", 1000, "permille");
  vrut::RuttingResult3 run;
  try {
    run = vrut::dispatch_backend(o.backend, [&](auto space) {
      used_threads = vrut::concurrency(space);
      return vrut::run_rutting3(sp, wt, mat, num, space,
                                [&](double fraction, long) { bar.update(static_cast<long>(1000 * fraction)); });
    });
  } catch (const vrut::SimulationUnstable&) {
    std::fprintf(stderr, "\n--timestep-safety sets the time-step safety (%g here)\n", num.timestep_safety);
    throw;
  }
  bar.finish();
  const vrut::RuttingResult& res = run.result;

  std::ostringstream csv;
  csv.precision(17);
  csv << "minutes,reduced_time_s,deformation_mm,plate_pressure_mpa\n";
  std::vector<double> minutes, deformation;
  for (const auto& s : res.samples) {
    csv << s.minutes << ',' << s.reduced_time << ',' << s.deformation * 1e3 << ',' << s.plate_pressure * 1e-6 << '\n';
    minutes.push_back(s.minutes);
    deformation.push_back(s.deformation * 1e3);
  }
  output.write_text("deformation.csv", csv.str());
  vrut::PlotSpec spec;
  spec.xlabel = "test time (min)";
  spec.ylabel = "deformation (mm)";
  spec.title = "Virtual wheel-tracking test in 3D, gradation " + ss.gradation.name;
  vrut::write_plot_png(output.file("deformation.png").string(), spec, {{"rut depth under the plate", minutes, deformation}});
  draw::section3_png(sp, output.file("specimen_mid_depth.png").string());
  draw::section3_png(sp, output.file("section_mid_depth.png").string(), 6.0, &run.final_positions);
  draw::surface3_png(sp, output.file("surface.png").string(), 6.0, &run.final_positions);
  {
    std::vector<double> x, y, z, radius, group, stone, dx, dy, dz;
    for (std::size_t i = 0; i < run.final_positions.size(); ++i) {
      x.push_back(run.final_positions[i].x());
      y.push_back(run.final_positions[i].y());
      z.push_back(run.final_positions[i].z());
      radius.push_back(sp.spheres.radius);
      group.push_back(res.group[i]);
      stone.push_back(sp.spheres.stone[i]);
      dx.push_back(run.displacement[i].x());
      dy.push_back(run.displacement[i].y());
      dz.push_back(run.displacement[i].z());
    }
    vrut::VtkPointData data;
    data.scalars = {{"radius", radius}, {"group", group}, {"stone", stone}, {"dx", dx}, {"dy", dy}, {"dz", dz}};
    vrut::write_vtk_points(output.file("final.vtk").string(),
                           "vrut 3D rutting, the end of the loading (mm, y up, z periodic); displacement while loading",
                           x, y, z, data);
  }

  const vrut::ReportedDS reported = vrut::report_ds(res.dynamic_stability, res.dynamic_stability_is_lower_bound);
  const double speed = res.particles * static_cast<double>(res.steps) / res.wall_seconds;
  nlohmann::json j;
  j["dimension"] = 3;
  j["gradation"] = ss.gradation.name;
  j["seed"] = ss.seed;
  j["sphere_radius_mm"] = sp.spheres.radius;
  j["shift_factor"] = num.shift;
  j["conversion"] = "fcc_lattice";
  j["particles"] = res.particles;
  j["bonds"] = res.bonds;
  j["contacts"] = res.contacts;
  j["rigid_stones"] = true;
  j["stone_film"] = "none";
  j["mastic_aggregate_factor"] = mat.mastic_aggregate_factor;
  j["calibrated"] = false;  // 3D has no calibration on 2# yet
  j["steps"] = res.steps;
  j["reduced_dt_s"] = res.dt;
  j["wall_seconds"] = res.wall_seconds;
  j["backend"] = o.backend;
  j["threads"] = used_threads;
  j["particle_steps_per_second"] = speed;
  j["contact_length_mm"] = wt.contact_length() * 1e3;
  j["plate_mm"] = {wt.contact_length() * 1e3, sp.depth};
  j["loading_time_s"] = wt.loading_time();
  j["deformation_45min_mm"] = res.deformation_at_ds_start * 1e3;
  j["deformation_60min_mm"] = res.deformation_final * 1e3;
  j["rut_depth_mm"] = res.deformation_final * 1e3;
  j["dynamic_stability_passes_per_mm"] = res.dynamic_stability;
  j["dynamic_stability_is_lower_bound"] = res.dynamic_stability_is_lower_bound;
  j["deformation_resolution_mm"] = res.deformation_resolution * 1e3;
  j["dynamic_stability_standard"] = standard_ds_json(reported);
  j["specimen"] = specimen_cli::specimen3_summary(sp);
  output.write_text("summary.json", j.dump(2) + '\n');
  output.commit();
  std::printf("gradation %s, 3D: rut depth %.2f mm at %.0f min, dynamic stability %s%.0f passes/mm, as the standard "
              "reports it %s (%zu spheres, %ld steps, %.0f s, %.3g particle-steps/s; not calibrated in 3D)\n"
              "results in %s\n",
              ss.gradation.name.c_str(), res.deformation_final * 1e3, wt.minutes,
              res.dynamic_stability_is_lower_bound ? "above " : "", res.dynamic_stability,
              vrut::reported_ds_text(reported).c_str(), res.particles, res.steps, res.wall_seconds, speed,
              o.out.c_str());
  return 0;
}

}  // namespace
