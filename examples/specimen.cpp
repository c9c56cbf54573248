// vrut-specimen: generates a digital asphalt specimen from a gradation, or
// makes one from an image of a section (--image), and writes its picture,
// its statistics and a VTK file of the disks; with --dim 3 a 3D specimen
// (polyhedral stones, spheres), its pictures at mid-depth and from above.
#include <vrut/app/cli.hpp>
#include <vrut/app/draw.hpp>
#include <vrut/app/draw3.hpp>
#include <vrut/app/image_cli.hpp>
#include <vrut/app/specimen3_cli.hpp>
#include <vrut/app/specimen_cli.hpp>

#include <vrut/io/memory_check.hpp>
#include <vrut/io/progress.hpp>
#include <vrut/io/output_dir.hpp>
#include <vrut/specimen/specimen.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

using namespace vrut::app;  // the command line's shared options and outputs (cli, draw, specimen_cli, ...)

int main(int argc, char** argv) {
  using namespace specimen_cli;
  SpecimenOptions o;
  std::string out = "out/specimen";
  bool force = false;
  image_cli::ImageOptions io;
  Specimen3Options o3;
  int dim = 2;
  CLI::App app("vrut-specimen: digital asphalt specimen from a gradation (aggregates, disks, air voids), or from an "
               "image of a section (--image); --dim 3: a 3D specimen (polyhedral stones, spheres)");
  app.add_option("--dim", dim, "2 (a section of disks) or 3 (a box of spheres, periodic along its depth)")
      ->check(CLI::IsMember({2, 3}))->capture_default_str();
  add_specimen_options(app, o);
  add_specimen3_options(app, o3);
  image_cli::add_image_options(app, io, false);
  int threads = 0;
  app.add_option("--threads", threads, "3D: host threads for a compaction (0: all the machine's); the specimen is "
                 "the same for any count")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_flag("--force", force, "overwrite an existing output folder");
  if (const int code = cli::parse(app, argc, argv); code >= 0) return code;
  io.images = image_cli::given_images(io);
  return cli::guarded([&] {
    if (dim == 3) {
      for (const char* only2d : {"--disk-radius-mm", "--placement", "--binder-film-mm", "--image", "--images"})
        if (app.get_option_no_throw(only2d) && app.count(only2d) > 0)
          throw std::invalid_argument(std::string(only2d) + " is for 2D sections; a 3D specimen has --sphere-radius-mm "
                                      "and --depth-mm, and places its stones by --stone-packing");
      vrut::SpecimenSettings3 s3 = to_settings3(o, o3);
      s3.compaction.threads = threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
      // About 0.3 kB a sphere at most (the specimen, its pictures and VTK).
      const double spheres = 4.0 / (std::pow(vrut::fcc_cell(s3.sphere_radius), 3)) * s3.placement.width *
                             s3.placement.height * s3.placement.depth;
      vrut::require_memory(spheres, 512.0, 64e6, "this 3D specimen");
      vrut::OutputDir dir(out, force);
      vrut::Specimen3 sp;
      const auto start = std::chrono::steady_clock::now();
      try {
        sp = generate_specimen3_showing_progress(s3, "placing stones");
      } catch (const std::runtime_error& e) {  // the target could not be reached
        std::cerr << "error: " << e.what() << '\n';
        return 1;
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      nlohmann::json j = specimen3_summary(sp);
      j["seconds"] = seconds;
      std::ofstream(dir.file("specimen.json")) << j.dump(2) << '\n';
      draw::section3_png(sp, dir.file("section_mid_depth.png").string());
      draw::surface3_png(sp, dir.file("surface.png").string());
      write_specimen3_vtk(sp, dir.file("specimen.vtk").string());
      dir.commit();
      const std::string jammed = jammed_compaction_note(sp.placement);
      if (!jammed.empty()) std::fprintf(stderr, "%s\n", jammed.c_str());
      const std::string packing =
          sp.placement.compaction_steps > 0
              ? "compacted in " + std::to_string(sp.placement.compaction_steps) + " steps"
              : std::to_string(sp.placement.jammed) + " jammed and jiggled in";
      std::printf("gradation %s, 3D: %.0f x %.0f x %.2f mm, %zu stones, volume fraction %.4f (target %.4f), %s; "
                  "%zu spheres of %.2f mm, air voids %.4f; generated in %.1f s\nresults in %s\n",
                  sp.settings.gradation.name.c_str(), sp.width, sp.height, sp.depth, sp.placement.stones.size(),
                  sp.placement.achieved_fraction, sp.placement.target_fraction, packing.c_str(),
                  sp.spheres.centers.size(), sp.spheres.radius, sp.spheres.air_void_achieved, seconds, out.c_str());
      return 0;
    }
    for (const char* only3d : {"--depth-mm", "--sphere-radius-mm", "--stone-packing", "--threads"})
      if (app.count(only3d) > 0) throw std::invalid_argument(std::string(only3d) + " is for 3D specimens (--dim 3)");
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
