// How many specimens a mix needs before its DS median is known within a
// given share: each ensemble's seeds.csv (vrut-rutting --seeds), its DS as
// the standard reports them (capped at 6000, lower bounds censored), the
// Kaplan-Meier median, and for n specimens the half-width of the central 95 %
// of the medians of n specimens drawn with replacement from the ensemble,
// over its median (analysis/standard_ds.hpp; smoothed draws). Beyond the
// ensemble's own size the draws take its specimens, smoothed, as the whole
// population: a projection.
//
//   vrut-ds-resample [--within 0.15] out/mix1/seeds.csv out/mix2/seeds.csv ...
#include <vrut/analysis/standard_ds.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}

// The DS of each specimen in a seeds.csv, as the standard reports it.
std::vector<vrut::ReportedDS> read_seeds_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + " is empty");
  const auto header = split(line);
  int ds = -1, bound = -1;
  for (int i = 0; i < static_cast<int>(header.size()); ++i) {
    if (header[i] == "dynamic_stability_passes_per_mm") ds = i;
    if (header[i] == "dynamic_stability_is_lower_bound") bound = i;
  }
  if (ds < 0 || bound < 0) throw std::runtime_error(path + " has no DS columns: is it a vrut-rutting seeds.csv?");
  std::vector<vrut::ReportedDS> out;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = split(line);
    if (static_cast<int>(cells.size()) <= std::max(ds, bound)) throw std::runtime_error(path + ": a short line: " + line);
    out.push_back(vrut::report_ds(std::stod(cells[ds]), cells[bound] == "1"));
  }
  if (out.empty()) throw std::runtime_error(path + " lists no specimen");
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"How many specimens a mix needs before its DS median is known within a share, by resampling"};
  std::vector<std::string> files;
  double within = 0.15;
  int draws = 4000;
  app.add_option("seeds_csv", files, "seeds.csv of each ensemble")->required()->check(CLI::ExistingFile);
  app.add_option("--within", within, "the share of the median asked for")->check(CLI::Range(0.001, 1.0));
  app.add_option("--draws", draws, "resampled medians per specimen count")->check(CLI::Range(100, 1000000));
  CLI11_PARSE(app, argc, argv);
  try {
    const std::vector<int> counts = {3, 5, 8, 10, 16, 20, 30, 40, 60, 80, 120, 160, 240, 320};
    for (const auto& f : files) {
      const auto ds = read_seeds_csv(f);
      const auto median = vrut::censored_median(ds);
      int censored = 0;
      for (const auto& d : ds) censored += d.censored;
      std::printf("%s: %zu specimens (%d censored), DS median %s%.0f passes/mm\n", f.c_str(), ds.size(), censored,
                  median.censored ? "above " : "", median.value);
      std::printf("  specimens  half-width of the median's 95 %% range, share of the median\n");
      int enough = -1;
      for (int n : counts) {
        const double h = vrut::median_relative_halfwidth(ds, n, draws);
        std::printf("  %9d  %.3f%s\n", n, h, n > static_cast<int>(ds.size()) ? "  (projection)" : "");
        if (enough < 0 && h <= within) enough = n;
      }
      if (enough > 0)
        std::printf("  within %.0f %% from %d specimens\n", 100 * within, enough);
      else
        std::printf("  not within %.0f %% at %d specimens\n", 100 * within, counts.back());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vrut-ds-resample: %s\n", e.what());
    return 2;
  }
  return 0;
}
