#pragma once
// The specimens of several vrut-rutting runs of one mix, for vrut-pool: each
// run given as its folder, its seeds.csv (an ensemble) or its summary.json (a
// single specimen, --seed). Runs of one mix and one model only: refused are
// runs whose config.ini files (beside their results) differ in a setting of
// the specimen, the model or the test, 2D pooled with 3D, a run made from
// images with any other (each numbers its images from 1), a seed counted
// twice, a run stopped before its end, and fewer than two specimens. A
// setting that one run's config.ini lacks (an option newer than that run)
// is not compared. The model's options that a run resolves (--stone-friction
// -1, --mastic-by-filler model) are compared as the run resolved them.
// Host-only.
#include <vrut/analysis/seeds_csv.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut::app {

// One run's specimens and what it was run with.
struct PooledRun {
  std::string path;    // the file read
  std::string header;  // seeds.csv's first line; empty for a single run
  int dimension = 2;
  bool from_images = false;
  std::map<std::string, std::string> settings;  // config.ini's key=value lines; empty where there is none
  std::vector<SeedRow> rows;
};

// The settings that may differ between runs of one mix and one model: which
// specimens, where the results go, and how the run was computed (Serial and
// OpenMP agree bit for bit).
inline bool setting_of_the_run_only(const std::string& key) {
  static const std::set<std::string> keys{"seed", "seeds", "out", "force", "threads", "backend", "checkpoint-every"};
  return keys.count(key) > 0;
}

// A config.ini value without the quotes CLI11 puts around text ("model";
// a number given to a text option, 0.35, it writes bare).
inline std::string unquoted(const std::string& value) {
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') return value.substr(1, value.size() - 2);
  return value;
}

// Two config.ini values of one setting agree: the same text, quoted or not,
// or the same number however it was typed (0.35 and .35, 1e4 and 10000).
inline bool same_setting(const std::string& quoted_a, const std::string& quoted_b) {
  const std::string a = unquoted(quoted_a), b = unquoted(quoted_b);
  if (a == b) return true;
  char *end_a = nullptr, *end_b = nullptr;
  const double x = std::strtod(a.c_str(), &end_a), y = std::strtod(b.c_str(), &end_b);
  return !a.empty() && !b.empty() && *end_a == '\0' && *end_b == '\0' && x == y;
}

// config.ini's settings, as vrut-rutting writes it: "key=value" lines and
// comment lines that start with '#'. None where the file is not there.
inline std::map<std::string, std::string> read_config_ini(const std::filesystem::path& file) {
  std::map<std::string, std::string> settings;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == '[') continue;
    const auto eq = line.find('=');
    if (eq != std::string::npos) settings[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return settings;
}

// The stones' friction and the filler's mastic as the run resolved them, in
// place of its config.ini's text: "-1" and "model" mean the model of the
// run's dimension and version (app/rutting_options.hpp,
// resolve_model_options), so the same model typed out or left to the
// defaults pools, and -1 of two versions does not. summary.json records
// them (mastic_by_filler since c53d8f2, stone_friction since version 0.2);
// before 0.2 a negative stone friction was the mastic's, its --friction,
// in 2D and 3D alike, and before --mastic-by-filler every mix had one
// mastic (none). A run with no config.ini compares nothing.
inline void resolve_model_settings(std::map<std::string, std::string>& settings, const nlohmann::json* summary) {
  if (settings.empty()) return;
  if (summary != nullptr && summary->contains("stone_friction")) {
    settings["stone-friction"] = summary->at("stone_friction").dump();  // the shortest text that reads back (0.6)
  } else {
    const auto stone = settings.find("stone-friction"), mastic = settings.find("friction");
    if (stone != settings.end() && mastic != settings.end() && std::strtod(stone->second.c_str(), nullptr) < 0.0)
      stone->second = mastic->second;
  }
  if (summary != nullptr && summary->contains("mastic_by_filler"))
    settings["mastic-by-filler"] = summary->at("mastic_by_filler").get<std::string>();  // as typed, compared as a number
  else if (settings.count("mastic-by-filler") == 0)
    settings["mastic-by-filler"] = "none";
  // The time step's safety: -1 is the dimension's (0.3 in 2D, 0.5 in 3D),
  // which summary.json records as resolved; an older summary has the
  // option's earlier default, 0.3 in both, written out as such.
  if (summary != nullptr && summary->contains("timestep_safety"))
    settings["timestep-safety"] = summary->at("timestep_safety").dump();
  // The settling's steps: -1 is as long as 4,000 steps at 0.3, which
  // summary.json records as resolved.
  if (summary != nullptr && summary->contains("settle_steps"))
    settings["settle-steps"] = summary->at("settle_steps").dump();
}

// A single run's summary.json as a seeds.csv row: its one specimen.
inline SeedRow single_run_row(const nlohmann::json& j, const std::string& path) {
  if (j.contains("ensemble"))
    throw std::runtime_error(path + " is an ensemble's summary: give its seeds.csv (or its folder)");
  if (!j.contains("rut_depth_mm") || !j.contains("seed"))
    throw std::runtime_error(path + " has no rut_depth_mm or seed: is it a vrut-rutting summary.json?");
  SeedRow row;
  row.seed = j.at("seed").get<std::uint64_t>();
  // A run stopped before its end wrote no DS (null where it is not a number).
  row.stopped = j.value("interrupted", false) || !j.contains("dynamic_stability_standard");
  if (row.stopped) return row;
  row.rut_depth_mm = j.at("rut_depth_mm").get<double>();
  row.deformation_45min_mm = j.at("deformation_45min_mm").get<double>();
  row.deformation_60min_mm = j.at("deformation_60min_mm").get<double>();
  // JSON has no infinity: a DS whose window did not deform is written null.
  const nlohmann::json& ds = j.at("dynamic_stability_passes_per_mm");
  row.dynamic_stability = ds.is_null() ? std::numeric_limits<double>::infinity() : ds.get<double>();
  row.dynamic_stability_is_lower_bound = j.at("dynamic_stability_is_lower_bound").get<bool>();
  row.standard.value = j.at("dynamic_stability_standard").at("passes_per_mm").get<double>();
  row.standard.censored = j.at("dynamic_stability_standard").at("censored").get<bool>();
  return row;
}

// One run: a folder (its seeds.csv where it has one, else its summary.json),
// a seeds.csv, or a single run's summary.json.
inline PooledRun read_pooled_run(const std::string& given) {
  namespace fs = std::filesystem;
  fs::path file = given;
  if (!fs::exists(file)) {
    // vrut-rutting writes its folder whole when the run ends, staged until then beside it (io/output_dir.hpp).
    const fs::path named = file.filename().empty() ? file.parent_path() : file;  // "run/" as "run"
    const fs::path staged = fs::absolute(named).parent_path() / ("." + named.filename().string() + ".partial");
    if (!named.filename().empty() && fs::is_directory(staged))
      throw std::runtime_error(given + " does not exist yet: its run is still going, or was killed (" +
                               staged.filename().string() + " holds it until the run ends)");
    throw std::runtime_error(given + ": no such file or folder");
  }
  if (fs::is_directory(file)) {
    if (fs::exists(file / "seeds.csv"))
      file /= "seeds.csv";
    else if (fs::exists(file / "summary.json"))
      file /= "summary.json";
    else
      throw std::runtime_error(given + " has no seeds.csv or summary.json: is its run still going, or did it fail?");
  }
  PooledRun run;
  run.path = file.string();
  run.settings = read_config_ini(file.parent_path() / "config.ini");
  // The run's summary.json: the file given, or the one beside its seeds.csv.
  const fs::path summary_file = file.extension() == ".json" ? file : file.parent_path() / "summary.json";
  nlohmann::json j;
  const bool has_summary = fs::exists(summary_file);
  if (has_summary) {
    std::ifstream in(summary_file);
    if (!in) throw std::runtime_error("cannot read " + summary_file.string());
    try {
      in >> j;
    } catch (const nlohmann::json::exception&) {
      throw std::runtime_error(summary_file.string() + " is not JSON");
    }
  }
  resolve_model_settings(run.settings, has_summary ? &j : nullptr);
  if (file.extension() == ".json") {
    try {
      run.rows.push_back(single_run_row(j, run.path));
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(run.path + ": " + e.what());
    }
    run.dimension = j.value("dimension", 2);
    run.from_images = j.contains("images");
  } else {
    const SeedsTable table = read_seeds_csv(run.path);
    run.header = table.header;
    run.rows = table.rows;
    run.dimension = table.header.find(",spheres,") != std::string::npos ? 3 : 2;
    run.from_images = table.header.size() >= 6 && table.header.compare(table.header.size() - 6, 6, ",image") == 0;
  }
  const auto image = run.settings.find("image");
  if (image != run.settings.end() && image->second != "\"\"" && !image->second.empty()) run.from_images = true;
  refuse_stopped(run.rows, run.path);
  return run;
}

// The specimens of all the runs, in the order given; throws
// std::runtime_error saying what keeps them apart.
inline std::vector<SeedRow> pool_runs(const std::vector<std::string>& given) {
  std::vector<PooledRun> runs;
  for (const auto& g : given) runs.push_back(read_pooled_run(g));
  for (const auto& run : runs)
    if (run.from_images && runs.size() > 1)
      throw std::runtime_error(run.path + " was run from images, which cannot be pooled with other runs (each run "
                               "numbers its images from 1): run the images as one ensemble, --image a --image b ...");
  std::vector<SeedRow> rows;
  std::map<std::uint64_t, std::string> file_of_seed;
  for (const auto& run : runs) {
    for (const auto& other : runs) {
      if (&other == &run) break;  // each pair once, against the runs before
      if (!run.header.empty() && !other.header.empty() && run.header != other.header)
        throw std::runtime_error(run.path + ": its columns differ from those of " + other.path);
      if (run.dimension != other.dimension)
        throw std::runtime_error(run.path + " is a " + std::to_string(run.dimension) + "D run and " + other.path +
                                 " a " + std::to_string(other.dimension) + "D one");
      std::string differences;
      for (const auto& [key, value] : run.settings) {
        const auto there = other.settings.find(key);
        if (there != other.settings.end() && !same_setting(there->second, value) && !setting_of_the_run_only(key))
          differences += (differences.empty() ? "" : ", ") + key + "=" + value + " against " + key + "=" + there->second;
      }
      if (!differences.empty())
        throw std::runtime_error(run.path + " and " + other.path +
                                 " were run with other settings (their config.ini; the stones' friction, the filler "
                                 "and the time step's safety as each run resolved them): " +
                                 differences + ": pool one mix's runs of one model");
    }
    for (const auto& row : run.rows) {
      const auto [at, fresh] = file_of_seed.emplace(row.seed, run.path);
      if (!fresh)
        throw std::runtime_error("seed " + std::to_string(row.seed) + " is in " + at->second + " and in " + run.path);
      rows.push_back(row);
    }
  }
  if (rows.size() < 2) throw std::runtime_error("need at least 2 specimens, got " + std::to_string(rows.size()));
  return rows;
}

}  // namespace vrut::app
