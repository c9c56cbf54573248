// vrut._vrut: the library's application layer (include/vrut/app/) for Python.
// The keyword arguments of vrut.rutting() reach it as the command line's
// arguments (python/vrut/__init__.py writes them) and are parsed by the very
// option table vrut-rutting parses, so the checks, the unit conversions and
// the error messages are the command line's own, and so are the answers.
#include <vrut/app/creep_run.hpp>
#include <vrut/app/image_cli.hpp>
#include <vrut/app/ranks.hpp>
#include <vrut/app/rutting_2d.hpp>
#include <vrut/app/rutting_3d.hpp>
#include <vrut/app/rutting_options.hpp>
#include <vrut/app/specimen3_cli.hpp>
#include <vrut/app/specimen_cli.hpp>
#include <vrut/app/stop_signal.hpp>
#include <vrut/backend.hpp>
#include <vrut/io/checkpoint.hpp>
#include <vrut/version.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;
namespace app = vrut::app;

namespace {

// One Kokkos runtime for the process, started by the first run on the
// threads that run asks for, and ended when Python exits.
void start_kokkos(int threads) {
  if (Kokkos::is_initialized()) {
    const int running = vrut::concurrency(Kokkos::DefaultHostExecutionSpace());
    if (threads > 0 && threads != running)
      throw std::invalid_argument("--threads: Kokkos runs on " + std::to_string(running) +
                                  " host threads in this process, chosen by its first run; start a new Python "
                                  "process for another count");
    return;
  }
  vrut::initialize_kokkos(threads);
  py::gil_scoped_acquire python;  // called from a run that let the interpreter go
  py::module_::import("atexit").attr("register")(py::cpp_function([] {
    if (Kokkos::is_initialized()) Kokkos::finalize();
  }));
}

// A whole run of the module: Ctrl-C and SIGTERM caught from its first line
// (the run stops at the loading's first sample when one came while the
// specimen was made), and the interpreter free for other Python threads
// while it runs.
template <class Run>
auto run_outside_python(Run&& run) {
  app::stop_signal = 0;
  const app::CatchStopSignals catching;
  py::gil_scoped_release free;
  return run();
}

// CLI11 takes its arguments last first.
void parse(CLI::App& cli, std::vector<std::string> args) {
  std::reverse(args.begin(), args.end());
  cli.parse(args);  // CLI::ParseError: the module's ValueError, with the command line's message
}

py::list curve_mm(const vrut::RuttingResult& r) {
  py::list out;
  for (const auto& s : r.samples) out.append(s.deformation * 1e3);
  return out;
}

// vrut-rutting with these arguments; out empty: no folder written.
py::dict rutting(const std::vector<std::string>& args, const std::string& out, const py::object& progress, bool print) {
  app::RunOptions given;
  CLI::App cli("vrut.rutting");
  app::add_run_options(cli, given);
  // The folder is an option of the run as the command line's --out is, so
  // that the checkpoint's options read back as vrut-rutting --resume reads
  // them, and config.ini names it.
  std::vector<std::string> argv = args;
  if (!out.empty()) argv.push_back("--out=" + out);  // one token: a folder may begin with '-'
  parse(cli, argv);
  given.io.images = app::image_cli::given_images(given.io);
  given.width_given = cli.count("--width-mm") > 0;
  given.voids_given = cli.count("--air-voids") > 0;
  given.seed_given = cli.count("--seed") > 0;
  given.out = out;
  std::optional<vrut::CheckpointFile> checkpoint;  // with a folder: Ctrl-C leaves one, for vrut-rutting --resume
  const std::string config_text = cli.config_to_str(true, true);
  if (!out.empty()) {
    if (std::filesystem::exists(std::filesystem::path(out) / "checkpoint.vrut") && !given.force)
      throw std::invalid_argument("'" + out + "' holds the checkpoint of an unfinished run: go on with it with "
                                  "vrut-rutting --resume " + out + ", or start again with force=True");
    nlohmann::json header;
    header["argv"] = argv;
    header["config"] = cli.config_to_str(true, false);
    header["config_with_help"] = config_text;
    checkpoint.emplace(std::filesystem::path(out) / "checkpoint.vrut", given.checkpoint_every, header);
  }
  app::RuttingHooks hooks;
  hooks.print = print;
  hooks.start_runtime = start_kokkos;
  if (!progress.is_none())
    hooks.progress = [&](double fraction) {
      py::gil_scoped_acquire python;
      progress(fraction);
    };
  int argc = 0;
  char** no_argv = nullptr;
  const app::ranks::Session one_rank(argc, no_argv);
  vrut::CheckpointFile* file = checkpoint ? &*checkpoint : nullptr;
  const app::RuttingOutcome outcome = run_outside_python([&] {
    return given.dim == 3 ? app::run_rutting_3d(given, file, config_text, one_rank, hooks)
                          : app::run_rutting_2d(given, file, config_text, one_rank, hooks);
  });
  py::dict d;
  d["exit_code"] = outcome.exit_code;
  d["summary"] = outcome.summary.dump();
  d["seeds"] = outcome.seeds;
  d["interrupted"] = outcome.interrupted;
  py::list minutes, curves;
  for (const auto& s : outcome.runs.front().samples) minutes.append(s.minutes);
  for (const auto& r : outcome.runs) curves.append(curve_mm(r));
  d["minutes"] = minutes;
  d["curves_mm"] = curves;
  d["mean_curve_mm"] = curve_mm(outcome.report.summary.mean_curve);
  py::list low, high;
  for (double v : outcome.report.summary.deformation_ci_low) low.append(v * 1e3);
  for (double v : outcome.report.summary.deformation_ci_high) high.append(v * 1e3);
  d["ci95_low_mm"] = low;
  d["ci95_high_mm"] = high;
  return d;
}

// A specimen of vrut-rutting's specimen options: its particles and measures.
py::dict specimen(const std::vector<std::string>& args) {
  app::RunOptions o;
  CLI::App cli("vrut.specimen");
  app::add_run_options(cli, o);  // the specimen's options are the run's: the same names, checks and defaults
  parse(cli, args);
  o.io.images = app::image_cli::given_images(o.io);
  py::dict d;
  py::list x, y, z, stone;
  if (o.dim == 3) {
    vrut::SpecimenSettings3 ss = app::specimen_cli::to_settings3(o.so, o.o3);
    const vrut::Specimen3 sp = run_outside_python([&] {
      start_kokkos(o.threads);  // a compacted specimen uses the host threads
      ss.compaction.threads = vrut::concurrency(Kokkos::DefaultHostExecutionSpace());
      return vrut::generate_specimen3(ss);
    });
    for (std::size_t i = 0; i < sp.spheres.centers.size(); ++i) {
      x.append(sp.spheres.centers[i].x());
      y.append(sp.spheres.centers[i].y());
      z.append(sp.spheres.centers[i].z());
      stone.append(sp.spheres.stone[i]);
    }
    d["radius_mm"] = sp.spheres.radius;
    d["summary"] = app::specimen_cli::specimen3_summary(sp).dump();
  } else {
    vrut::Specimen sp;
    if (!o.io.images.empty()) {
      if (o.io.images.size() > 1) throw std::invalid_argument("--image: one image makes one specimen");
      sp = vrut::specimen_from_image(o.io.images.front(), app::image_cli::to_settings(o.io, o.so, cli.count("--width-mm") > 0,
                                                                                      cli.count("--air-voids") > 0));
    } else {
      sp = vrut::generate_specimen(app::specimen_cli::to_settings(o.so));
    }
    for (std::size_t i = 0; i < sp.disks.centers.size(); ++i) {
      x.append(sp.disks.centers[i].x());
      y.append(sp.disks.centers[i].y());
      stone.append(sp.disks.aggregate[i]);
    }
    d["radius_mm"] = sp.disks.radius;
    d["summary"] = app::specimen_cli::specimen_summary(sp).dump();
  }
  d["x_mm"] = x;
  d["y_mm"] = y;
  if (o.dim == 3) d["z_mm"] = z;
  d["stone"] = stone;
  return d;
}

// A gradation checked as the command line checks a CSV file's: name, then
// the sieves (mm) and percent passing as the library keeps them.
py::tuple gradation(const py::object& which, const std::vector<double>& sieve_mm, const std::vector<double>& passing,
                    const std::string& name) {
  vrut::Gradation g;
  if (!which.is_none()) {
    g = vrut::builtin_gradation(which.cast<int>());
  } else {
    if (sieve_mm.size() != passing.size())
      throw std::invalid_argument("a gradation: " + std::to_string(sieve_mm.size()) + " sieves and " +
                                  std::to_string(passing.size()) + " percentages passing");
    if (sieve_mm.empty()) throw std::invalid_argument("a gradation: no sieves");
    g = {name, sieve_mm, passing};
    vrut::validate_gradation(g, [&](std::size_t i) { return name + " row " + std::to_string(i + 1); });
  }
  return py::make_tuple(g.name, g.sieve_mm, g.passing);
}

// A program's option table, bound to options nobody reads: for its names,
// defaults and checks alone.
struct OptionTable {
  app::RunOptions run;
  app::CreepOptions creep;
  CLI::App cli;
  explicit OptionTable(const std::string& program) : cli("vrut." + program) {
    if (program == "creep") app::add_creep_options(cli, creep);
    else app::add_run_options(cli, run);
  }
};

// Parses without running: the options' checks alone.
void check(const std::string& program, const std::vector<std::string>& args) {
  OptionTable table(program);
  parse(table.cli, args);
}

// vrut-creep with these arguments; out empty: no folder written.
py::dict creep(const std::vector<std::string>& args, const std::string& out) {
  app::CreepOptions o;
  CLI::App cli("vrut.creep");
  app::add_creep_options(cli, o);
  parse(cli, args);
  o.out = out;
  const app::CreepOutcome outcome = run_outside_python([&] { return app::run_creep_app(o, false, start_kokkos); });
  py::dict d;
  d["summary"] = outcome.summary.dump();
  py::list time, reduced, strain, analytic, stress;
  for (const auto& s : outcome.result.samples) {
    time.append(s.time);
    reduced.append(s.reduced_time);
    strain.append(s.strain_virtual);
    analytic.append(s.strain_analytic);
    stress.append(s.plate_stress * 1e-6);
  }
  d["time_s"] = time;
  d["reduced_time_s"] = reduced;
  d["strain"] = strain;
  d["strain_analytic"] = analytic;
  d["plate_stress_mpa"] = stress;
  return d;
}

// The options of vrut-rutting (or of vrut-creep): name (without "--"), whether it is a flag,
// its default as text, and its help.
py::list options(const std::string& program) {
  const OptionTable table(program);
  py::list out;
  for (const CLI::Option* opt : table.cli.get_options()) {
    const std::string name = opt->get_single_name();
    if (name == "help" || name.empty()) continue;
    py::dict d;
    d["name"] = name;
    d["flag"] = opt->get_items_expected_max() == 0;  // takes no value
    d["default"] = opt->get_default_str();
    d["help"] = opt->get_description();
    d["group"] = opt->get_group();
    out.append(d);
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_vrut, m) {
  m.doc() = "vrut's C++ core: use the vrut package (vrut.rutting, vrut.specimen)";
  m.attr("version") = VRUT_VERSION_STRING;
  // The library's errors as Python's: bad input is a ValueError with the
  // command line's message; a malformed option too.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const CLI::ParseError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  m.def("rutting", &rutting, py::arg("args"), py::arg("out"), py::arg("progress"), py::arg("print"));
  m.def("specimen", &specimen, py::arg("args"));
  m.def("gradation", &gradation, py::arg("which"), py::arg("sieve_mm"), py::arg("passing"), py::arg("name"));
  m.def("check", &check, py::arg("program"), py::arg("args"));
  m.def("creep", &creep, py::arg("args"), py::arg("out"));
  m.def("options", &options, py::arg("program") = "rutting");
  m.def("backends", &vrut::available_backends);
  m.def("kokkos_threads", [] {
    return Kokkos::is_initialized() ? vrut::concurrency(Kokkos::DefaultHostExecutionSpace()) : 0;
  });
}
