#pragma once
// Command-line options and outputs of specimens from images, shared by
// vrut-specimen and vrut-rutting (--image).
#include "cli.hpp"
#include "specimen_cli.hpp"

#include <vrut/specimen/image_settings.hpp>
#include <vrut/specimen/specimen.hpp>
#ifndef VRUT_NO_IMAGES
#include <vrut/specimen/image.hpp>
#endif

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#ifndef VRUT_NO_IMAGES
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#endif

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifdef VRUT_NO_IMAGES
// Built without OpenCV (VRUT_IMAGES=OFF, for machines that lack it, a GPU
// node say): the options are known, and an image is refused with a reason.
namespace vrut {
inline Specimen specimen_from_image(const std::string& path, const ImageSettings&) {
  throw std::invalid_argument("cannot read image " + path + ": this program was built without OpenCV "
                              "(VRUT_IMAGES=OFF); build it with VRUT_IMAGES=ON to make specimens from images");
}
}  // namespace vrut
#endif

namespace vrut::app::image_cli {

struct ImageOptions {
  std::vector<std::string> images;
  double mm_per_pixel = 0.0;
  std::string phases = "void,mastic,stone";
  int stone_threshold = -1, void_threshold = -1;
  bool labels = false;
  int void_label = -1;
  double separation_depth_mm = vrut::ImageSettings{}.separation_depth_mm;
};

inline void add_image_options(CLI::App& app, ImageOptions& o, bool several) {
  app.add_option("--image", o.images,
                 several ? "a specimen from this image of a section (PNG, TIFF, JPEG); give it again for an "
                           "ensemble of images, run side by side (instead of --seed or --seeds)"
                         : "a specimen from this image of a section (PNG, TIFF, JPEG) instead of the generator")
      // A config file written by a run without images holds an empty one.
      ->check(CLI::Validator([](std::string& path) { return path.empty() ? std::string() : CLI::ExistingFile(path); },
                             "FILE"))
      ->group("Image");
  app.add_option("--mm-per-pixel", o.mm_per_pixel, "the image's scale (0: from --width-mm, the section's width)")
      ->check(cli::finite_range(0.0, 1e3))->capture_default_str()->group("Image");
  app.add_option("--phases", o.phases,
                 "the image's phases from dark to bright: void,mastic,stone (a CT slice, the default), or any order "
                 "of two or three of them")
      ->capture_default_str()->group("Image");
  app.add_option("--stone-threshold", o.stone_threshold,
                 "grey level (0-255) where stone begins, counted from the mastic's side (-1: Otsu's)")
      ->check(CLI::Range(-1, 255))->capture_default_str()->group("Image");
  app.add_option("--void-threshold", o.void_threshold,
                 "grey level (0-255) where void begins, counted from the mastic's side (-1: Otsu's)")
      ->check(CLI::Range(-1, 255))->capture_default_str()->group("Image");
  app.add_flag("--labels", o.labels, "the image is a label image: 0 mastic, each other value one stone")->group("Image");
  app.add_option("--void-label", o.void_label, "in a label image, the value of the voids (-1: none)")
      ->check(CLI::Range(-1, 65535))->capture_default_str()->group("Image");
  app.add_option("--separation-depth-mm", o.separation_depth_mm,
                 "touching stones are told apart where the distance to the edge dips by more than this between them")
      ->check(cli::finite_range(0.0, 100.0))->capture_default_str()->group("Image");
}

// The images given, less the empty ones a config file may hold.
inline std::vector<std::string> given_images(const ImageOptions& o) {
  std::vector<std::string> out;
  for (const auto& path : o.images)
    if (!path.empty()) out.push_back(path);
  return out;
}

inline std::vector<vrut::ImagePhase> parse_phases(const std::string& text) {
  std::vector<vrut::ImagePhase> out;
  std::stringstream in(text);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name == "void") out.push_back(vrut::ImagePhase::air_void);
    else if (name == "mastic") out.push_back(vrut::ImagePhase::mastic);
    else if (name == "stone") out.push_back(vrut::ImagePhase::stone);
    else throw std::invalid_argument("--phases: '" + name + "' is not a phase (void, mastic, stone)");
  }
  return out;
}

// The image settings from the options; the specimen's own options give the
// disks and the random voids. `width_given`: --width-mm was given (the
// scale from the image's width), `voids_given`: --air-voids was (an image's
// specimen has none added unless asked).
inline vrut::ImageSettings to_settings(const ImageOptions& o, const specimen_cli::SpecimenOptions& so,
                                       bool width_given, bool voids_given) {
  vrut::ImageSettings s;
  s.mm_per_pixel = o.mm_per_pixel;
  s.width_mm = width_given ? so.width_mm : 0.0;
  s.order = parse_phases(o.phases);
  s.stone_threshold = o.stone_threshold;
  s.void_threshold = o.void_threshold;
  s.label_image = o.labels;
  s.void_label = o.void_label;
  s.separation_depth_mm = o.separation_depth_mm;
  s.disk_radius = so.disk_radius_mm;
  s.air_voids = voids_given ? so.air_voids : 0.0;
  s.seed = so.seed;
  return s;
}

#ifndef VRUT_NO_IMAGES
// The original beside the segmentation: mastic black, voids white, every
// stone in a colour of its own.
inline void write_segmented_png(const vrut::SegmentedImage& seg, const std::string& path) {
  cv::Mat colour(seg.labels.size(), CV_8UC3), original;
  for (int r = 0; r < colour.rows; ++r)
    for (int c = 0; c < colour.cols; ++c) {
      const int l = seg.labels.at<int>(r, c);
      colour.at<cv::Vec3b>(r, c) = l == -1   ? cv::Vec3b(30, 30, 30)
                                   : l == -2 ? cv::Vec3b(255, 255, 255)
                                             : cv::Vec3b(60 + (l * 67) % 180, 60 + (l * 131) % 180, 60 + (l * 29) % 180);
    }
  cv::cvtColor(seg.grey, original, cv::COLOR_GRAY2BGR);
  cv::Mat gap(colour.rows, std::max(4, colour.cols / 100), CV_8UC3, cv::Scalar(255, 255, 255)), both;
  cv::hconcat(std::vector<cv::Mat>{original, gap, colour}, both);
  if (!cv::imwrite(path, both)) throw std::runtime_error("cannot write " + path);
}

// What the image gave: the phases' area fractions, the thresholds, and the
// stones' sizes (equivalent diameter) by sieve class; with a gradation, the
// 2D quantity gradation it implies beside the image's.
inline nlohmann::json image_summary(const vrut::SegmentedImage& seg, const vrut::ImageSettings& s,
                                    const std::string& path, const vrut::Gradation* gradation,
                                    const vrut::MixVolumetrics& mix) {
  nlohmann::json j;
  j["image"] = path;
  j["pixels"] = {seg.grey.cols, seg.grey.rows};
  j["mm_per_pixel"] = seg.mm_per_pixel;
  j["label_image"] = s.label_image;
  if (!s.label_image) j["grey_thresholds"] = {seg.thresholds[0], seg.thresholds[1]};
  j["area_fraction"] = {{"stone", seg.fraction[static_cast<int>(vrut::ImagePhase::stone)]},
                        {"mastic", seg.fraction[static_cast<int>(vrut::ImagePhase::mastic)]},
                        {"void", seg.fraction[static_cast<int>(vrut::ImagePhase::air_void)]}};
  j["stones"] = seg.stone_area_mm2.size();
  j["stones_under_smallest_taken_as_mastic"] = seg.stones_dropped;
  // The sieve classes: the gradation's, or the method's (2#) where none is given.
  const vrut::Gradation g = gradation ? *gradation : vrut::builtin_gradation(2);
  const vrut::Stereology st = vrut::stereology(g, mix);
  std::vector<int> count(st.classes.size(), 0);
  int above = 0;
  for (double a : seg.stone_area_mm2) {
    const double d = std::sqrt(4.0 * a / M_PI);
    bool placed = false;
    for (std::size_t c = 0; c < st.classes.size() && !placed; ++c)
      if (d >= st.classes[c].lower_mm && d < st.classes[c].upper_mm) ++count[c], placed = true;
    if (!placed && d >= st.classes.back().upper_mm) ++above;
  }
  double expected_total = 0.0;
  for (double n : st.sections_per_area) expected_total += n;
  const double n_stones = static_cast<double>(seg.stone_area_mm2.size());
  nlohmann::json per = nlohmann::json::array();
  for (std::size_t c = 0; c < st.classes.size(); ++c) {
    nlohmann::json row = {{"lower_mm", st.classes[c].lower_mm},
                          {"upper_mm", st.classes[c].upper_mm},
                          {"count", count[c]},
                          {"number_fraction", n_stones > 0 ? count[c] / n_stones : 0.0}};
    if (gradation) row["gradation_number_fraction"] = st.sections_per_area[c] / expected_total;
    per.push_back(row);
  }
  j["stones_by_equivalent_diameter"] = per;
  j["stones_above_largest_class"] = above;
  // The image's 2D quantity gradation: percent of the stones' number passing each sieve.
  nlohmann::json q = nlohmann::json::array();
  double below = n_stones;
  for (std::size_t c = st.classes.size(); c-- > 0;) {
    q.push_back({{"sieve_mm", st.classes[c].upper_mm}, {"image_percent_passing", n_stones > 0 ? 100.0 * (below - above) / n_stones : 0.0}});
    below -= count[c];
  }
  if (gradation) {
    const auto implied = st.quantity_gradation();
    for (std::size_t k = 0; k < q.size() && k < implied.size(); ++k) q[k]["gradation_percent_passing"] = implied[k].second;
  }
  j["quantity_gradation"] = q;
  return j;
}

#endif  // VRUT_NO_IMAGES

}  // namespace vrut::app::image_cli
