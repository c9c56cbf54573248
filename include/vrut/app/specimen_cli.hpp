#pragma once
// Command-line options, summary and VTK output of a digital specimen, shared
// by vrut-specimen and vrut-rutting.
#include "cli.hpp"

#include <vrut/io/vtk.hpp>
#include <vrut/specimen/specimen.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace vrut::app::specimen_cli {

struct SpecimenOptions {
  std::string gradation = "2";
  std::uint64_t seed = 1;
  double width_mm = 300.0, height_mm = 50.0;
  double radius_fluctuation = vrut::ShapeParameters{}.radius_fluctuation;
  double angle_fluctuation = vrut::ShapeParameters{}.angle_fluctuation;
  double asphalt_content = 0.048, gsb = 2.70, gmb = 2.40;
  double disk_radius_mm = 0.5, air_voids = 0.04;
  std::string placement = "scan";
  double binder_film_mm = 0.0;
};

inline void add_specimen_options(CLI::App& app, SpecimenOptions& o) {
  app.add_option("--gradation", o.gradation, "1, 2, 3 (docs/method.md section 2) or a CSV file sieve_mm,percent_passing")
      ->capture_default_str();
  app.add_option("--seed", o.seed, "random seed")->capture_default_str();
  app.add_option("--width-mm", o.width_mm, "section width")->check(cli::finite_range(1.0, 1e4))->capture_default_str();
  app.add_option("--height-mm", o.height_mm, "section height")->check(cli::finite_range(1.0, 1e4))->capture_default_str();
  app.add_option("--radius-fluctuation", o.radius_fluctuation, "polygon radius fluctuation R/R0, [0, 1)")
      ->check(cli::finite_range(0.0, 0.99))->capture_default_str();
  app.add_option("--angle-fluctuation", o.angle_fluctuation, "polygon angle fluctuation delta, [0, 1]")
      ->check(cli::finite_range(0.0, 1.0))->capture_default_str();
  app.add_option("--asphalt-content", o.asphalt_content, "binder, mass fraction of the mix")
      ->check(cli::finite_range(0.0, 0.5))->capture_default_str();
  app.add_option("--gsb", o.gsb, "aggregate bulk specific gravity")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--gmb", o.gmb, "mix bulk specific gravity")->check(cli::finite_positive())->capture_default_str();
  app.add_option("--disk-radius-mm", o.disk_radius_mm, "disk radius")->check(cli::finite_range(0.05, 10.0))
      ->capture_default_str();
  app.add_option("--air-voids", o.air_voids, "air void fraction of the section, [0, 0.3]")
      ->check(cli::finite_range(0.0, 0.3))->capture_default_str();
  app.add_option("--placement", o.placement,
                 "where random tries jam: scan (systematic, the default) or jiggle (Monte Carlo moves; random)")
      ->check(CLI::IsMember({"scan", "jiggle"}))->capture_default_str();
  app.add_option("--binder-film-mm", o.binder_film_mm,
                 "least gap between two aggregates, a film of mastic (0: they may touch)")
      ->check(cli::finite_range(0.0, 10.0))->capture_default_str();
}

inline vrut::SpecimenSettings to_settings(const SpecimenOptions& o) {
  vrut::SpecimenSettings s;
  s.gradation = vrut::gradation_from_name(o.gradation);
  s.seed = o.seed;
  s.placement.width = o.width_mm;
  s.placement.height = o.height_mm;
  s.placement.shape.radius_fluctuation = o.radius_fluctuation;
  s.placement.shape.angle_fluctuation = o.angle_fluctuation;
  s.mix.asphalt_content = o.asphalt_content;
  s.mix.aggregate_specific_gravity = o.gsb;
  s.mix.mix_specific_gravity = o.gmb;
  s.disk_radius = o.disk_radius_mm;
  s.air_voids = o.air_voids;
  s.placement.method = o.placement == "jiggle" ? vrut::PlacementMethod::jiggle : vrut::PlacementMethod::scan;
  s.placement.binder_film = o.binder_film_mm;
  return s;
}

inline nlohmann::json specimen_summary(const vrut::Specimen& sp) {
  nlohmann::json j;
  j["dimension"] = 2;
  if (sp.stereology.classes.empty()) {  // not generated: from an image
    const std::size_t agg = sp.aggregate_disks();
    j["source"] = sp.name;
    j["section_mm"] = {sp.width, sp.height};
    j["aggregate_count"] = sp.placement.aggregates.size();
    j["aggregate_area_fraction"] = {{"achieved", sp.placement.achieved_fraction}};
    j["disk_radius_mm"] = sp.disks.radius;
    j["disks"] = {{"total", sp.disks.centers.size()}, {"aggregate", agg}, {"mastic", sp.disks.centers.size() - agg},
                  {"void_sites", sp.disks.void_sites}, {"removed_for_air_voids", sp.disks.removed_for_voids},
                  {"bonds", sp.disks.bonds.size()}};
    return j;
  }
  j["gradation"] = sp.settings.gradation.name;
  j["seed"] = sp.settings.seed;
  j["section_mm"] = {sp.width, sp.height};
  nlohmann::json q = nlohmann::json::array();
  for (const auto& [sieve, passing] : sp.stereology.quantity_gradation())
    q.push_back({{"sieve_mm", sieve}, {"percent_passing", passing}});
  j["quantity_gradation"] = q;
  j["pieces_jammed"] = sp.placement.jammed;  // found no room in random tries: scanned or jiggled
  j["aggregate_area_fraction"] = {{"target", sp.placement.target_fraction},
                                  {"achieved", sp.placement.achieved_fraction},
                                  {"coarse_volume_fraction", sp.stereology.coarse_volume_fraction}};
  j["air_void_fraction"] = {{"target", sp.disks.air_void_target}, {"achieved", sp.disks.air_void_achieved}};
  j["disk_radius_mm"] = sp.disks.radius;
  const std::size_t agg = sp.aggregate_disks();
  j["disks"] = {{"total", sp.disks.centers.size()}, {"aggregate", agg}, {"mastic", sp.disks.centers.size() - agg},
                {"removed_for_air_voids", sp.disks.removed_for_voids}, {"bonds", sp.disks.bonds.size()}};
  double total = 0.0;
  for (double n : sp.stereology.sections_per_area) total += n;
  nlohmann::json per_class = nlohmann::json::array();
  for (std::size_t c = 0; c < sp.stereology.classes.size(); ++c) {
    int count = 0;
    double area = 0.0;
    for (const auto& a : sp.placement.aggregates)
      if (a.size_class == static_cast<int>(c)) ++count, area += a.area;
    per_class.push_back({{"lower_mm", sp.stereology.classes[c].lower_mm},
                         {"upper_mm", sp.stereology.classes[c].upper_mm},
                         {"count", count},
                         {"expected_number_fraction", sp.stereology.sections_per_area[c] / total},
                         {"area_mm2", area}});
  }
  j["aggregates"] = per_class;
  j["aggregate_count"] = sp.placement.aggregates.size();
  return j;
}

inline void write_specimen_vtk(const vrut::Specimen& sp, const std::string& path) {
  std::vector<double> x, y, radius, group, aggregate;
  for (std::size_t i = 0; i < sp.disks.centers.size(); ++i) {
    x.push_back(sp.disks.centers[i].x());
    y.push_back(sp.disks.centers[i].y());
    radius.push_back(sp.disks.radius);
    group.push_back(sp.disks.aggregate[i] >= 0 ? vrut::aggregate_group : vrut::mastic_group);
    aggregate.push_back(sp.disks.aggregate[i]);
  }
  vrut::VtkPointData data;
  data.scalars = {{"radius", radius}, {"group", group}, {"aggregate", aggregate}};
  vrut::write_vtk_disks(path, "vrut specimen (mm); group 0 mastic, 1 aggregate", x, y, data);
}

}  // namespace vrut::app::specimen_cli
