#pragma once
// The demonstration job: a bonded hex-packed block of disks compressed by a
// servo-controlled plate to a target stress. Generic in the contact law, so a
// user-written law plugs in (see custom_law/).
#include <vrut/app/cli.hpp>

#include <vrut/backend.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/vrut.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace demo {

struct Options {
  std::string backend = "openmp";
  int threads = 0;
  int columns = 60, rows = 30;
  double radius_mm = 0.5;
  double stress_mpa = 0.7;
  double thickness_mm = 50.0;
  double damping = 0.7;
  long steps = 20000;
  std::string out = "out/demo";
  bool force = false;
};

// Fills opts from the command line. Returns -1 to go on, else the exit code
// (0 for --help, 2 for a malformed command line).
inline int parse(int argc, char** argv, Options& opts, const std::string& description) {
  CLI::App app(description);
  const auto backends = vrut::available_backends();
  app.add_option("--backend", opts.backend, "Kokkos backend")->check(CLI::IsMember(backends))->capture_default_str();
  app.add_option("--threads", opts.threads, "host threads (0: OMP_NUM_THREADS)")->check(CLI::Range(0, 1024));
  app.add_option("--columns", opts.columns, "disks per row")->check(CLI::Range(2, 2000))->capture_default_str();
  app.add_option("--rows", opts.rows, "rows of disks")->check(CLI::Range(2, 2000))->capture_default_str();
  app.add_option("--radius-mm", opts.radius_mm, "disk radius, mm")
      ->check(CLI::Range(1e-3, 100.0))->capture_default_str();
  app.add_option("--stress-mpa", opts.stress_mpa, "target plate stress, MPa")
      ->check(CLI::Range(1e-6, 100.0))->capture_default_str();
  app.add_option("--thickness-mm", opts.thickness_mm, "out-of-plane disk width t, mm")
      ->check(CLI::Range(1e-3, 1e4))->capture_default_str();
  app.add_option("--damping", opts.damping, "local damping coefficient")
      ->check(CLI::Range(0.0, 0.99))->capture_default_str();
  app.add_option("--steps", opts.steps, "time steps")->check(CLI::Range(1L, 100000000L))->capture_default_str();
  app.add_option("--out", opts.out, "output folder")->capture_default_str();
  app.add_flag("--force", opts.force, "overwrite an existing output folder");
  return vrut::app::cli::parse(app, argc, argv);
}

// Material constants of the demonstration block (aggregate-like disks).
struct Material {
  double density = 2700.0;  // kg/m^3
  double kn = 0.0, ks = 0.0;
};

template <class Law, class Space>
nlohmann::json compress(const Options& o, const vrut::AssignmentTable<Law>& table, const Material& mat,
                        const vrut::OutputDir& dir, const Space& space) {
  using namespace vrut;
  const double r = o.radius_mm * 1e-3, t = o.thickness_mm * 1e-3, stress = o.stress_mpa * 1e6;
  SimulationSettings settings;
  settings.thickness = t;
  CentralDifference::params_type integrator;
  integrator.damping = o.damping;
  Simulation<Law, Space, CentralDifference, ServoControl> sim(hex_packing(o.columns, o.rows, r, mat.density), table,
                                                              settings, integrator, space);
  const int bonds = sim.bond_touching_contacts(1e-9 * r);
  const double width = 2.0 * r * o.columns + r;
  const double top = r * (2.0 + std::sqrt(3.0) * (o.rows - 1));
  const auto wall_law = linear_params(mat.kn, 0.0, 0.0);
  // A mould: bottom and side walls, frictionless, and the plate on top.
  sim.add_wall(Wall{{0.0, 0.0}, {width, 0.0}, {}}, wall_law);
  sim.add_wall(Wall{{0.0, 2.0 * top}, {0.0, 0.0}, {}}, wall_law);
  sim.add_wall(Wall{{width, 0.0}, {width, 2.0 * top}, {}}, wall_law);
  const int plate = sim.add_wall(Wall{{width, top}, {0.0, top}, {}}, wall_law,
                                 ServoControl::for_stress(stress, width, t, mat.kn, 0.2, 0.05));
  const double dt = 0.2 * sim.critical_timestep();
  const double height0 = top;

  std::ofstream csv(dir.file("compression.csv"));
  csv << "step,time_s,plate_stress_mpa,strain\n";
  ProgressBar bar("compressing", o.steps);
  const long every = std::max(1L, o.steps / 200);
  double plate_stress = 0.0, strain = 0.0;
  for (long s = 1; s <= o.steps; ++s) {
    sim.step(dt);
    if (s % every == 0 || s == o.steps) {
      const Wall w = sim.wall(plate);
      plate_stress = ServoControl::compressive_force(w, sim.wall_load(plate)) / (width * t);
      strain = 1.0 - w.start.y / height0;
      csv << s << ',' << sim.time() << ',' << plate_stress * 1e-6 << ',' << strain << '\n';
      bar.update(s);
    }
  }
  bar.finish();
  const double seconds = bar.elapsed_seconds();
  nlohmann::json j;
  j["particles"] = sim.particles().size();
  j["bonds"] = bonds;
  j["intact_bonds"] = sim.intact_bonds();
  j["steps"] = o.steps;
  j["dt_s"] = dt;
  j["wall_seconds"] = seconds;
  j["particle_steps_per_second"] = sim.particles().size() * static_cast<double>(o.steps) / seconds;
  j["target_stress_mpa"] = o.stress_mpa;
  j["plate_stress_mpa"] = plate_stress * 1e-6;
  j["plate_strain"] = strain;
  return j;
}

// Everything main does after parsing: output folder check, Kokkos, dispatch.
template <class Law, class MakeTable>
int run(const Options& o, const Material& mat, MakeTable make_table, const std::string& law_name) {
  return vrut::app::cli::guarded([&] {
    vrut::OutputDir dir(o.out, o.force);
    vrut::KokkosSession kokkos(o.threads);
    const vrut::AssignmentTable<Law> table = make_table();
    nlohmann::json j = vrut::dispatch_backend(o.backend, [&](auto space) {
      auto summary = compress<Law>(o, table, mat, dir, space);
      summary["threads"] = vrut::concurrency(space);
      return summary;
    });
    j["backend"] = o.backend;
    j["law"] = law_name;
    std::ofstream(dir.file("summary.json")) << j.dump(2) << '\n';
    dir.commit();
    std::printf("plate stress %.4f MPa (target %.4f), strain %.5f, %.3g particle-steps/s on %s\n",
                j["plate_stress_mpa"].get<double>(), o.stress_mpa, j["plate_strain"].get<double>(),
                j["particle_steps_per_second"].get<double>(), o.backend.c_str());
    std::printf("results in %s/summary.json and compression.csv\n", o.out.c_str());
    return 0;
  });
}

}  // namespace demo
