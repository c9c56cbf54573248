// vrut-rutting: the virtual wheel-tracking test of an asphalt mixture, from
// its gradation and binder properties to the rut depth and dynamic stability.
#include "common/cli.hpp"
#include "common/draw.hpp"
#include "common/image_cli.hpp"
#include "common/ranks.hpp"
#include "common/seeds.hpp"
#include "common/specimen_cli.hpp"

#include <vrut/analysis/rutting_ensemble.hpp>
#include <vrut/analysis/standard_ds.hpp>
#include <vrut/backend.hpp>
#include <vrut/io/checkpoint.hpp>
#include <vrut/io/memory_check.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/io/plot.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/io/vtk.hpp>
#include <vrut/protocol/rutting.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <iostream>

namespace {

// Ctrl-C (SIGINT) or SIGTERM: the run stops at its next sample and writes
// what it has.
volatile std::sig_atomic_t stop_signal = 0;
extern "C" void on_stop_signal(int signal) { stop_signal = signal; }

// The deformed specimen at one moment: disks where they are, stones and
// mastic in their colours, the plate in red.
void snapshot_panel(draw::Canvas& c, const vrut::Specimen& sp, const vrut::RuttingSnapshot& s, double y_offset_mm,
                    const vrut::RuttingResult& res, double plate_y_mm) {
  const double r = sp.disks.radius;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const int a = sp.disks.aggregate[i];
    c.disk(s.x[i] * 1e3, s.y[i] * 1e3 + y_offset_mm, r, a >= 0 ? draw::stone(a) : draw::Rgb{0.22, 0.22, 0.22});
  }
  c.rectangle(res.plate_x0 * 1e3, plate_y_mm + y_offset_mm, (res.plate_x1 - res.plate_x0) * 1e3, 1.5,
              {0.8, 0.1, 0.1});
}

// rut_forming.png: the specimen at 20, 40 and 60 min.
void rut_forming_png(const vrut::Specimen& sp, const vrut::RuttingResult& res, double test_minutes,
                     const std::string& path) {
  const double W = sp.width, H = sp.height;
  const double panel = H + 12.0;  // a strip for the label above each panel
  draw::Canvas c(W, 3 * panel, 5.0);
  const double plate_top = res.plate_y_final * 1e3;
  const double final_mm = res.samples.back().deformation * 1e3;
  for (std::size_t k = 0; k < res.snapshots.size(); ++k) {
    const double offset = (2 - static_cast<double>(k)) * panel;
    const auto& s = res.snapshots[k];
    // Plate height at this moment: from the deformation curve.
    const double when = s.fraction * test_minutes;
    double def = final_mm;
    for (const auto& smp : res.samples)
      if (smp.minutes >= when) { def = smp.deformation * 1e3; break; }
    snapshot_panel(c, sp, s, offset, res, plate_top + final_mm - def);
    char label[128];
    std::snprintf(label, sizeof label, "%.0f min: rut %.2f mm", when, def);
    c.text(2.0, offset + H + 5.0, label, 16.0);
  }
  c.save(path);
}

// displacement.png: the displacement field at the end, colour and arrows.
void displacement_png(const vrut::Specimen& sp, const vrut::RuttingResult& res, const std::string& path) {
  const double W = sp.width, H = sp.height;
  const auto& end = res.snapshots.back();
  draw::Canvas c(W, H + 12.0, 6.0);
  double dmax = 1e-12;
  for (std::size_t i = 0; i < end.x.size(); ++i) dmax = std::max(dmax, std::hypot(end.dx[i], end.dy[i]));
  for (std::size_t i = 0; i < end.x.size(); ++i)
    c.disk(end.x[i] * 1e3, end.y[i] * 1e3, sp.disks.radius, draw::heat(std::hypot(end.dx[i], end.dy[i]) / dmax));
  // Vectors on a coarse grid, scaled so the largest is 8 mm long.
  const double every = std::max(1.0, std::floor(end.x.size() / 600.0));
  for (std::size_t i = 0; i < end.x.size(); i += static_cast<std::size_t>(every))
    c.arrow(end.x[i] * 1e3, end.y[i] * 1e3, end.dx[i] / dmax * 8.0, end.dy[i] / dmax * 8.0, {0, 0, 0}, 1.0);
  char label[160];
  std::snprintf(label, sizeof label, "|u| at the end: 0 (blue) to %.2f mm (red); longest arrow 8 mm", dmax * 1e3);
  c.text(2.0, H + 6.0, label, 14.0);
  c.save(path);
}

// final.vtk: final positions, displacement, velocity, group.
void final_vtk(const vrut::Specimen& sp, const vrut::RuttingResult& res, const std::string& path) {
  const auto& end = res.snapshots.back();
  std::vector<double> group(res.group.begin(), res.group.end()), radius(end.x.size(), sp.disks.radius * 1e-3);
  std::vector<std::pair<double, double>> disp, vel;
  for (std::size_t i = 0; i < end.x.size(); ++i) {
    disp.emplace_back(end.dx[i], end.dy[i]);
    vel.emplace_back(res.vx[i], res.vy[i]);
  }
  vrut::VtkPointData data;
  data.scalars = {{"radius", radius}, {"group", group}};
  data.vectors = {{"displacement", disp}, {"velocity", vel}};
  vrut::write_vtk_disks(path, "vrut rutting final state (m); group 0 mastic, 1 aggregate", end.x, end.y, data);
}

// A DS as the standard reports it (analysis/standard_ds.hpp): the value, and
// whether it is only a lower bound ("> 6000", or our "above N").
nlohmann::json standard_ds_json(const vrut::ReportedDS& d) {
  return {{"passes_per_mm", d.value}, {"censored", d.censored}};
}

nlohmann::json statistics_json(const vrut::SampleStatistics& s) {
  nlohmann::json j;
  j["n"] = s.n;
  j["mean"] = s.mean;
  j["sd"] = s.sd;
  j["ci"] = {s.ci_low, s.ci_high};
  j["confidence"] = s.confidence;
  j["median"] = s.median;
  j["min"] = s.min;
  j["max"] = s.max;
  return j;
}

// Every option of a run: parsed from the command line, or on --resume from
// the arguments the checkpoint stored.
struct RunOptions {
  specimen_cli::SpecimenOptions so;
  image_cli::ImageOptions io;
  bool width_given = false, voids_given = false, seed_given = false;  // for --image: what was typed
  vrut::WheelTracking wt;
  vrut::RuttingMaterials mat;
  vrut::RuttingNumerics num;
  std::string backend = "openmp", out = "out/rutting", conversion = "seed", stone_film = "per-contact", seeds_text;
  int threads = 0;
  bool force = false, exact_stones = false;
  double checkpoint_every = 0.0;
  double e1 = 0, eta1 = 0, e2 = 0, eta2 = 0, pressure_mpa = 0, wheel_width_mm = 0, travel_mm = 0, aggregate_gpa = 0;

  RunOptions() {
    so.disk_radius_mm = 1.0;  // the rutting default: a full test in minutes on 2 cores (docs/rutting.md)
    e1 = mat.mastic.E1 * 1e-6, eta1 = mat.mastic.eta1 * 1e-6, e2 = mat.mastic.E2 * 1e-6, eta2 = mat.mastic.eta2 * 1e-6;
    pressure_mpa = wt.pressure * 1e-6, wheel_width_mm = wt.wheel_width * 1e3, travel_mm = wt.travel * 1e3;
    aggregate_gpa = mat.aggregate_modulus * 1e-9;
  }
  // The model in SI units, from the options as typed.
  void convert() {
    mat.mastic = {e1 * 1e6, eta1 * 1e6, e2 * 1e6, eta2 * 1e6};
    mat.calibrated_conversion = conversion == "calibrated";
    mat.stone_film = stone_film == "none" ? vrut::StoneFilm::none
                     : stone_film == "mean" ? vrut::StoneFilm::mean
                                            : vrut::StoneFilm::per_contact;
    mat.aggregate_modulus = aggregate_gpa * 1e9;
    mat.rigid_stones = !exact_stones;
    wt.pressure = pressure_mpa * 1e6;
    wt.wheel_width = wheel_width_mm * 1e-3;
    wt.travel = travel_mm * 1e-3;
  }
};

// Options that a resumed run may change: where and how fast it runs, not what.
const std::vector<std::string> resumable_options = {"--backend", "--threads", "--checkpoint-every"};

void add_run_options(CLI::App& app, RunOptions& o) {
  using namespace specimen_cli;
  auto& mat = o.mat;
  auto& wt = o.wt;
  auto& num = o.num;
  app.set_config("--config", "", "read options from this file (INI/TOML, as written to DIR/config.ini)");
  app.allow_config_extras(false);  // an unknown key in a config file is an error
  add_specimen_options(app, o.so);
  image_cli::add_image_options(app, o.io, true);
  app.add_option("--seeds", o.seeds_text,
                 "an ensemble: specimens of these seeds, run side by side, e.g. 1-16 or 1,4,9 (instead of --seed)");
  app.add_option("--E1", o.e1, "mastic Maxwell modulus at 60 C, MPa")->check(cli::finite_positive())->capture_default_str()->group("Materials");
  app.add_option("--eta1", o.eta1, "mastic Maxwell viscosity, MPa s")->check(cli::finite_positive())->capture_default_str()->group("Materials");
  app.add_option("--E2", o.e2, "mastic Kelvin modulus, MPa")->check(cli::finite_positive())->capture_default_str()->group("Materials");
  app.add_option("--eta2", o.eta2, "mastic Kelvin viscosity, MPa s")->check(cli::finite_positive())->capture_default_str()->group("Materials");
  app.add_option("--mastic-nu", mat.mastic_nu, "Poisson's ratio of the mastic")->check(cli::finite_range(0.0, 0.5, true))
      ->capture_default_str()->group("Materials");
  app.add_option("--conversion", o.conversion, "micro parameters: seed (method.md rules) or calibrated (docs/burgers.md)")
      ->check(CLI::IsMember({"seed", "calibrated"}))->capture_default_str()->group("Materials");
  app.add_option("--mastic-aggregate-factor", mat.mastic_aggregate_factor,
                 "mastic-aggregate contacts get this times the mastic-mastic values")
      ->check(cli::finite_positive())->capture_default_str()->group("Materials");
  app.add_option("--aggregate-modulus-gpa", o.aggregate_gpa, "aggregate Young's modulus (the stone springs 2 t E of --exact-stones)")->check(cli::finite_positive())
      ->capture_default_str()->group("Materials");
  app.add_option("--aggregate-nu", mat.aggregate_nu, "aggregate Poisson's ratio")->check(cli::finite_range(0.0, 0.5, true))
      ->capture_default_str()->group("Materials");
  app.add_option("--mastic-density", mat.mastic_density, "kg/m^3")->check(cli::finite_positive())->capture_default_str()
      ->group("Materials");
  app.add_option("--aggregate-density", mat.aggregate_density, "kg/m^3")->check(cli::finite_positive())
      ->capture_default_str()->group("Materials");
  app.add_option("--friction", mat.friction, "disk-disk friction where no bond holds")->check(cli::finite_range(0.0, 10.0))
      ->capture_default_str()->group("Materials");
  app.add_option("--stone-friction", mat.stone_friction,
                 "aggregate-aggregate friction where no bond holds (-1: the same as --friction)")
      ->check(cli::finite_range(-1.0, 10.0))->capture_default_str()->group("Materials");
  app.add_option("--stone-film", o.stone_film,
                 "how two stones meet: per-contact (each pair through its own mastic film, sized from where its disks "
                 "lie inside the stones' outlines, then the stone law once it squeezes out), mean (one film of "
                 "--film-gap for every pair), none (method.md's stone law alone, the model before 2026-12-02)")
      ->check(CLI::IsMember({"per-contact", "mean", "none"}))->capture_default_str()->group("Materials");
  app.add_option("--film-gap", mat.film_gap,
                 "--stone-film mean: the film's thickness, in disk diameters (0.40: the mean gap between two stones' "
                 "outlines in 2# where their disks are neighbours)")
      ->check(cli::finite_range(0.01, 0.99))->capture_default_str()->group("Materials");
  app.add_flag("--film-endless", mat.film_endless,
               "--stone-film mean: the film never squeezes out, the stones never bear (refused with the others)")
      ->group("Materials");  // no CLI excludes: config.ini holds every option, and reads back
  app.add_flag("--exact-stones", o.exact_stones,
               "the method's stones: bonded disks on the stone's 2 t E springs, walls as stiff, and the time step "
               "from them (the default: rigid stones on --stone-contact-ratio times the mastic's spring, damped)")
      ->group("Numerics");
  app.add_option("--stone-contact-ratio", mat.stone_contact_ratio,
                 "rigid stones: the stone-stone and wall spring over the mastic's E1 t")
      ->check(cli::finite_positive())->capture_default_str()->group("Numerics");
  app.add_option("--stone-damping", mat.stone_damping,
                 "rigid stones: the stone-stone and wall dashpot, a fraction of critical damping")
      ->check(cli::finite_range(0.0, 0.99))->capture_default_str()->group("Numerics");
  app.add_option("--wall-friction", mat.wall_friction, "mould and plate friction")->check(cli::finite_range(0.0, 10.0))
      ->capture_default_str()->group("Materials");
  app.add_option("--pressure-mpa", o.pressure_mpa, "wheel contact pressure p")->check(cli::finite_positive())
      ->capture_default_str()->group("Loading");
  app.add_option("--wheel-mass-kg", wt.wheel_mass, "wheel mass m")->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--wheel-width-mm", o.wheel_width_mm, "wheel width d (= disk thickness t)")
      ->check(cli::finite_positive())->capture_default_str()
      ->group("Loading");
  app.add_option("--travel-mm", o.travel_mm, "wheel travel")->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--passes-per-minute", wt.passes_per_minute, "N")->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--minutes", wt.minutes, "test duration (more than the DS window's start, 45)")
      ->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--shift", num.shift, "time-temperature shift factor alpha_T")->capture_default_str()->group("Numerics");
  app.add_option("--timestep-safety", num.timestep_safety, "fraction of the critical time step")
      ->check(cli::finite_range(1e-3, 1.0))->capture_default_str()->group("Numerics");
  app.add_option("--damping", num.damping, "local damping while loading")->check(cli::finite_range(0.0, 0.99))
      ->capture_default_str()->group("Numerics");
  app.add_option("--settle-steps", num.settle_steps, "steps of settling under gravity")
      ->check(CLI::Range(0L, 100000000L))->capture_default_str()->group("Numerics");
  app.add_option("--samples", num.samples, "points of the deformation curve")->check(CLI::Range(10, 100000))
      ->capture_default_str()->group("Numerics");
  app.add_option("--backend", o.backend, "Kokkos backend")->check(CLI::IsMember(vrut::available_backends()))
      ->capture_default_str()->group("Numerics");
  app.add_option("--threads", o.threads, "host threads (0: OMP_NUM_THREADS)")->check(CLI::Range(0, 1024))
      ->capture_default_str()->group("Numerics");
  app.add_option("--checkpoint-every", o.checkpoint_every,
                 "write DIR/checkpoint.vrut every this many seconds (0: only on Ctrl-C); resume with --resume DIR")
      ->check(cli::finite_range(0.0, 1e9))->capture_default_str()->group("Runs");
  app.add_option("--out", o.out, "output folder")->capture_default_str()->group("Runs");
  app.add_flag("--force", o.force, "overwrite an existing output folder")->group("Runs");
}

// The checkpoint's options, parsed as they were, with the resumable ones
// taken from this command line. A run whose --config file has changed since
// is refused: it would not be the same run.
RunOptions options_to_resume(const CLI::App& command_line, const RunOptions& given, const vrut::CheckpointFile& file) {
  for (const CLI::Option* opt : command_line.get_options())
    if (opt->count() > 0 && opt->get_name() != "--resume" &&
        std::find(resumable_options.begin(), resumable_options.end(), opt->get_name()) == resumable_options.end())
      throw std::invalid_argument("--resume takes every option from the checkpoint; only --backend, --threads and "
                                  "--checkpoint-every may be given with it, not " + opt->get_name());
  RunOptions o;
  CLI::App stored;
  add_run_options(stored, o);
  auto args = file.header().at("argv").get<std::vector<std::string>>();
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  try {
    stored.parse(args);
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument("the options stored in " + file.path().string() + " no longer parse: " + e.what());
  }
  if (stored.config_to_str(true, false) != file.header().at("config").get<std::string>())
    throw std::invalid_argument("the options of " + file.path().string() +
                                " read differently now (has its --config file changed?): it cannot be resumed");
  for (const std::string& name : resumable_options)
    if (command_line.count(name) > 0) {
      if (name == "--backend") o.backend = given.backend;
      if (name == "--threads") o.threads = given.threads;
      if (name == "--checkpoint-every") o.checkpoint_every = given.checkpoint_every;
    }
  o.io.images = image_cli::given_images(o.io);
  o.width_given = stored.count("--width-mm") > 0;
  o.voids_given = stored.count("--air-voids") > 0;
  o.seed_given = stored.count("--seed") > 0;
  o.force = true;  // the folder is this run's own
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  ranks::Session session(argc, argv);  // mpirun -np K: K ranks share the seeds of an ensemble
  RunOptions given;
  std::string resume;
  CLI::App app("vrut-rutting: virtual wheel-tracking (rutting) test of an asphalt mixture, DEM with Burger's mastic");
  add_run_options(app, given);
  app.add_option("--resume", resume, "go on with the run whose checkpoint is in this folder, with its options")
      ->group("Runs")->configurable(false);
  if (const int code = cli::parse(app, argc, argv); code >= 0) return code;
  given.io.images = image_cli::given_images(given.io);
  given.width_given = app.count("--width-mm") > 0;
  given.voids_given = app.count("--air-voids") > 0;
  given.seed_given = app.count("--seed") > 0;

  const int code = cli::guarded([&] {
    namespace fs = std::filesystem;
    std::optional<vrut::CheckpointFile> checkpoint;
    RunOptions o = given;
    std::string config_text = app.config_to_str(true, true);
    // Each rank checkpoints its own specimens, and resumes them with as many ranks.
    const std::string checkpoint_name = ranks::checkpoint_name(session.rank(), session.size());
    if (!resume.empty()) {
      const fs::path file = fs::path(resume) / checkpoint_name;
      if (!fs::exists(file))
        throw std::invalid_argument("no checkpoint in " + resume + " (" + file.string() +
                                    "): a run writes one on Ctrl-C, or every --checkpoint-every seconds" +
                                    (session.size() > 1 ? "; resume with as many ranks as the run had" : ""));
      checkpoint = vrut::CheckpointFile::resume(file, given.checkpoint_every);
      o = options_to_resume(app, given, *checkpoint);
      checkpoint->set_interval(o.checkpoint_every);
      o.out = resume;
      config_text = checkpoint->header().at("config_with_help").get<std::string>();
    } else {
      if (fs::exists(fs::path(given.out) / checkpoint_name) && !given.force)
        throw std::invalid_argument("'" + given.out + "' holds the checkpoint of an unfinished run: go on with it "
                                    "with --resume " + given.out + ", or start again with --force");
      nlohmann::json header;
      header["argv"] = std::vector<std::string>(argv + 1, argv + argc);
      header["config"] = app.config_to_str(true, false);
      header["config_with_help"] = config_text;
      checkpoint.emplace(fs::path(given.out) / checkpoint_name, given.checkpoint_every, header);
    }
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
    vrut::SpecimenSettings ss = to_settings(so);
    // Everything checkable is checked before the specimen is made.
    mat.mastic.validate();
    vrut::validate_poisson(mat.mastic_nu);
    vrut::validate_poisson(mat.aggregate_nu);
    vrut::TimeShift{num.shift};
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
    if (session.root()) output.emplace(out, o.force);
    // An ensemble of images is numbered 1 .. N in the order given, as seeds are.
    std::vector<std::uint64_t> seeds;
    if (from_images)
      for (std::size_t k = 1; k <= images.size(); ++k) seeds.push_back(k);
    else
      seeds = seeds_text.empty() ? std::vector<std::uint64_t>{so.seed} : cli::parse_seed_list(seeds_text);
    const bool ensemble = !seeds_text.empty() || images.size() > 1;
    if (seeds.size() < static_cast<std::size_t>(session.size()))
      throw std::invalid_argument(std::to_string(session.size()) + " MPI ranks for " + std::to_string(seeds.size()) +
                                  " seed(s): give at least one seed per rank (--seeds)");
    if (session.root()) output->write_text("config.ini", config_text);
    const auto [first_seed, last_seed] = ranks::block(seeds.size(), session.rank(), session.size());
    const std::vector<std::uint64_t> my_seeds(seeds.begin() + first_seed, seeds.begin() + last_seed);
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
        std::cerr << "error: seed " << seed << ": " << e.what() << '\n';
        return 1;
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
                   wt.contact_length() * 1e3, wt.loading_time(), wt.loading_time() / num.shift);

    // The results, and two checkpoints (the old one stays until the new one is
    // whole) of about 1.2 kB per disk, must fit on the disk: checked now.
    if (session.root())
      output->require_space(4'000'000 + 200 * sp.disks.centers.size() + 2 * 1'200 * my_disks * session.size());
    vrut::KokkosSession kokkos(o.threads);
    int used_threads = 1;
    vrut::ProgressBar bar(ensemble ? "loading " + std::to_string(seeds.size()) + " specimens" : "loading", 1000,
                          "permille", session.root() ? stderr : nullptr);
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    if (checkpoint->resuming()) std::fprintf(stderr, "resuming from %s\n", checkpoint->path().c_str());
    std::vector<vrut::RuttingResult> runs;
    try {
      runs = vrut::dispatch_backend(backend, [&](auto space) {
        used_threads = vrut::concurrency(space);
        return vrut::run_rutting_ensemble(
            specimens, wt, mat, num, space,
            [&](double fraction, long) { bar.update(static_cast<long>(1000 * fraction)); },
            // Every rank stops at the same sample, so the curves stay the same length.
            [&] { return session.any(stop_signal != 0); }, &*checkpoint);
      });
    } catch (const vrut::SimulationUnstable&) {
      std::fprintf(stderr, "\n--timestep-safety sets the time-step safety (%g here)\n", num.timestep_safety);
      // The checkpoints before the blow-up stay, for a look at the state that led to it.
      if (fs::exists(checkpoint->path()))
        std::fprintf(stderr, "\nthe last checkpoint before it is kept in %s\n", checkpoint->path().c_str());
      throw;
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    const bool interrupted = runs.front().interrupted;
    // Rank 0 gathers every specimen's result, in the seeds' order.
    std::vector<ranks::SpecimenFacts> facts;
    for (const auto& one : specimens)
      facts.push_back({one.placement.aggregates.size(), one.placement.achieved_fraction, session.rank()});
    if (session.size() > 1) {
      nlohmann::json mine = nlohmann::json::array();
      for (std::size_t e = 0; e < runs.size(); ++e) mine.push_back(ranks::to_json(runs[e], facts[e]));
      const auto parts = session.gather(nlohmann::json::to_cbor(mine));
      if (!session.root()) return interrupted ? 128 + static_cast<int>(stop_signal) : 0;
      std::vector<vrut::RuttingResult> all;
      facts.clear();
      for (const auto& part : parts)
        for (const auto& j : nlohmann::json::from_cbor(part)) {
          auto [r, f] = ranks::from_json(j);
          all.push_back(std::move(r));
          facts.push_back(f);
        }
      all.front() = std::move(runs.front());  // with what only rank 0 has: the snapshots and velocities, for the pictures
      runs = std::move(all);
    }
    std::size_t disks = 0;
    double wall_seconds = 0.0;
    for (const auto& r : runs) disks += r.particles, wall_seconds = std::max(wall_seconds, r.wall_seconds);
    if (!interrupted) bar.finish();
    const double minutes_done = runs.front().samples.empty() ? 0.0 : runs.front().samples.back().minutes;
    if (interrupted)
      std::fprintf(stderr, "\n%s at %.1f of %.0f minutes: writing the results so far\n",
                   stop_signal == SIGTERM ? "terminated (SIGTERM)" : "interrupted (Ctrl-C)", minutes_done, wt.minutes);
    const vrut::RuttingResult& res = runs.front();
    const vrut::RuttingEnsembleSummary summary = vrut::summarize_rutting(runs, wt);

    // deformation.csv and .png: one specimen's curve, or the ensemble's mean,
    // interval and every specimen's curve.
    std::ostringstream csv;
    csv.precision(17);  // every double as it is: files compared bit for bit (resume, MPI) must differ where the runs do
    csv << "minutes,reduced_time_s,deformation_mm,plate_pressure_mpa";
    if (ensemble) {
      csv << ",sd_mm,ci95_low_mm,ci95_high_mm";
      for (auto seed : seeds) csv << ",seed_" << seed << "_mm";
    }
    csv << '\n';
    std::vector<double> minutes, deformation, low, high;
    const auto& mean = summary.mean_curve.samples;
    for (std::size_t k = 0; k < mean.size(); ++k) {
      csv << mean[k].minutes << ',' << mean[k].reduced_time << ',' << mean[k].deformation * 1e3 << ','
          << mean[k].plate_pressure * 1e-6;
      if (ensemble) {
        csv << ',' << summary.deformation_sd[k] * 1e3 << ',' << summary.deformation_ci_low[k] * 1e3 << ','
            << summary.deformation_ci_high[k] * 1e3;
        for (const auto& r : runs) csv << ',' << r.samples[k].deformation * 1e3;
      }
      csv << '\n';
      minutes.push_back(mean[k].minutes);
      deformation.push_back(mean[k].deformation * 1e3);
      low.push_back(summary.deformation_ci_low[k] * 1e3);
      high.push_back(summary.deformation_ci_high[k] * 1e3);
    }
    output->write_text("deformation.csv", csv.str());
    // What was run, for the plot and the printout.
    const std::string what_was_run = from_images ? (images.size() > 1 ? "images" : "image " + images.front())
                                                 : "gradation " + ss.gradation.name;
    vrut::PlotSpec spec;
    spec.xlabel = "test time (min)";
    spec.ylabel = "deformation (mm)";
    std::vector<vrut::PlotSeries> series;
    if (ensemble) {
      spec.title = "Virtual wheel-tracking test, " + what_was_run + ", " +
                   std::to_string(runs.size()) + " specimens";
      vrut::PlotSeries band{"95 % interval of the mean", minutes, low, "filledcurves fs transparent solid 0.3 lc rgb '#4477aa'"};
      band.y2 = high;
      series.push_back(band);
      for (std::size_t e = 0; e < runs.size(); ++e) {
        vrut::PlotSeries one{e == 0 ? "each specimen" : "", {}, {}, "lines lw 1 lc rgb '#bbbbbb'"};
        for (const auto& smp : runs[e].samples) {
          one.x.push_back(smp.minutes);
          one.y.push_back(smp.deformation * 1e3);
        }
        series.push_back(one);
      }
      series.push_back({"mean", minutes, deformation, "lines lw 3 lc rgb '#223388'"});
    } else {
      spec.title = "Virtual wheel-tracking test, " + what_was_run;
      series.push_back({"rut depth under the plate", minutes, deformation});
    }
    vrut::write_plot_png(output->file("deformation.png").string(), spec, series);

    // Pictures and VTK of the first specimen.
    draw::specimen_png(sp, output->file("specimen.png").string());
    rut_forming_png(sp, res, wt.minutes, output->file("rut_forming.png").string());
    displacement_png(sp, res, output->file("displacement.png").string());
    final_vtk(sp, res, output->file("final.vtk").string());

    // Each specimen's DS as the standard reports it, and their median with
    // the censored ones counted as censored (Kaplan-Meier).
    std::vector<vrut::ReportedDS> reported;
    for (const auto& r : runs)
      reported.push_back(interrupted ? vrut::ReportedDS{0.0, true}
                                     : vrut::report_ds(r.dynamic_stability, r.dynamic_stability_is_lower_bound));
    const vrut::ReportedDS reported_mean_curve =
        interrupted ? vrut::ReportedDS{0.0, true}
                    : vrut::report_ds(summary.mean_curve.dynamic_stability, summary.mean_curve.dynamic_stability_is_lower_bound);
    const vrut::ReportedDS reported_median = vrut::censored_median(reported);
    // Their 95 % intervals (analysis/standard_ds.hpp): the median's from the
    // order statistics, the mean curve's from the mean window deformation.
    const vrut::MedianInterval median_ci = vrut::median_interval(reported);
    std::vector<double> window_mm;
    for (const auto& r : runs) window_mm.push_back((r.deformation_final - r.deformation_at_ds_start) * 1e3);
    const bool intervals = ensemble && !interrupted && runs.size() >= 2;
    const vrut::DSInterval mean_curve_ci =
        intervals ? vrut::mean_curve_ds_interval(window_mm, wt.ds_window_passes()) : vrut::DSInterval{};
    if (ensemble) {
      std::ostringstream per_seed;
      per_seed.precision(17);
      per_seed << "seed,disks,aggregates,aggregate_area_fraction,rut_depth_mm,deformation_45min_mm,"
                  "deformation_60min_mm,dynamic_stability_passes_per_mm,dynamic_stability_is_lower_bound,"
                  "deformation_resolution_mm,stones,stone_pairs_touching,steps,ds_standard_passes_per_mm,"
                  "ds_standard_censored"
               << (from_images ? ",image\n" : "\n");
      for (std::size_t e = 0; e < runs.size(); ++e) {
        per_seed << seeds[e] << ',' << runs[e].particles << ',' << facts[e].aggregates << ','
                 << facts[e].aggregate_area_fraction << ',' << runs[e].deformation_final * 1e3 << ','
                 << runs[e].deformation_at_ds_start * 1e3 << ',' << runs[e].deformation_final * 1e3 << ','
                 << runs[e].dynamic_stability << ',' << (runs[e].dynamic_stability_is_lower_bound ? 1 : 0) << ','
                 << runs[e].deformation_resolution * 1e3 << ',' << runs[e].stones << ','
                 << runs[e].stone_pairs_touching << ',' << runs[e].steps << ',';
        if (interrupted)
          per_seed << "nan,nan";  // a run stopped before its end has no DS
        else
          per_seed << reported[e].value << ',' << (reported[e].censored ? 1 : 0);
        if (from_images) per_seed << ',' << images[seeds[e] - 1];
        per_seed << '\n';
      }
      output->write_text("seeds.csv", per_seed.str());
    }

    nlohmann::json j;
    j["gradation"] = ss.gradation.name;
    j["seed"] = seeds.front();
    if (from_images) j["images"] = images;  // specimen k (the "seed" k) is image k
    j["disk_radius_mm"] = sp.disks.radius;
    j["shift_factor"] = num.shift;
    j["conversion"] = conversion;
    j["particles"] = disks;
    j["bonds"] = res.bonds;
    j["contacts"] = res.contacts;
    // The skeleton at the end, of the first specimen: stones, the pairs of
    // them touching, and touching neighbours per stone (2 pairs / stones).
    j["stones"] = res.stones;
    j["stone_pairs_touching"] = res.stone_pairs_touching;
    j["stone_neighbours_per_stone"] = res.stones > 0 ? 2.0 * res.stone_pairs_touching / res.stones : 0.0;
    j["rigid_stones"] = mat.rigid_stones;
    j["stone_film"] = stone_film;
    j["mastic_aggregate_factor"] = mat.mastic_aggregate_factor;
    j["steps"] = res.steps;
    j["reduced_dt_s"] = res.dt;
    j["wall_seconds"] = wall_seconds;
    j["mpi_ranks"] = session.size();
    j["backend"] = backend;
    j["threads"] = used_threads;
    j["particle_steps_per_second"] = disks * static_cast<double>(res.steps) / wall_seconds;
    j["contact_length_mm"] = wt.contact_length() * 1e3;
    j["loading_time_s"] = wt.loading_time();
    // For an ensemble: the means over the specimens (the DS: of the mean curve),
    // the first specimen's bonds, contacts and description.
    j["deformation_45min_mm"] = summary.deformation_at_ds_start.mean;
    j["deformation_60min_mm"] = summary.deformation_final.mean;
    j["rut_depth_mm"] = summary.rut_depth.mean;
    j["dynamic_stability_passes_per_mm"] = summary.mean_curve.dynamic_stability;
    // Where the 45-60 min deformation is below what the curve resolves, the DS
    // is a lower bound: "above" the value given.
    j["dynamic_stability_is_lower_bound"] = summary.mean_curve.dynamic_stability_is_lower_bound;
    j["deformation_resolution_mm"] = summary.mean_curve.deformation_resolution * 1e3;
    // As JTG E20 T0719 writes it: capped at 6000 ("> 6000").
    if (!interrupted) j["dynamic_stability_standard"] = standard_ds_json(reported_mean_curve);
    j["specimen"] = specimen_cli::specimen_summary(sp);
    j["interrupted"] = interrupted;
    j["minutes_done"] = minutes_done;
    if (ensemble) {
      nlohmann::json e;
      e["seeds"] = seeds;
      e["specimens"] = runs.size();
      e["rut_depth_mm"] = statistics_json(summary.rut_depth);
      e["deformation_45min_mm"] = statistics_json(summary.deformation_at_ds_start);
      e["deformation_60min_mm"] = statistics_json(summary.deformation_final);
      e["dynamic_stability_passes_per_mm"] = statistics_json(summary.dynamic_stability);
      e["dynamic_stability_of_mean_curve"] = summary.mean_curve.dynamic_stability;
      e["dynamic_stability_lower_bounds"] = summary.dynamic_stability_lower_bounds;
      e["dynamic_stability_median_is_lower_bound"] = summary.dynamic_stability_median_is_lower_bound;
      // The standard's values: the median with capped and unresolved DS
      // as censored (Kaplan-Meier), and the mean curve's DS.
      if (!interrupted) {
        e["dynamic_stability_standard_median"] = standard_ds_json(reported_median);
        e["dynamic_stability_standard_of_mean_curve"] = standard_ds_json(reported_mean_curve);
        if (intervals && median_ci.defined)
          e["dynamic_stability_standard_median_ci95"] = {{"low", standard_ds_json(median_ci.low)},
                                                         {"high", standard_ds_json(median_ci.high)},
                                                         {"coverage", median_ci.coverage}};
        if (intervals)
          e["dynamic_stability_standard_of_mean_curve_ci95"] = {{"low", standard_ds_json(mean_curve_ci.low)},
                                                                {"high", standard_ds_json(mean_curve_ci.high)}};
      }
      nlohmann::json per = nlohmann::json::array();
      for (std::size_t k = 0; k < runs.size(); ++k)
        per.push_back({{"seed", seeds[k]},
                       {"disks", runs[k].particles},
                       {"rut_depth_mm", runs[k].deformation_final * 1e3},
                       {"deformation_45min_mm", runs[k].deformation_at_ds_start * 1e3},
                       {"dynamic_stability_passes_per_mm", runs[k].dynamic_stability},
                       {"dynamic_stability_is_lower_bound", runs[k].dynamic_stability_is_lower_bound},
                       {"dynamic_stability_standard", standard_ds_json(reported[k])},
                       {"rank", facts[k].rank}});  // the MPI rank that ran it
      e["per_seed"] = per;
      j["ensemble"] = e;
    }
    output->write_text("summary.json", j.dump(2) + '\n');
    // The checkpoint of a stopped run goes with its partial results; a run
    // that ended needs none.
    if (interrupted)
      for (int r = 0; r < session.size(); ++r) {
        const std::string name = ranks::checkpoint_name(r, session.size());
        fs::rename(fs::path(out) / name, output->file(name));
      }
    output->commit();
    if (interrupted) {
      const std::string launcher = session.size() > 1 ? "mpirun -np " + std::to_string(session.size()) + " " : "";
      std::printf("partial results (%.1f of %.0f minutes, no dynamic stability) in %s\n"
                  "go on with: %svrut-rutting --resume %s\n",
                  minutes_done, wt.minutes, out.c_str(), launcher.c_str(), out.c_str());
      return 128 + static_cast<int>(stop_signal);
    }
    // A DS that is only a lower bound reads "above N", as a laboratory writes it.
    auto ds_text = [](double ds, bool lower_bound) {
      char text[64];
      std::snprintf(text, sizeof text, "%s%.0f", lower_bound ? "above " : "", ds);
      return std::string(text);
    };
    const auto& standard_text = vrut::reported_ds_text;  // "> 6000" past the cap, ours "above N"
    const std::string speed = [&] {
      char text[128];
      std::snprintf(text, sizeof text, "%zu disks, %ld steps, %.0f s, %.3g particle-steps/s", disks, res.steps,
                    wall_seconds, j["particle_steps_per_second"].get<double>());
      return std::string(text);
    }();
    if (ensemble) {
      const auto& r = summary.rut_depth;
      const auto& d = summary.dynamic_stability;
      const bool any_bound = summary.dynamic_stability_lower_bounds > 0;
      std::printf("%s, %d specimens: rut depth %.2f mm at %.0f min (sd %.2f, 95 %% CI %.2f to %.2f), "
                  "dynamic stability: mean %s (95 %% CI %s), median %s, of the mean curve %s passes/mm",
                  what_was_run.c_str(), r.n, r.mean, wt.minutes, r.sd, r.ci_low, r.ci_high,
                  ds_text(d.mean, any_bound).c_str(),
                  any_bound ? "not known" : (ds_text(d.ci_low, false) + " to " + ds_text(d.ci_high, false)).c_str(),
                  ds_text(d.median, summary.dynamic_stability_median_is_lower_bound).c_str(),
                  ds_text(summary.mean_curve.dynamic_stability, summary.mean_curve.dynamic_stability_is_lower_bound).c_str());
      if (any_bound)
        std::printf("; %d of %d specimens deform less from minute %.0f to %.0f than their curves resolve, so their DS "
                    "are lower bounds (seeds.csv)",
                    summary.dynamic_stability_lower_bounds, r.n, wt.ds_from_minute, wt.minutes);
      auto interval_text = [&](const vrut::ReportedDS& low, const vrut::ReportedDS& high) {
        return " (95 % interval " + standard_text(low) + " to " + standard_text(high) + ")";
      };
      std::printf("; as the standard reports it (capped at %.0f): median %s%s (censored values counted as such), of "
                  "the mean curve %s%s passes/mm",
                  vrut::standard_ds_cap, standard_text(reported_median).c_str(),
                  median_ci.defined ? interval_text(median_ci.low, median_ci.high).c_str() : "",
                  standard_text(reported_mean_curve).c_str(),
                  intervals ? interval_text(mean_curve_ci.low, mean_curve_ci.high).c_str() : "");
      std::printf(" (%s)\nresults in %s\n", speed.c_str(), out.c_str());
    } else {
      std::printf("%s: rut depth %.2f mm at %.0f min, dynamic stability %s passes/mm",
                  what_was_run.c_str(), res.deformation_final * 1e3, wt.minutes,
                  ds_text(res.dynamic_stability, res.dynamic_stability_is_lower_bound).c_str());
      if (res.dynamic_stability_is_lower_bound)
        std::printf(" (from minute %.0f to %.0f the plate sank %.4f mm, less than the %.4f mm its curve resolves)",
                    wt.ds_from_minute, wt.minutes, (res.deformation_final - res.deformation_at_ds_start) * 1e3,
                    res.deformation_resolution * 1e3);
      std::printf(", as the standard reports it %s", standard_text(reported_mean_curve).c_str());
      std::printf(" (%s)\nresults in %s\n", speed.c_str(), out.c_str());
    }
    return 0;
  });
  // A rank that failed takes the others down rather than leave them waiting.
  if (session.size() > 1 && code != 0 && code < 128) session.abort(code);
  return code;
}
