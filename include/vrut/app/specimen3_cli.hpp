#pragma once
// The 3D specimen's options, summary and VTK file (vrut-specimen --dim 3).
#include "cli.hpp"
#include "seeds.hpp"
#include "specimen_cli.hpp"

#include <vrut/io/progress.hpp>
#include <vrut/io/vtk.hpp>
#include <vrut/specimen/specimen3.hpp>
#include <vrut/specimen/specimens3.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

namespace vrut::app::specimen_cli {

struct Specimen3Options {
  double depth_mm = vrut::PlacementSettings3{}.depth;
  double sphere_radius_mm = vrut::SpecimenSettings3{}.sphere_radius;
  std::string stone_packing = "auto";
};

inline const std::map<std::string, vrut::StonePacking3>& stone_packings() {
  static const std::map<std::string, vrut::StonePacking3> names{{"auto", vrut::StonePacking3::automatic},
                                                                {"random", vrut::StonePacking3::random_addition},
                                                                {"compaction", vrut::StonePacking3::compaction}};
  return names;
}

// The options only 3D has; `o` holds the ones both have.
inline void add_specimen3_options(CLI::App& app, Specimen3Options& o) {
  app.add_option("--depth-mm", o.depth_mm,
                 "3D: the specimen's depth, periodic, rounded to whole FCC cells; at least twice the largest stone")
      ->check(cli::finite_range(1.0, 1e4))->capture_default_str();
  app.add_option("--sphere-radius-mm", o.sphere_radius_mm, "3D: sphere radius")->check(cli::finite_range(0.05, 10.0))
      ->capture_default_str();
  app.add_option("--stone-packing", o.stone_packing,
                 "3D: how the stones reach their volume fraction: random (random addition, jiggled where a stone "
                 "finds no room), compaction (placed loosely in a taller box, then pushed down by a lid; "
                 "docs/specimen.md), or auto: random, and compaction where it jams short (3#)")
      ->check(CLI::IsMember({"auto", "random", "compaction"}))->capture_default_str();
}

inline vrut::SpecimenSettings3 to_settings3(const SpecimenOptions& o, const Specimen3Options& o3) {
  const vrut::SpecimenSettings s2 = to_settings(o);
  vrut::SpecimenSettings3 s;
  s.gradation = s2.gradation;
  s.mix = s2.mix;
  s.seed = s2.seed;
  s.air_voids = s2.air_voids;
  s.placement.width = o.width_mm;
  s.placement.height = o.height_mm;
  s.placement.depth = o3.depth_mm;
  s.placement.shape.radius_fluctuation = o.radius_fluctuation;
  s.placement.shape.angle_fluctuation = o.angle_fluctuation;
  s.sphere_radius = o3.sphere_radius_mm;
  s.packing = stone_packings().at(o3.stone_packing);
  return s;
}

// A line for a compaction that jammed under its lid (compaction3.hpp);
// empty where the stones settled.
inline std::string jammed_compaction_note(const vrut::Placement3& p) {
  if (p.pairs_within_clearance == 0 && p.stones_within_clearance_of_a_wall == 0) return "";
  return "the compaction jammed under its lid: " + std::to_string(p.pairs_within_clearance) + " stone pairs and " +
         std::to_string(p.stones_within_clearance_of_a_wall) +
         " stones at a wall are nearer than its 0.001 mm clearance, none overlapping (the placement's test): "
         "the specimen is kept";
}

// generate_specimen3 with a progress bar for the placement (`label`) and,
// where there is one, for the compaction (its bar runs to the most steps it
// may take; it ends early when the stones have settled).
inline vrut::Specimen3 generate_specimen3_showing_progress(const vrut::SpecimenSettings3& s, const std::string& label) {
  std::unique_ptr<vrut::ProgressBar> placing, compacting;
  std::size_t last_placed = 0;
  return vrut::generate_specimen3(
      s,
      [&](std::size_t placed, std::size_t total) {
        if (placing && placed <= last_placed) {  // a second placement: the loose one of a compaction
          std::fprintf(stderr, "\nrandom addition jammed short of the stones' volume fraction: compacting instead\n");
          placing.reset();
        }
        last_placed = placed;
        if (!placing) placing = std::make_unique<vrut::ProgressBar>(label, static_cast<long>(total), "stones");
        placing->update(static_cast<long>(placed));
        if (placed == total) placing->finish();
      },
      [&](long step, long most) {
        if (!compacting) compacting = std::make_unique<vrut::ProgressBar>("compacting (at most)", most, "steps");
        compacting->update(step);
        if (step == most) compacting->finish();
      });
}

// An ensemble's specimens, `workers` at a time (specimen/specimens3.hpp;
// workers left over, more than seeds, go to each specimen's compaction),
// with one bar that counts the finished specimens and a line for each that
// compacts. A specimen that cannot be made throws vrut::SpecimenSeedError.
inline std::vector<vrut::Specimen3> generate_specimens3_showing_progress(const vrut::SpecimenSettings3& s,
                                                                       const std::vector<std::uint64_t>& seeds,
                                                                       int workers) {
  const int at_once = std::max(1, std::min<int>(workers, static_cast<int>(seeds.size())));
  vrut::ProgressBar bar("placing stones, " + cli::specimens_text(seeds.size()) + ", " +
                            std::to_string(at_once) + " at a time",
                        static_cast<long>(seeds.size()), "specimens");
  bar.update(0);
  long finished = 0;
  auto specimens = vrut::generate_specimens3(
      s, seeds, workers, {},
      [&](std::size_t) {
        if (++finished == static_cast<long>(seeds.size())) bar.finish();
        else bar.update(finished);
      },
      [&](std::size_t i) {
        std::fprintf(stderr, "%sseed %llu: random addition jammed short of the stones' volume fraction: compacting "
                     "instead (about 4 minutes for a 3# specimen of 300 x 50 x 40 mm on two threads)\n",
                     isatty(fileno(stderr)) ? "\n" : "", static_cast<unsigned long long>(seeds[i]));
      });
  return specimens;
}

inline nlohmann::json specimen3_summary(const vrut::Specimen3& sp) {
  nlohmann::json j;
  j["dimension"] = 3;
  j["gradation"] = sp.settings.gradation.name;
  j["seed"] = sp.settings.seed;
  j["box_mm"] = {sp.width, sp.height, sp.depth};
  j["periodic"] = "depth (z)";
  j["stones_jammed"] = sp.placement.jammed;  // found no room in random tries: jiggled in
  j["stone_packing"] = sp.placement.compaction_steps > 0 ? "compaction" : "random addition";
  if (sp.placement.compaction_steps > 0) {
    j["compaction_steps"] = sp.placement.compaction_steps;
    // Left nearer than the compaction's clearance where it jammed under its lid (0: settled).
    j["compaction_pairs_within_clearance"] = sp.placement.pairs_within_clearance;
    j["compaction_stones_within_clearance_of_a_wall"] = sp.placement.stones_within_clearance_of_a_wall;
    j["compaction_threads"] = sp.settings.compaction.threads;  // the same packing on any count
  }
  j["stone_volume_fraction"] = {{"target", sp.placement.target_fraction}, {"achieved", sp.placement.achieved_fraction}};
  j["air_void_fraction"] = {{"target", sp.spheres.air_void_target}, {"achieved", sp.spheres.air_void_achieved}};
  j["sphere_radius_mm"] = sp.spheres.radius;
  std::size_t in_stones = 0;
  for (int s : sp.spheres.stone) in_stones += s >= 0;
  j["spheres"] = {{"total", sp.spheres.centers.size()}, {"in_stones", in_stones},
                  {"mastic", sp.spheres.centers.size() - in_stones},
                  {"removed_for_air_voids", sp.spheres.removed_for_voids}, {"bonds", sp.spheres.bonds.size()}};
  nlohmann::json per_class = nlohmann::json::array();
  const double box = sp.width * sp.height * sp.depth;
  for (std::size_t c = 0; c < sp.stereology.classes.size(); ++c) {
    int count = 0;
    double volume = 0.0;
    for (const auto& s : sp.placement.stones)
      if (s.size_class == static_cast<int>(c)) ++count, volume += s.shape.volume;
    per_class.push_back({{"lower_mm", sp.stereology.classes[c].lower_mm},
                         {"upper_mm", sp.stereology.classes[c].upper_mm},
                         {"count", count},
                         {"volume_fraction", volume / box},
                         {"target_volume_fraction", sp.stereology.volume_fraction[c]}});
  }
  j["stones"] = per_class;
  j["stone_count"] = sp.placement.stones.size();
  return j;
}

inline void write_specimen3_vtk(const vrut::Specimen3& sp, const std::string& path) {
  std::vector<double> x, y, z, radius, group, stone;
  for (std::size_t i = 0; i < sp.spheres.centers.size(); ++i) {
    x.push_back(sp.spheres.centers[i].x());
    y.push_back(sp.spheres.centers[i].y());
    z.push_back(sp.spheres.centers[i].z());
    radius.push_back(sp.spheres.radius);
    group.push_back(sp.spheres.stone[i] >= 0 ? vrut::aggregate_group : vrut::mastic_group);
    stone.push_back(sp.spheres.stone[i]);
  }
  vrut::VtkPointData data;
  data.scalars = {{"radius", radius}, {"group", group}, {"stone", stone}};
  vrut::write_vtk_points(path, "vrut 3D specimen (mm, y up, z periodic); group 0 mastic, 1 stone", x, y, z, data);
}

}  // namespace vrut::app::specimen_cli
