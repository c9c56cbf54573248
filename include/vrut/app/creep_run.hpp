#pragma once
// The virtual creep test of the application layer: vrut-creep's options (with
// their checks and units), the run and its outputs, shared by vrut-creep and
// the Python module (vrut.creep).
#include "cli.hpp"

#include <vrut/backend.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/plot.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/material/burgers_fit.hpp>
#include <vrut/protocol/creep.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut::app {

// Every option of a creep run, in the units typed (mm, MPa).
struct CreepOptions {
  vrut::CreepSettings cs;
  std::string backend = "openmp", out = "out/creep", conversion = "seed";
  int threads = 0;
  bool force = false;
  double radius_mm = cs.radius * 1e3, thickness_mm = cs.thickness * 1e3, stress_mpa = cs.stress * 1e-6;
  double e1 = cs.macro.E1 * 1e-6, eta1 = cs.macro.eta1 * 1e-6, e2 = cs.macro.E2 * 1e-6, eta2 = cs.macro.eta2 * 1e-6;
};

inline void add_creep_options(CLI::App& app, CreepOptions& o) {
  auto& cs = o.cs;
  app.add_option("--backend", o.backend, "Kokkos backend")->check(CLI::IsMember(vrut::available_backends()))
      ->capture_default_str();
  app.add_option("--threads", o.threads, "host threads (0: OMP_NUM_THREADS)")->check(CLI::Range(0, 1024));
  app.add_option("--columns", cs.columns, "disks per row")->check(CLI::Range(2, 2000))->capture_default_str();
  app.add_option("--rows", cs.rows, "rows of disks")->check(CLI::Range(2, 2000))->capture_default_str();
  app.add_option("--radius-mm", o.radius_mm, "disk radius, mm")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--thickness-mm", o.thickness_mm, "disk width t, mm")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--density", cs.density, "mastic density, kg/m^3")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--stress-mpa", o.stress_mpa, "plate stress sigma0, MPa")->check(cli::finite_positive())
      ->capture_default_str();
  app.add_option("--time-s", cs.duration, "loading time, s (real; reduced by the shift factor)")
      ->check(cli::finite_positive())->capture_default_str();
  app.add_option("--shift", cs.shift, "time-temperature shift factor alpha_T")->capture_default_str();
  app.add_option("--E1", o.e1, "Maxwell modulus, MPa")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--eta1", o.eta1, "Maxwell viscosity, MPa s")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--E2", o.e2, "Kelvin modulus, MPa")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--eta2", o.eta2, "Kelvin viscosity, MPa s")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--nu", cs.nu, "Poisson's ratio of the mastic, [0, 0.5)")->check(cli::finite_range(0.0, 0.5, true))
      ->capture_default_str();
  app.add_option("--conversion", o.conversion, "macro-to-micro rules: seed (method.md) or calibrated")
      ->check(CLI::IsMember({"seed", "calibrated"}))->capture_default_str();
  app.add_option("--damping", cs.damping, "local damping coefficient")->check(cli::finite_range(0.0, 0.99))
      ->capture_default_str();
  app.add_option("--points", cs.points, "samples written")->check(CLI::Range(2, 100000))->capture_default_str();
  app.add_option("--out", o.out, "output folder")->capture_default_str();
  app.add_flag("--force", o.force, "overwrite an existing output folder");
}

struct CreepOutcome {
  vrut::CreepResult result;
  nlohmann::json summary;  // creep.json's content
};

// Runs the creep test of these options; with o.out empty nothing is written.
// Bad input throws std::invalid_argument. print: the command line's lines;
// start_runtime: as in RuttingHooks (unset: the run's own Kokkos session).
inline CreepOutcome run_creep_app(CreepOptions o, bool print = true,
                                  const std::function<void(int)>& start_runtime = {}) {
  auto& cs = o.cs;
  cs.radius = o.radius_mm * 1e-3;
  cs.thickness = o.thickness_mm * 1e-3;
  cs.stress = o.stress_mpa * 1e6;
  cs.macro = {o.e1 * 1e6, o.eta1 * 1e6, o.e2 * 1e6, o.eta2 * 1e6};
  cs.validate();
  cs.conversion = o.conversion == "seed" ? vrut::MicroConversion::seed() : vrut::MicroConversion::calibrated(cs.nu);
  const double final_macro_strain = cs.macro.creep_strain(cs.stress, cs.duration);
  if (final_macro_strain > 0.2)
    std::cerr << "warning: the macro model creeps to a strain of " << final_macro_strain
              << "; a DEM block cannot follow that far (compare at a lower --stress-mpa, e.g. 0.01)\n";

  std::optional<vrut::OutputDir> dir;
  if (!o.out.empty()) dir.emplace(o.out, o.force);
  std::optional<vrut::KokkosSession> kokkos;
  if (start_runtime) start_runtime(o.threads);
  else kokkos.emplace(o.threads);
  int used_threads = 1;
  // Reported in permille of the test; read as seconds of the (real) loading a second.
  vrut::ProgressBar bar("creep", 1000, {"test s", cs.duration / 1000.0});
  CreepOutcome outcome;
  outcome.result = vrut::dispatch_backend(o.backend, [&](auto space) {
    used_threads = vrut::concurrency(space);
    return vrut::run_creep(cs, space, [&](long done, long total) { bar.update(done * 1000 / total); });
  });
  bar.finish();
  const vrut::CreepResult& res = outcome.result;

  std::vector<double> t, eps_virtual, eps_macro;
  double worst = 0.0;
  std::ostringstream csv;
  csv << "time_s,reduced_time_s,strain_virtual,strain_analytic,plate_stress_mpa\n";
  for (const auto& s : res.samples) {
    csv << s.time << ',' << s.reduced_time << ',' << s.strain_virtual << ',' << s.strain_analytic << ','
        << s.plate_stress * 1e-6 << '\n';
    t.push_back(s.time);
    eps_virtual.push_back(s.strain_virtual);
    eps_macro.push_back(s.strain_analytic);
    worst = std::max(worst, std::abs(s.strain_virtual / s.strain_analytic - 1.0));
  }
  const vrut::BurgersFit fit = vrut::fit_burgers(t, eps_virtual, cs.stress);

  nlohmann::json& j = outcome.summary;
  j["backend"] = o.backend;
  j["threads"] = used_threads;
  j["conversion"] = o.conversion;
  j["conversion_factors"] = {{"maxwell_stiffness", cs.conversion.maxwell_stiffness},
                             {"maxwell_viscosity", cs.conversion.maxwell_viscosity},
                             {"kelvin_stiffness", cs.conversion.kelvin_stiffness},
                             {"kelvin_viscosity", cs.conversion.kelvin_viscosity}};
  j["specimen"] = {{"columns", cs.columns}, {"rows", cs.rows}, {"radius_mm", o.radius_mm},
                   {"thickness_mm", o.thickness_mm}, {"density", cs.density}, {"nu", cs.nu}};
  j["stress_mpa"] = o.stress_mpa;
  j["time_s"] = cs.duration;
  j["shift_factor"] = cs.shift;
  j["macro"] = {{"E1_mpa", o.e1}, {"eta1_mpa_s", o.eta1}, {"E2_mpa", o.e2}, {"eta2_mpa_s", o.eta2}};
  j["apparent"] = {{"E1_mpa", fit.macro.E1 * 1e-6}, {"eta1_mpa_s", fit.macro.eta1 * 1e-6},
                   {"E2_mpa", fit.macro.E2 * 1e-6}, {"eta2_mpa_s", fit.macro.eta2 * 1e-6},
                   {"rms_strain_residual", fit.rms_residual}};
  j["ratio_apparent_to_macro"] = {{"E1", fit.macro.E1 / cs.macro.E1}, {"eta1", fit.macro.eta1 / cs.macro.eta1},
                                  {"E2", fit.macro.E2 / cs.macro.E2}, {"eta2", fit.macro.eta2 / cs.macro.eta2}};
  j["max_relative_deviation"] = worst;
  j["particles"] = res.particles;
  j["steps"] = res.steps;
  j["reduced_dt_s"] = res.dt;
  j["wall_seconds"] = res.wall_seconds;
  j["particle_steps_per_second"] = res.particles * static_cast<double>(res.steps) / res.wall_seconds;
  if (dir) {
    dir->write_text("creep.csv", csv.str());
    dir->write_text("creep.json", j.dump(2) + '\n');
    vrut::PlotSpec spec;
    spec.title = "Creep at " + std::to_string(o.stress_mpa).substr(0, 6) + " MPa, " + o.conversion + " conversion";
    spec.xlabel = "time (s, unshifted)";
    spec.ylabel = "strain";
    vrut::write_plot_png(dir->file("creep.png").string(), spec,
                         {{"virtual (DEM)", t, eps_virtual, "lines lw 2"},
                          {"macro Burger's model", t, eps_macro, "lines lw 2 dt 2"}});
    dir->commit();
  }
  if (print) {
    std::printf("apparent/macro: E1 %.4f  eta1 %.4f  E2 %.4f  eta2 %.4f; worst deviation from macro %.2f %%\n",
                j["ratio_apparent_to_macro"]["E1"].get<double>(), j["ratio_apparent_to_macro"]["eta1"].get<double>(),
                j["ratio_apparent_to_macro"]["E2"].get<double>(), j["ratio_apparent_to_macro"]["eta2"].get<double>(),
                100.0 * worst);
    std::printf("%zu disks, %ld steps, %.1f s; results in %s\n", res.particles, res.steps, res.wall_seconds,
                o.out.c_str());
  }
  return outcome;
}

}  // namespace vrut::app
