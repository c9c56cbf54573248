#pragma once
// seeds.csv, the table of an ensemble's specimens that vrut-rutting writes
// (one row a seed), read back: the tools that pool several runs of one mix or
// resample an ensemble's DS read it by column name, so the columns of the
// specimen's facts (2D: disks, aggregates; 3D: spheres, stones) may differ.
// Host-only.
#include <vrut/analysis/standard_ds.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

// The result columns every seeds.csv has after the specimen's facts, in
// order. The writer (include/vrut/app/rutting_report.hpp) writes exactly these.
inline constexpr const char* seeds_csv_result_columns =
    "rut_depth_mm,deformation_45min_mm,deformation_60min_mm,dynamic_stability_passes_per_mm,"
    "dynamic_stability_is_lower_bound,deformation_resolution_mm,stones,stone_pairs_touching,steps,"
    "ds_standard_passes_per_mm,ds_standard_censored";

// One specimen's row. A run stopped before its end (Ctrl-C) has no DS as the
// standard reports it: `stopped`, and `standard` is then meaningless.
struct SeedRow {
  std::uint64_t seed = 0;
  double rut_depth_mm = 0.0, deformation_45min_mm = 0.0, deformation_60min_mm = 0.0;
  double dynamic_stability = 0.0;  // passes/mm
  bool dynamic_stability_is_lower_bound = false;
  ReportedDS standard;
  bool stopped = false;
};

struct SeedsTable {
  std::string header;  // the first line, as written
  std::vector<SeedRow> rows;
};

namespace detail {
inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(cell);
  return out;
}
}  // namespace detail

// Reads a seeds.csv; throws std::runtime_error naming the file where it
// cannot be read, lacks a result column, or has a short or unreadable line.
inline SeedsTable read_seeds_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  SeedsTable table;
  if (!std::getline(in, table.header)) throw std::runtime_error(path + " is empty");
  const auto names = detail::split_csv_line(table.header);
  auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return i;
    throw std::runtime_error(path + " has no column " + name + ": is it a vrut-rutting seeds.csv?");
  };
  const std::size_t seed = column("seed"), rut = column("rut_depth_mm"), at_45 = column("deformation_45min_mm"),
                    at_60 = column("deformation_60min_mm"), ds = column("dynamic_stability_passes_per_mm"),
                    bound = column("dynamic_stability_is_lower_bound"), standard = column("ds_standard_passes_per_mm"),
                    censored = column("ds_standard_censored");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = detail::split_csv_line(line);
    if (cells.size() < names.size()) throw std::runtime_error(path + ": a short line: " + line);
    SeedRow row;
    try {
      row.seed = std::stoull(cells[seed]);
      row.rut_depth_mm = std::stod(cells[rut]);
      row.deformation_45min_mm = std::stod(cells[at_45]);
      row.deformation_60min_mm = std::stod(cells[at_60]);
      row.dynamic_stability = std::stod(cells[ds]);
      row.dynamic_stability_is_lower_bound = cells[bound] == "1";
      row.standard.value = std::stod(cells[standard]);
      row.standard.censored = cells[censored] == "1";
    } catch (const std::logic_error&) {  // std::stod's invalid_argument and out_of_range
      throw std::runtime_error(path + ": a line that is not numbers: " + line);
    }
    row.stopped = std::isnan(row.standard.value);
    table.rows.push_back(row);
  }
  if (table.rows.empty()) throw std::runtime_error(path + " lists no specimen");
  return table;
}

// Throws std::runtime_error naming the file and the seed where a row was
// stopped before its end: its specimen has no DS to pool or resample.
inline void refuse_stopped(const std::vector<SeedRow>& rows, const std::string& path) {
  for (const auto& row : rows)
    if (row.stopped)
      throw std::runtime_error(path + ": seed " + std::to_string(row.seed) +
                               " was stopped before its end (no DS): resume it first");
}

// read_seeds_csv, refusing a run stopped before its end.
inline SeedsTable read_finished_seeds_csv(const std::string& path) {
  SeedsTable table = read_seeds_csv(path);
  refuse_stopped(table.rows, path);
  return table;
}

}  // namespace vrut
