// How many specimens a mix needs before its DS median is known within a
// given share: each ensemble's seeds.csv (vrut-rutting --seeds), its DS as
// the standard reports them (capped at 6000, lower bounds censored), the
// Kaplan-Meier median, and for n specimens the half-width of the central 95 %
// of the medians of n specimens drawn with replacement from the ensemble,
// over its median (analysis/standard_ds.hpp; smoothed draws). Beyond the
// ensemble's own size the draws take its specimens, smoothed, as the whole
// population: a projection. First, for each ensemble, the DS median's and
// the mean curve's DS with their 95 % intervals, as vrut-rutting reports
// them today, so that ensembles run before it did get them too.
//
//   vrut-ds-resample [--within 0.15] out/mix1/seeds.csv out/mix2/seeds.csv ...
#include <vrut/analysis/seeds_csv.hpp>
#include <vrut/analysis/standard_ds.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// A seeds.csv: each specimen's DS as the standard reports it, and its
// deformation from minute 45 to the end (mm).
struct Ensemble {
  std::vector<vrut::ReportedDS> ds;
  std::vector<double> window_mm;
};

Ensemble read_ensemble(const std::string& path) {
  Ensemble out;
  for (const auto& row : vrut::read_finished_seeds_csv(path).rows) {
    out.ds.push_back(vrut::report_ds(row.dynamic_stability, row.dynamic_stability_is_lower_bound));
    out.window_mm.push_back(row.deformation_60min_mm - row.deformation_45min_mm);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"How many specimens a mix needs before its DS median is known within a share, by resampling"};
  std::vector<std::string> files;
  double within = 0.15;
  int draws = 4000;
  double passes = 630.0;
  app.add_option("seeds_csv", files, "seeds.csv of each ensemble")->required()->check(CLI::ExistingFile);
  app.add_option("--within", within, "the share of the median asked for")->check(CLI::Range(0.001, 1.0));
  app.add_option("--draws", draws, "resampled medians per specimen count")->check(CLI::Range(100, 1000000));
  app.add_option("--window-passes", passes, "passes from minute 45 to the end, (t2 - t1) N C1 C2")
      ->check(CLI::Range(1.0, 1e9));
  CLI11_PARSE(app, argc, argv);
  try {
    const std::vector<int> counts = {3, 5, 8, 10, 16, 20, 30, 40, 60, 80, 120, 160, 240, 320};
    for (const auto& f : files) {
      const Ensemble e = read_ensemble(f);
      const auto& ds = e.ds;
      const auto median = vrut::censored_median(ds);
      int censored = 0;
      for (const auto& d : ds) censored += d.censored;
      std::printf("%s: %zu specimens (%d censored), DS median %s", f.c_str(), ds.size(), censored, vrut::reported_ds_text(median).c_str());
      const auto median_ci = vrut::median_interval(ds);
      if (median_ci.defined)
        std::printf(" (95 %% interval %s to %s, coverage %.3f)", vrut::reported_ds_text(median_ci.low).c_str(),
                    vrut::reported_ds_text(median_ci.high).c_str(), median_ci.coverage);
      double mean_window = 0.0;
      for (double w : e.window_mm) mean_window += w / e.window_mm.size();
      std::printf(" passes/mm; of the mean curve %s",
                  vrut::reported_ds_text(vrut::report_ds(mean_window > 0.0 ? passes / mean_window : HUGE_VAL, false)).c_str());
      if (ds.size() >= 2) {
        const auto curve_ci = vrut::mean_curve_ds_interval(e.window_mm, passes);
        std::printf(" (95 %% interval %s to %s)", vrut::reported_ds_text(curve_ci.low).c_str(), vrut::reported_ds_text(curve_ci.high).c_str());
      }
      std::printf("\n");
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
