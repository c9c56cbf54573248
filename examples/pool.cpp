// vrut-pool: the statistics of one mix's specimens run as several ensembles
// or single specimens of vrut-rutting (seeds 1-3 one day, 4 and 5 the next),
// from their folders (an ensemble's seeds.csv, a single run's summary.json):
// what one ensemble of them all reports, as far as the specimens' rows carry
// it. The rut depth's mean, 95 % interval (Student t) and sd; the
// DS's mean, its geometric mean with that one's interval (Student t in the
// logarithms, so it stays positive, as vrut-rutting prints it), and median;
// the DS as the standard reports it: the median (Kaplan-Meier over the
// capped values) with its interval, and the DS of the mean curve with its
// interval (from the specimens' deformation over the DS window). Not without
// the curves: whether the mean curve scatters more over the window than it
// deforms, where an ensemble would call its DS a lower bound.
//
//   vrut-pool out/a out/b/seeds.csv out/c/summary.json ...
//   vrut-pool --cells ...   # "mean (low to high) | DS median | mean", for benchmarks/gradation_study.sh
//
// Refused (app/pooled_runs.hpp): a seed in two runs, seeds.csv files whose
// columns differ (runs of another version), 2D with 3D, runs whose config.ini
// differ in a setting other than the seeds, the output, --force, the
// checkpoints, the backend and threads (another mix or model), a run from
// images with any other, a run stopped before its end, fewer than two
// specimens. The runs' time steps may differ (each is the smallest its own
// specimens need); docs/validation.md measured what that moves.
#include <vrut/analysis/rutting_ensemble.hpp>
#include <vrut/analysis/standard_ds.hpp>
#include <vrut/analysis/statistics.hpp>
#include <vrut/app/pooled_runs.hpp>
#include <vrut/protocol/rutting/test.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"Pools several vrut-rutting runs of one mix and one model, ensembles or single specimens: the rut "
               "depth's and the DS's statistics over all their specimens"};
  std::vector<std::string> files;
  bool cells = false;
  app.add_option("runs", files, "each run's folder, or its seeds.csv (an ensemble) or summary.json (a single run)")
      ->required();
  app.add_flag("--cells", cells, "one line for benchmarks/gradation_study.sh: \"mean (low to high) | DS median | mean\"");
  CLI11_PARSE(app, argc, argv);
  try {
    const std::vector<vrut::SeedRow> rows = vrut::app::pool_runs(files);
    std::vector<double> rut, ds, window_mm;
    std::vector<std::pair<double, bool>> ds_bounds;
    std::vector<vrut::ReportedDS> reported;
    std::string seeds;
    int bounds = 0;
    for (const auto& r : rows) {
      rut.push_back(r.rut_depth_mm);
      ds.push_back(r.dynamic_stability);
      ds_bounds.emplace_back(r.dynamic_stability, r.dynamic_stability_is_lower_bound);
      bounds += r.dynamic_stability_is_lower_bound ? 1 : 0;
      window_mm.push_back(r.deformation_60min_mm - r.deformation_45min_mm);
      reported.push_back(r.standard);
      seeds += " " + std::to_string(r.seed);
    }
    const vrut::SampleStatistics r = vrut::describe(rut), d = vrut::describe(ds);
    const char* median_above = vrut::median_is_lower_bound(ds_bounds) ? "above " : "";
    if (cells) {
      std::printf("%.2f (%.2f to %.2f) | %s%.0f | %.4f\n", r.mean, r.ci_low, r.ci_high, median_above, d.median, r.mean);
      return 0;
    }
    std::printf("specimens: %d (seeds%s)\n", r.n, seeds.c_str());
    std::printf("rut depth, mm: %.2f (95 %% interval %.2f to %.2f), sd %.2f\n", r.mean, r.ci_low, r.ci_high, r.sd);
    const vrut::GeometricStatistics g = vrut::describe_geometric(ds);
    if (bounds == 0)
      std::printf("DS, passes/mm: mean %.0f, geometric mean %.0f (95 %% interval %.0f to %.0f), median %.0f\n", d.mean,
                  g.mean, g.ci_low, g.ci_high, d.median);
    else
      std::printf("DS, passes/mm: mean above %.0f (interval not known: %d of %d are lower bounds), median %s%.0f\n",
                  d.mean, bounds, r.n, median_above, d.median);
    const vrut::ReportedDS median = vrut::censored_median(reported);
    const vrut::MedianInterval median_ci = vrut::median_interval(reported);
    double mean_window = 0.0;
    for (double w : window_mm) mean_window += w / window_mm.size();
    const double passes = vrut::WheelTracking{}.ds_window_passes();
    const vrut::ReportedDS mean_curve =
        vrut::report_ds(mean_window > 0.0 ? passes / mean_window : std::numeric_limits<double>::infinity(), false);
    const vrut::DSInterval mean_curve_ci = vrut::mean_curve_ds_interval(window_mm, passes);
    const std::string median_interval =
        median_ci.defined ? "95 % interval " + vrut::reported_ds_text(median_ci.low) + " to " +
                                vrut::reported_ds_text(median_ci.high)
                          : "no interval below 6 specimens";
    std::printf("DS as the standard reports it (capped at %.0f), passes/mm: median %s (%s), of the mean curve %s "
                "(95 %% interval %s to %s)\n",
                vrut::standard_ds_cap, vrut::reported_ds_text(median).c_str(), median_interval.c_str(),
                vrut::reported_ds_text(mean_curve).c_str(), vrut::reported_ds_text(mean_curve_ci.low).c_str(),
                vrut::reported_ds_text(mean_curve_ci.high).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vrut-pool: %s\n", e.what());
    return 1;
  }
  return 0;
}
