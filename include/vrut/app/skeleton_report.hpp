#pragma once
// vrut-rutting's report of what holds each specimen up (protocol/rutting/skeleton.hpp):
// the load path across a cut at half height under the plate, by class of
// contact, early (5 min) and at the end; the stones' films; the stones
// touching per stone; the late creep. In summary.json, seeds.csv and
// skeleton.png, 2D and 3D alike.
#include "seeds.hpp"

#include <vrut/io/output_dir.hpp>
#include <vrut/io/plot.hpp>
#include <vrut/protocol/rutting/result.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace vrut::app {

// seeds.csv's columns of the skeleton, after the result columns.
inline constexpr const char* skeleton_csv_columns =
    "late_creep_share,stones_touching_per_stone,"
    "load_5min_stone_spring_share,load_5min_stone_film_share,load_5min_mastic_share,"
    "load_end_stone_spring_share,load_end_stone_film_share,load_end_mastic_share,"
    "stone_contacts_start,stone_contacts_bearing_start,stone_contacts_end,stone_contacts_bearing_end";

inline std::string skeleton_csv_cells(const vrut::RuttingResult& r) {
  const auto& s = r.skeleton;
  std::ostringstream out;
  out.precision(17);
  auto shares = [&](const vrut::LoadPath& p) {
    out << ',' << p.share(p.stone_spring) << ',' << p.share(p.stone_film) << ',' << p.share(p.mastic);
  };
  out << r.late_creep_share() << ',' << r.stones_touching_per_stone();
  shares(s.load_early);
  shares(s.load_end);
  out << ',' << s.films_start.total_contacts() << ',' << s.films_start.total_bearing() << ','
      << s.films_end.total_contacts() << ',' << s.films_end.total_bearing();
  return out.str();
}

// A number, or null where it is not defined (JSON has no NaN).
inline nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

inline nlohmann::json load_path_json(const vrut::LoadPath& p) {
  if (!p.measured()) return nullptr;  // the run ended (or was stopped) before that minute
  return {{"minute", p.minutes},
          {"force_n", {{"stone_spring", p.stone_spring}, {"stone_film", p.stone_film}, {"mastic", p.mastic}}},
          {"share", {{"stone_spring", number_or_null(p.share(p.stone_spring))},
                     {"stone_film", number_or_null(p.share(p.stone_film))},
                     {"mastic", number_or_null(p.share(p.mastic))}}}};
}

inline nlohmann::json film_census_json(const vrut::FilmCensus& c) {
  nlohmann::json bins = nlohmann::json::array();
  for (int b = 0; b < vrut::film_census_bins; ++b)
    bins.push_back({{"film_diameters", vrut::FilmCensus::thickness(b)},
                    {"contacts", c.contacts[b]},
                    {"bearing_on_stone_spring", c.bearing[b]}});
  return {{"contacts", c.total_contacts()}, {"bearing_on_stone_spring", c.total_bearing()}, {"by_film", bins}};
}

// One specimen's skeleton, for summary.json.
inline nlohmann::json skeleton_json(const vrut::RuttingResult& r) {
  const auto& s = r.skeleton;
  return {{"late_creep_share", number_or_null(r.late_creep_share())},
          {"stones_touching_per_stone", number_or_null(r.stones_touching_per_stone())},
          {"load_path_5min", load_path_json(s.load_early)},
          {"load_path_end", load_path_json(s.load_end)},
          {"stone_films_start", film_census_json(s.films_start)},
          {"stone_films_end", film_census_json(s.films_end)}};
}

// summary.json's "skeleton": its definitions, the means over the specimens
// and each specimen's (in seed order).
inline nlohmann::json skeleton_summary_json(const std::vector<vrut::RuttingResult>& runs) {
  auto mean = [&](auto value) {
    double sum = 0.0;
    int n = 0;
    for (const auto& r : runs) {
      const double v = value(r);
      if (std::isfinite(v)) sum += v, ++n;
    }
    return n > 0 ? nlohmann::json(sum / n) : nlohmann::json(nullptr);
  };
  auto share_means = [&](auto path) {
    return nlohmann::json{
        {"stone_spring", mean([&](const vrut::RuttingResult& r) { return path(r).share(path(r).stone_spring); })},
        {"stone_film", mean([&](const vrut::RuttingResult& r) { return path(r).share(path(r).stone_film); })},
        {"mastic", mean([&](const vrut::RuttingResult& r) { return path(r).share(path(r).mastic); })}};
  };
  nlohmann::json per = nlohmann::json::array();
  for (const auto& r : runs) per.push_back(skeleton_json(r));
  return {{"about",
           "load path: the vertical force crossing a horizontal cut half way between the floor and the plate (where it "
           "is then), under the plate, "
           "by class of contact (stone_spring: two stones bearing on the stones' spring, their overlap beyond the "
           "film between them; stone_film: two stones on their film alone; mastic: any contact with a mastic "
           "particle); a stone lies on the side of its centroid. stone films: the overlapping contacts between two "
           "stones' particles by the film between them (diameters), and those bearing on the stones' spring. "
           "late_creep_share: (d60 - d45) / d60."},
          {"late_creep_share", mean([](const vrut::RuttingResult& r) { return r.late_creep_share(); })},
          {"stones_touching_per_stone", mean([](const vrut::RuttingResult& r) { return r.stones_touching_per_stone(); })},
          {"load_path_5min_share", share_means([](const vrut::RuttingResult& r) { return r.skeleton.load_early; })},
          {"load_path_end_share", share_means([](const vrut::RuttingResult& r) { return r.skeleton.load_end; })},
          {"per_specimen", per}};
}

// skeleton.png: the load path's shares at 5 min and at the end, the mean
// over the specimens, one bar per class.
inline void write_skeleton_plot(vrut::OutputDir& output, const std::vector<vrut::RuttingResult>& runs,
                         const std::string& title) {
  auto mean_share = [&](bool early, int cls) {
    double sum = 0.0;
    int n = 0;
    for (const auto& r : runs) {
      const vrut::LoadPath& p = early ? r.skeleton.load_early : r.skeleton.load_end;
      const double part = cls == 0 ? p.stone_spring : cls == 1 ? p.stone_film : p.mastic;
      const double v = p.share(part);
      if (std::isfinite(v)) sum += v, ++n;
    }
    return n > 0 ? 100.0 * sum / n : 0.0;
  };
  const char* names[3] = {"stones on their spring", "stones on their film alone", "through mastic"};
  const char* colours[3] = {"#aa3333", "#dd9944", "#4477aa"};
  std::vector<vrut::PlotSeries> series;
  for (int c = 0; c < 3; ++c)
    series.push_back({names[c], {1.0 + c, 5.0 + c}, {mean_share(true, c), mean_share(false, c)},
                      std::string("boxes fs solid 0.8 lc rgb '") + colours[c] + "'"});
  vrut::PlotSpec spec;
  spec.title = title + ": what carries the plate's load at half height" +
               (runs.size() > 1 ? " (mean of " + cli::specimens_text(runs.size()) + ")" : "");
  spec.xlabel = "";
  spec.ylabel = "share of the vertical force across the cut (%)";
  spec.extra = "set boxwidth 0.8\nset xrange [0:8]\nset yrange [0:115]\nset key top center horizontal\n"
               "set xtics ('minute 5' 2, 'end of test' 6)";
  vrut::write_plot_png(output.file("skeleton.png").string(), spec, series);
}

}  // namespace vrut::app
