#pragma once
// What vrut-rutting reports of a run, read back from its writers (seeds.csv,
// summary.json's skeleton block) against the library's RuttingResult: the
// application layer's writers, so for the test programs that link vrut::app.
#include "scratch.hpp"

#include <vrut/app/rutting_report.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/test.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace vrut_test {

// One cell of a CSV table by its column's name.
inline double csv_cell(const std::string& csv, const std::string& column, std::size_t row) {
  std::istringstream lines(csv);
  std::string header, line;
  std::getline(lines, header);
  auto cells = [](const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
    return out;
  };
  const auto names = cells(header);
  const auto at = std::find(names.begin(), names.end(), column);
  INFO("column " << column << " in " << header);
  REQUIRE(at != names.end());
  for (std::size_t r = 0; r <= row; ++r) REQUIRE(std::getline(lines, line));
  const auto values = cells(line);
  REQUIRE(values.size() == names.size());
  return std::strtod(values[static_cast<std::size_t>(at - names.begin())].c_str(), nullptr);
}

// What vrut-rutting writes of each specimen's skeleton, seeds.csv's columns
// and summary.json's block, read back by name against the library's
// RuttingResult::skeleton, each share worked out here from the forces; and
// the early load path measured at the first sample from minute 5 on.
// specimen_columns: seeds.csv's specimen columns, as the 2D or the 3D program names them.
inline void check_skeleton_reports(const std::vector<vrut::RuttingResult>& runs, const vrut::WheelTracking& wt,
                                   const std::string& specimen_columns = "disks,aggregates,aggregate_area_fraction") {
  const vrut_test::ScratchDir scratch("vrut-test-skeleton-report");
  std::vector<std::uint64_t> seeds;
  std::vector<vrut::app::ranks::SpecimenFacts> facts;
  for (std::size_t e = 0; e < runs.size(); ++e) seeds.push_back(11 + e), facts.push_back({3 + e, 0.5, 0});
  {
    vrut::OutputDir output(scratch / "out", false);
    vrut::app::write_seeds_csv(output, runs, vrut::app::report_runs(runs, wt, true, false), seeds, facts,
                               specimen_columns, false);
    output.commit();
  }
  std::ifstream in(scratch / "out" / "seeds.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json json = vrut::app::skeleton_summary_json(runs);
  REQUIRE(json.at("per_specimen").size() == runs.size());
  auto share = [](const vrut::LoadPath& p, double part) { return part / (p.mastic + p.stone_film + p.stone_spring); };
  auto sum = [](const std::array<int, vrut::film_census_bins>& bins) { return std::accumulate(bins.begin(), bins.end(), 0); };
  for (std::size_t e = 0; e < runs.size(); ++e) {
    INFO("specimen " << e);
    const vrut::RuttingResult& r = runs[e];
    const auto& s = r.skeleton;
    const nlohmann::json& j = json.at("per_specimen").at(e);
    CHECK(csv_cell(csv, "seed", e) == static_cast<double>(seeds[e]));
    const double late = (r.deformation_final - r.deformation_at_ds_start) / r.deformation_final;
    CHECK(csv_cell(csv, "late_creep_share", e) == Approx(late).epsilon(1e-14));
    CHECK(j.at("late_creep_share").get<double>() == Approx(late).epsilon(1e-14));
    const double per_stone = 2.0 * r.stone_pairs_touching / r.stones;
    CHECK(csv_cell(csv, "stones_touching_per_stone", e) == Approx(per_stone).epsilon(1e-14));
    CHECK(j.at("stones_touching_per_stone").get<double>() == Approx(per_stone).epsilon(1e-14));
    for (const auto& [when, key, path] : {std::tuple{"5min", "load_path_5min", s.load_early},
                                          std::tuple{"end", "load_path_end", s.load_end}}) {
      INFO(key);
      const nlohmann::json& jp = j.at(key);
      CHECK(jp.at("minute").get<double>() == path.minutes);
      for (const auto& [name, part] : {std::pair{"stone_spring", path.stone_spring}, std::pair{"stone_film", path.stone_film},
                                       std::pair{"mastic", path.mastic}}) {
        INFO(name);
        CHECK(jp.at("force_n").at(name).get<double>() == part);
        CHECK(jp.at("share").at(name).get<double>() == Approx(share(path, part)).epsilon(1e-14));
        CHECK(csv_cell(csv, std::string("load_") + when + "_" + name + "_share", e) ==
              Approx(share(path, part)).epsilon(1e-14));
      }
    }
    for (const auto& [when, census] : {std::pair{"start", s.films_start}, std::pair{"end", s.films_end}}) {
      INFO("films at the " << when);
      CHECK(csv_cell(csv, std::string("stone_contacts_") + when, e) == sum(census.contacts));
      CHECK(csv_cell(csv, std::string("stone_contacts_bearing_") + when, e) == sum(census.bearing));
      const nlohmann::json& jc = j.at(std::string("stone_films_") + when);
      CHECK(jc.at("contacts").get<int>() == sum(census.contacts));
      for (int b = 0; b < vrut::film_census_bins; ++b) {
        CHECK(jc.at("by_film").at(b).at("contacts").get<int>() == census.contacts[b]);
        CHECK(jc.at("by_film").at(b).at("bearing_on_stone_spring").get<int>() == census.bearing[b]);
      }
    }
    // The early load path at the first sample from minute 5 on; the end's at the last.
    const auto first_after = std::find_if(r.samples.begin(), r.samples.end(),
                                          [](const vrut::RuttingSample& smp) { return smp.minutes >= 5.0; });
    REQUIRE(first_after != r.samples.end());
    CHECK(s.load_early.minutes == first_after->minutes);
    CHECK(s.load_end.minutes == r.samples.back().minutes);
    CHECK(s.load_early.total() > 0.0);  // the plate's load crosses the cut
  }
}

}  // namespace vrut_test
