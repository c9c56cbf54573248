// vrut-specimen: generates a digital asphalt specimen from a gradation and
// writes its picture, its statistics and a VTK file of the disks.
#include "common/cli.hpp"
#include "common/draw.hpp"
#include "common/specimen_cli.hpp"

#include <vrut/io/memory_check.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/specimen/specimen.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  using namespace specimen_cli;
  SpecimenOptions o;
  std::string out = "out/specimen";
  bool force = false;
  CLI::App app("vrut-specimen: digital asphalt specimen from a gradation (aggregates, disks, air voids)");
  add_specimen_options(app, o);
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_flag("--force", force, "overwrite an existing output folder");
  if (const int code = cli::parse(app, argc, argv); code >= 0) return code;
  return cli::guarded([&] {
    vrut::OutputDir dir(out, force);
    // Measured: 267 MB for 412,757 disks, the specimen and its pictures (0.5 kB a disk).
    vrut::require_memory(vrut::hex_disks_in(o.width_mm, o.height_mm, o.disk_radius_mm), 512.0, 64e6, "this specimen");
    vrut::Specimen sp;
    const auto start = std::chrono::steady_clock::now();
    try {
      sp = vrut::generate_specimen(to_settings(o));
    } catch (const std::runtime_error& e) {  // the target could not be reached
      std::cerr << "error: " << e.what() << '\n';
      return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json j = specimen_summary(sp);
    std::ofstream(dir.file("specimen.json")) << j.dump(2) << '\n';
    draw::specimen_png(sp, dir.file("specimen.png").string());
    write_specimen_vtk(sp, dir.file("specimen.vtk").string());
    dir.commit();
    std::printf("gradation %s: %zu aggregates, area fraction %.4f (target %.4f), %zu disks (%zu aggregate), air voids "
                "%.4f; generated in %.2f s\nresults in %s\n",
                sp.settings.gradation.name.c_str(), sp.placement.aggregates.size(), sp.placement.achieved_fraction,
                sp.placement.target_fraction, sp.disks.centers.size(), sp.aggregate_disks(),
                sp.disks.air_void_achieved, seconds, out.c_str());
    return 0;
  });
}
