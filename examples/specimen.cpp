// vrut-specimen: generates a digital asphalt specimen from a gradation, or
// makes one from an image of a section (--image), and writes its picture,
// its statistics and a VTK file of the disks.
#include "common/cli.hpp"
#include "common/draw.hpp"
#include "common/image_cli.hpp"
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
  image_cli::ImageOptions io;
  CLI::App app("vrut-specimen: digital asphalt specimen from a gradation (aggregates, disks, air voids), or from an "
               "image of a section (--image)");
  add_specimen_options(app, o);
  image_cli::add_image_options(app, io, false);
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_flag("--force", force, "overwrite an existing output folder");
  if (const int code = cli::parse(app, argc, argv); code >= 0) return code;
  io.images = image_cli::given_images(io);
  return cli::guarded([&] {
    if (io.images.size() > 1) throw std::invalid_argument("--image: one image at a time (vrut-rutting runs several)");
    if (!io.images.empty()) {
      // Everything is read and checked before the output folder is made.
      const vrut::ImageSettings is = image_cli::to_settings(io, o, app.count("--width-mm") > 0, app.count("--air-voids") > 0);
      const auto start = std::chrono::steady_clock::now();
      const vrut::SegmentedImage seg = vrut::segment_image(vrut::read_section_image(io.images[0], is.label_image), is);
      vrut::require_memory(vrut::hex_disks_in(seg.width_mm(), seg.height_mm(), is.disk_radius), 512.0, 64e6, "this specimen");
      const vrut::Specimen sp = vrut::specimen_from_segmented(seg, is, "image " + io.images[0]);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const vrut::Gradation gradation = vrut::gradation_from_name(o.gradation);
      const vrut::SpecimenSettings mix_only = to_settings(o);
      vrut::OutputDir dir(out, force);
      nlohmann::json j = image_cli::image_summary(seg, is, io.images[0],
                                                  app.count("--gradation") ? &gradation : nullptr, mix_only.mix);
      j["section_mm"] = {sp.width, sp.height};
      j["disk_radius_mm"] = sp.disks.radius;
      const std::size_t agg = sp.aggregate_disks();
      j["disks"] = {{"total", sp.disks.centers.size()}, {"aggregate", agg}, {"mastic", sp.disks.centers.size() - agg},
                    {"void_sites", sp.disks.void_sites}, {"removed_for_air_voids", sp.disks.removed_for_voids},
                    {"bonds", sp.disks.bonds.size()}};
      std::ofstream(dir.file("specimen.json")) << j.dump(2) << '\n';
      image_cli::write_segmented_png(seg, dir.file("segmented.png").string());
      draw::specimen_png(sp, dir.file("specimen.png").string());
      write_specimen_vtk(sp, dir.file("specimen.vtk").string());
      dir.commit();
      std::printf("image %s: %.1f x %.1f mm, %zu stones (%d smaller than %.2f mm taken as mastic); stone %.4f, mastic "
                  "%.4f, void %.4f of the section; %zu disks (%zu aggregate); made in %.2f s\nresults in %s\n",
                  io.images[0].c_str(), sp.width, sp.height, seg.stone_area_mm2.size(), seg.stones_dropped,
                  is.smallest_stone_mm, seg.fraction[2], seg.fraction[1], seg.fraction[0], sp.disks.centers.size(), agg,
                  seconds, out.c_str());
      return 0;
    }
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
    draw::section_png(sp, dir.file("section.png").string(), 10.0);
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
