#pragma once
// vrut-rutting's options: every option of a run, the command line that sets
// them, and the options of a run resumed from its checkpoint.
#include "cli.hpp"
#include "image_cli.hpp"
#include "seeds.hpp"
#include "specimen3_cli.hpp"
#include "specimen_cli.hpp"

#include <vrut/backend.hpp>
#include <vrut/io/checkpoint.hpp>
#include <vrut/protocol/rutting.hpp>
#include <vrut/protocol/rutting/model3.hpp>
#include <vrut/specimen/binder_film.hpp>
#include <vrut/specimen/filler_mastic.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut::app {

// The 3D model (vrut-rutting --dim 3), where its options are
// left at their defaults: the stones' friction 0.6, its one constant, fitted
// on 2#'s eight specimens at 1 mm spheres, and each mix's mastic stiffened by
// its filler at Rigden voids 0.35, on no fitted constant (docs/validation.md,
// "The frozen 3D model"). The 3D model before it: --stone-friction
// 1 --mastic-by-filler none. 2D keeps its own: the stones' friction that of
// the mastic (--friction) and one mastic for every mix.
// The constants are the library's vrut::RuttingModel3
// (protocol/rutting/model3.hpp); the filler's as the option's text.
// tests/cli_errors.sh checks that a run at these defaults is the library's
// model, to the bit.
inline constexpr double stone_friction_3d = vrut::RuttingModel3::stone_friction;
inline constexpr const char* mastic_by_filler_3d = "0.35";

// Every option of a run: parsed from the command line, or on --resume from
// the arguments the checkpoint stored.
struct RunOptions {
  specimen_cli::SpecimenOptions so;
  specimen_cli::Specimen3Options o3;
  int dim = 2;
  image_cli::ImageOptions io;
  bool width_given = false, voids_given = false, seed_given = false;  // for --image: what was typed
  vrut::WheelTracking wt;
  vrut::RuttingMaterials mat;
  vrut::RuttingNumerics num;
  std::string backend = "openmp", out = "out/rutting", conversion = "seed", stone_film = "per-contact", seeds_text;
  std::string section = "longitudinal";  // --section (wt.transverse)
  std::string plate = "strip";           // --plate (wt.patch)
  std::string least_film = "none";  // --least-film: none, binder or micrometres (binder_film_option_m)
  std::string stone_shear_film = "none";  // --stone-shear-film: the same words (mat.stone_shear_film)
  std::string mastic_by_filler = "model";  // --mastic-by-filler: model, none or the filler's Rigden voids (mastic_filler_scale)
  double mastic_scale = 1.0;              // the factor --mastic-by-filler gave the mastic (1 with none)
  int threads = 0;
  bool force = false, exact_stones = false;
  double checkpoint_every = 0.0;
  // The mastic-aggregate factor in 3D: 1, the source's own value. At the
  // default 1 mm spheres the rut falls as the factor rises (three specimens
  // of 2# at factor 1 come nearest the laboratory's 12.2 mm), and a factor
  // below 1, a mastic softer against a stone than against itself, has no
  // physical reading, so none is fitted (docs/validation.md, "The factor at
  // 1 mm"). The 2D calibration's 4 held only at 1.5 mm spheres.
  double mastic_aggregate_factor_3d = vrut::RuttingModel3::mastic_aggregate_factor;
  double e1 = 0, eta1 = 0, e2 = 0, eta2 = 0, pressure_mpa = 0, wheel_width_mm = 0, travel_mm = 0, aggregate_gpa = 0;

  RunOptions() {
    so.disk_radius_mm = 1.0;  // the rutting default: a full test in minutes on 2 cores (docs/rutting.md)
    // Divided, not times 1e-6: the quotient is the decimal value itself (83.34,
    // where times 1e-6 gave 83.33999999999999), the one config.ini writes and
    // reads back, so a run's config.ini gives it again bit for bit.
    e1 = mat.mastic.E1 / 1e6, eta1 = mat.mastic.eta1 / 1e6, e2 = mat.mastic.E2 / 1e6, eta2 = mat.mastic.eta2 / 1e6;
    pressure_mpa = wt.pressure * 1e-6, wheel_width_mm = wt.wheel_width * 1e3, travel_mm = wt.travel * 1e3;
    aggregate_gpa = mat.aggregate_modulus * 1e-9;
    num.timestep_safety = -1.0;  // the dimension's (resolve_model_options)
    num.settle_steps = -1;       // as long as the method's 4,000 steps at 0.3 (resolve_model_options)
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
    wt.transverse = section == "transverse";
    wt.patch = plate == "patch";
  }
};

// A number that is the whole of text; NaN when it is not one.
inline double whole_number(const std::string& text) {
  std::size_t used = 0;
  double value = std::nan("");
  try {
    value = std::stod(text, &used);
  } catch (const std::logic_error&) {
    return std::nan("");
  }
  return used == text.size() ? value : std::nan("");
}

// The thickness, m, that a film option gives (--least-film,
// --stone-shear-film; `option` names which in a refusal): none (0), binder
// (two binder films of the mix, one on each stone: specimen/binder_film.hpp),
// or micrometres.
inline double binder_film_option_m(const std::string& option, const std::string& text, const vrut::Gradation& g,
                                   const vrut::MixVolumetrics& mix) {
  if (text == "none") return 0.0;
  if (text == "binder") return 2.0 * vrut::binder_film(g, mix).thickness_um * 1e-6;
  const double um = whole_number(text);
  if (!(um >= 0.0) || !std::isfinite(um))
    throw std::invalid_argument(option + ": '" + text + "' is none, binder or a thickness in micrometres (>= 0)");
  return um * 1e-6;
}

// A --least-film-like option's check: CLI11 names the option itself.
inline std::function<std::string(const std::string&)> binder_film_check(const std::string& option) {
  return [option](const std::string& v) {
    try {
      binder_film_option_m(option, v == "binder" ? "0" : v, vrut::builtin_gradation(2), vrut::MixVolumetrics{});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).substr(option.size() + 2);
    }
    return std::string();
  };
}

// --mastic-by-filler, as the dimension resolved it (resolve_model_options):
// none (every mix on the one mastic), or the Rigden voids of the filler, a
// fraction: the factor on every Burger's constant of this mix's mastic, its
// filler's stiffening over that of 2#, the mix the mastic was calibrated on
// (specimen/filler_mastic.hpp).
inline double mastic_filler_scale(const std::string& text, const vrut::Gradation& g, const vrut::MixVolumetrics& mix) {
  if (text == "none") return 1.0;
  const double voids = whole_number(text);
  if (!(voids > 0.0 && voids < 1.0))
    throw std::invalid_argument("--mastic-by-filler: '" + text +
                                "' is model, none or the filler's Rigden voids, a fraction between 0 and 1");
  return vrut::mastic_scale_by_filler(g, vrut::builtin_gradation(vrut::RuttingModel3::calibration_mix), mix, voids);
}

// The options left at "the model's" (--stone-friction -1, --mastic-by-filler
// model) given the dimension's model: in 3D the fitted friction and the filler
// at 0.35; in 2D one mastic, and a stone friction of -1 left for the library
// to read as the mastic's (vrut::stone_friction_of). And the time step's
// safety left at -1, the dimension's numerics: 0.3 in 2D (the library's
// RuttingNumerics), vrut::timestep_safety_3d in 3D; and the settling's steps
// left at -1, as long in time as the method's 4,000 at 0.3
// (vrut::settle_steps_at_safety). Before anything reads them.
inline void resolve_model_options(RunOptions& o) {
  const bool three = o.dim == 3;
  if (o.num.timestep_safety < 0.0)
    o.num.timestep_safety = three ? vrut::timestep_safety_3d : vrut::RuttingNumerics{}.timestep_safety;
  if (o.num.settle_steps < 0) o.num.settle_steps = vrut::settle_steps_at_safety(o.num.timestep_safety);
  if (three && o.mat.stone_friction < 0.0) o.mat.stone_friction = stone_friction_3d;
  if (o.mastic_by_filler == "model") o.mastic_by_filler = three ? mastic_by_filler_3d : "none";
}

// The mastic scaled by --mastic-by-filler's factor (vrut::scale_mastic).
inline void scale_mastic_by_filler(RunOptions& o, const vrut::Gradation& g, const vrut::MixVolumetrics& mix) {
  o.mastic_scale = mastic_filler_scale(o.mastic_by_filler, g, mix);
  if (o.mastic_by_filler == "none") return;
  if (!o.io.images.empty())
    throw std::invalid_argument("--mastic-by-filler needs the mix's filler content from --gradation: an image does not give it");
  vrut::scale_mastic(o.mat, o.mastic_scale);
}

// Options that a resumed run may change: where and how fast it runs, not what.
inline const std::vector<std::string> resumable_options = {"--backend", "--threads", "--checkpoint-every"};

inline void add_run_options(CLI::App& app, RunOptions& o) {
  using namespace specimen_cli;
  auto& mat = o.mat;
  auto& wt = o.wt;
  auto& num = o.num;
  app.set_config("--config", "", "read options from this file (INI/TOML, as written to DIR/config.ini)");
  app.allow_config_extras(false);  // an unknown key in a config file is an error
  app.add_option("--dim", o.dim, "2 (a section of disks, the method's) or 3 (a box of spheres, periodic along its "
                 "depth, its one constant the stones' friction, fitted on 2#: docs/rutting.md)")
      ->check(CLI::IsMember({2, 3}))->capture_default_str();
  add_specimen_options(app, o.so);
  specimen_cli::add_specimen3_options(app, o.o3);
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
  app.add_option("--mastic-aggregate-factor-3d", o.mastic_aggregate_factor_3d,
                 "3D (--dim 3): the same factor (1: the source's value, no constant fitted in 3D; docs/validation.md, "
                 "\"The factor at 1 mm\")")
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
                 "aggregate-aggregate friction where no bond holds (-1: the model's: in 3D 0.6, its one constant, "
                 "fitted on 2#; in 2D the same as --friction)")
      ->check(cli::finite_range(-1.0, 10.0))->capture_default_str()->group("Materials");
  app.add_option("--stone-film", o.stone_film,
                 "how two stones meet: per-contact (each pair through its own mastic film, sized from where its disks "
                 "lie inside the stones' outlines, then the stone law once it squeezes out), mean (one film of "
                 "--film-gap for every pair), none (method.md's stone law alone, the older 2D model's)")
      ->check(CLI::IsMember({"per-contact", "mean", "none"}))->capture_default_str()->group("Materials");
  app.add_option("--film-gap", mat.film_gap,
                 "--stone-film mean: the film's thickness, in disk diameters (0.40: the mean gap between two stones' "
                 "outlines in 2# where their disks are neighbours)")
      ->check(cli::finite_range(0.01, 0.99))->capture_default_str()->group("Materials");
  app.add_option("--least-film", o.least_film,
                 "a candidate, not the model: the thinnest film two stones meet through, so their spring bears only "
                 "past it: none, binder (two binder films of the mix from its gradation and volumetrics, "
                 "docs/validation.md) or micrometres; with --stone-film per-contact")
      ->check(binder_film_check("--least-film"))
      ->capture_default_str()->group("Materials");
  app.add_option("--stone-shear-film", o.stone_shear_film,
                 "an experiment, not the model: touching stones' shear relaxes through the binder film between "
                 "them (their shear spring in series with the film's dashpot, the mastic's viscosity over the "
                 "film): none, binder (two binder films of the mix from its gradation and volumetrics, "
                 "docs/validation.md) or micrometres; with --stone-film per-contact")
      ->check(binder_film_check("--stone-shear-film"))
      ->capture_default_str()->group("Experiments (not the model)");
  app.add_option("--mastic-by-filler", o.mastic_by_filler,
                 "each mix's mastic stiffened by its filler (passing 0.075 mm, from --gradation; below its smallest "
                 "sieve the 0.45-power line) over 2#'s, by Krieger-Dougherty: model (3D: 0.35; 2D: none), none, or "
                 "the filler's Rigden voids as a fraction (EN 13043 allows 0.28 to 0.45; docs/validation.md)")
      ->check([](const std::string& v) {
        if (v == "model") return std::string();
        try {
          mastic_filler_scale(v, vrut::builtin_gradation(2), vrut::MixVolumetrics{});
        } catch (const std::invalid_argument& e) {
          const std::string what = e.what(), prefix = "--mastic-by-filler: ";
          return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;  // CLI11 names the option
        }
        return std::string();
      })
      ->capture_default_str()->group("Materials");
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
  app.add_option("--section", o.section,
                 "the section along the wheel's travel (the method's; the plate is the contact length) or across "
                 "it (transverse: the plate is the wheel's width; in 3D a strip across the travel, the periodic depth "
                 "along it, so the mix flows out sideways; an experiment of docs/validation.md, not the model)")
      ->check(CLI::IsMember({"longitudinal", "transverse"}))->capture_default_str()->group("Loading");
  app.add_option("--plate", o.plate,
                 "3D: the plate a strip across the periodic depth (the model's) or the tyre's patch, the contact "
                 "length by the wheel's width at mid-depth, in a box at least twice the wheel's width deep (give "
                 "--depth-mm; an experiment of docs/validation.md, round four, not the model)")
      ->check(CLI::IsMember({"strip", "patch"}))->capture_default_str()->group("Loading");
  app.add_option("--travel-mm", o.travel_mm, "wheel travel")->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--passes-per-minute", wt.passes_per_minute, "N")->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--minutes", wt.minutes, "test duration (more than the DS window's start, 45)")
      ->check(cli::finite_positive())->capture_default_str()->group("Loading");
  app.add_option("--shift", num.shift, "time-temperature shift factor alpha_T")->capture_default_str()->group("Numerics");
  app.add_option("--timestep-safety", num.timestep_safety,
                 "fraction of sqrt(m / k), the stiffest spring on the lightest mass it meets (-1: the dimension's: " +
                     CLI::detail::to_string(vrut::RuttingNumerics{}.timestep_safety) + " in 2D, " +
                     CLI::detail::to_string(vrut::timestep_safety_3d) + " in 3D)")
      ->check(cli::finite_range_or(-1.0, 1e-3, 2.0))->capture_default_str()->group("Numerics");
  app.add_option("--damping", num.damping, "local damping while loading")->check(cli::finite_range(0.0, 0.99))
      ->capture_default_str()->group("Numerics");
  app.add_option("--settle-steps", num.settle_steps,
                 "steps of settling under gravity (-1: as long as 4,000 steps at the safety 0.3: 4,000 in 2D, "
                 "fewer at a larger step)")
      ->check(CLI::Range(-1L, 100000000L))->capture_default_str()->group("Numerics");
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
inline RunOptions options_to_resume(const CLI::App& command_line, const RunOptions& given, const vrut::CheckpointFile& file) {
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

}  // namespace vrut::app
