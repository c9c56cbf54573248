#pragma once
// A specimen from an image of a section: a photograph of a sawn face, an
// X-ray CT slice, or a label image. Host-only; needs OpenCV (core, imgproc,
// imgcodecs: target vrut::image); mm.
//
//  1. Phases by grey level: stone, mastic and air void, in a given order from
//     dark to bright (a CT slice: void, mastic, stone). The two thresholds are
//     Otsu's for three classes unless given; with two phases, OpenCV's Otsu.
//     Or a label image: 0 mastic, every other value one stone (and, where
//     asked, one value the voids).
//  2. Touching stones separated by a watershed on the distance transform
//     (cv::distanceTransform, cv::watershed), from one marker per stone: the
//     distance's maxima deeper than `separation_depth_mm` (an h-maxima
//     transform, by morphological reconstruction with cv::dilate). A neck
//     between two stones is a saddle of the distance; a stone's own bumps
//     are shallower than that depth. Where a small stone presses on a large
//     one along a wide contact the saddle lies inside the small one, so each
//     touching pair is split again along the line between the concave
//     corners of its outline (cv::convexityDefects). Before that, threads of
//     stone-grey pixels on the rims of voids (the mean of void and mastic)
//     are taken off by an opening.
//  3. Stones smaller than the 2.36 mm class (equivalent diameter) are mastic,
//     by the method's rule (docs/method.md section 3).
//  4. The disks of the hexagonal packing take the phase under their centres:
//     a stone's disks become that aggregate, void sites are left empty, and
//     random voids are added only where asked.
#include <vrut/specimen/image_settings.hpp>
#include <vrut/specimen/image_steps.hpp>
#include <vrut/specimen/specimen.hpp>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

// The image, segmented: per pixel -2 void, -1 mastic, k >= 0 stone k.
struct SegmentedImage {
  cv::Mat grey;    // CV_8U, as read (colour turned grey)
  cv::Mat labels;  // CV_32S
  double mm_per_pixel = 0.0;
  int thresholds[2] = {-1, -1};  // the grey levels used, dark to bright (-1: none)
  int stones_dropped = 0;        // smaller than smallest_stone_mm, made mastic
  double fraction[3] = {0, 0, 0};  // of the section, by ImagePhase
  std::vector<double> stone_area_mm2;
  double width_mm() const { return grey.cols * mm_per_pixel; }
  double height_mm() const { return grey.rows * mm_per_pixel; }
};


// Reads an image file, in grey (colour is turned grey), or as it is for a
// label image (16-bit labels kept). Throws std::invalid_argument with a
// message a user can act on.
inline cv::Mat read_section_image(const std::string& path, bool label_image) {
  cv::Mat img;
  try {
    img = cv::imread(path, label_image ? cv::IMREAD_ANYDEPTH : cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception& e) {
    throw std::invalid_argument("cannot read the image " + path + ": " + e.what());
  }
  if (img.empty())
    throw std::invalid_argument("cannot read the image " + path +
                                ": no such file, or not an image (PNG, TIFF, JPEG, BMP) OpenCV can decode");
  if (img.channels() != 1) cv::cvtColor(img, img, cv::COLOR_BGR2GRAY);
  if (img.rows < 8 || img.cols < 8)
    throw std::invalid_argument("the image " + path + " is " + std::to_string(img.cols) + " x " +
                                std::to_string(img.rows) + " pixels: too small to hold a section");
  return img;
}

inline double image_scale(const cv::Mat& img, const ImageSettings& s) {
  if (s.mm_per_pixel > 0.0 && s.width_mm > 0.0)
    throw std::invalid_argument("give the scale once: --mm-per-pixel or --width-mm, not both");
  const double scale = s.mm_per_pixel > 0.0 ? s.mm_per_pixel : s.width_mm / img.cols;
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument("the image needs a scale: --mm-per-pixel, or --width-mm (the section's width)");
  return scale;
}

inline SegmentedImage segment_image(const cv::Mat& image, const ImageSettings& s) {
  SegmentedImage out;
  out.mm_per_pixel = image_scale(image, s);
  const double px = out.mm_per_pixel;
  if (!(s.disk_radius > 0.0)) throw std::invalid_argument("disk radius must be positive");
  if (s.disk_radius < px)
    throw std::invalid_argument("a disk (radius " + detail::mm_text(s.disk_radius) + " mm) is smaller than a pixel (" +
                                detail::mm_text(px) + " mm): is the scale right?");
  cv::Mat stones(image.size(), CV_8U, cv::Scalar(0)), voids(image.size(), CV_8U, cv::Scalar(0));
  cv::Mat given_labels;  // a label image's stones
  if (s.label_image) {
    cv::Mat l32;
    image.convertTo(l32, CV_32S);
    if (s.void_label >= 0) voids = l32 == s.void_label;
    stones = (l32 != 0) & (l32 != s.void_label);
    given_labels = l32;
    image.convertTo(out.grey, CV_8U, image.depth() == CV_16U ? 1.0 / 257.0 : 1.0);
  } else {
    out.grey = image.depth() == CV_8U ? image : cv::Mat();
    if (out.grey.empty()) image.convertTo(out.grey, CV_8U, image.depth() == CV_16U ? 1.0 / 257.0 : 1.0);
    const auto& order = s.order;
    const int n = static_cast<int>(order.size());
    if (n < 2 || n > 3) throw std::invalid_argument("the phases' order names 2 or 3 phases");
    int mastic_at = -1, stone_at = -1, void_at = -1;
    for (int i = 0; i < n; ++i) {
      int& at = order[i] == ImagePhase::mastic ? mastic_at : order[i] == ImagePhase::stone ? stone_at : void_at;
      if (at >= 0) throw std::invalid_argument(std::string("the phases' order names ") + detail::phase_name(order[i]) + " twice");
      at = i;
    }
    if (mastic_at < 0 || stone_at < 0) throw std::invalid_argument("the phases' order must name mastic and stone");
    if (s.void_threshold >= 0 && void_at < 0)
      throw std::invalid_argument("a void threshold is given, but the phases' order has no void");
    // Boundary b between classes b and b+1 is the threshold of the one further from the mastic.
    std::array<int, 2> t{-1, -1};
    auto given = [&](int b) {
      const int further = b >= mastic_at ? b + 1 : b;
      return order[further] == ImagePhase::stone ? s.stone_threshold : s.void_threshold;
    };
    if (n == 2) {
      cv::Mat unused;
      t[0] = given(0) >= 0 ? given(0) : static_cast<int>(cv::threshold(out.grey, unused, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU)) + 1;
    } else {
      const auto otsu = detail::otsu_three_classes(out.grey);
      t[0] = given(0) >= 0 ? given(0) : otsu[0];
      t[1] = given(1) >= 0 ? given(1) : otsu[1];
      if (!(t[0] < t[1]))
        throw std::invalid_argument("the grey thresholds must rise from dark to bright: " + std::to_string(t[0]) +
                                    " then " + std::to_string(t[1]));
    }
    out.thresholds[0] = t[0], out.thresholds[1] = t[1];
    // The class of each pixel, 0 .. n-1 from dark to bright.
    auto in_class = [&](int k) {
      cv::Mat m = cv::Mat(out.grey.size(), CV_8U, cv::Scalar(255));
      if (k > 0) m &= out.grey >= t[k - 1];
      if (k < n - 1) m &= out.grey < t[k];
      return m;
    };
    stones = in_class(stone_at);
    if (void_at >= 0) voids = in_class(void_at);
    // A pixel on the edge between void (bright) and mastic (dark) is the mean
    // of the two, which is the grey of stone: a thread of such pixels along a
    // void's rim is no stone. A stone is thicker than 3 pixels everywhere but
    // at its sharpest corners, so an opening by a 3 x 3 square takes the
    // threads and leaves the stones.
    if (void_at >= 0) {
      cv::Mat opened;
      cv::morphologyEx(stones, opened, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
      stones = opened;
    }
  }
  if (cv::countNonZero(stones) == 0)
    throw std::invalid_argument("no stone in the image: all " + std::to_string(image.total()) +
                                " pixels are mastic or void (check the thresholds or the phases' order)");

  // Stones: from the label image, or separated by the watershed.
  cv::Mat labels(image.size(), CV_32S, cv::Scalar(-1));
  labels.setTo(-2, voids);
  int count = 0;
  cv::Mat markers;
  if (s.label_image) {
    markers = given_labels.clone();
    markers.setTo(0, ~stones);
  } else {
    cv::Mat padded;  // the section's edge is not a stone's edge: pad with stone
    cv::copyMakeBorder(stones, padded, 1, 1, 1, 1, cv::BORDER_REPLICATE);
    cv::Mat distance;
    cv::distanceTransform(padded, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    distance = distance(cv::Rect(1, 1, stones.cols, stones.rows)).clone();
    cv::Mat seeds = s.separate_stones ? detail::deep_maxima(distance, static_cast<float>(s.separation_depth_mm / px))
                                      : stones.clone();
    const int found = cv::connectedComponents(seeds, markers, 8, CV_32S) - 1;
    if (s.separate_stones && found > 1) {
      detail::flood_by_levels(distance, stones, markers);
      detail::split_at_concavities(markers, s.separation_depth_mm / px);
    } else if (s.separate_stones) {
      markers = cv::Mat();
      cv::connectedComponents(stones, markers, 8, CV_32S);
    }
    markers.setTo(0, ~stones);
  }
  // Relabel the stones 0 .. N-1 in scan order, dropping those below the smallest size.
  double most = 0.0;
  cv::minMaxLoc(markers, nullptr, &most);
  std::vector<long> pixels(static_cast<std::size_t>(most) + 1, 0);
  for (int r = 0; r < markers.rows; ++r)
    for (int c = 0; c < markers.cols; ++c) {
      const int m = markers.at<int>(r, c);
      if (m > 0) ++pixels[m];
    }
  std::vector<int> index(pixels.size(), -1);
  const double least_area = M_PI * 0.25 * s.smallest_stone_mm * s.smallest_stone_mm / (px * px);
  for (int r = 0; r < markers.rows; ++r)
    for (int c = 0; c < markers.cols; ++c) {
      const int m = markers.at<int>(r, c);
      if (m <= 0 || labels.at<int>(r, c) == -2) continue;
      if (index[m] == -1) {
        if (pixels[m] < least_area) {
          index[m] = -3;  // too small: mastic
          ++out.stones_dropped;
        } else {
          index[m] = count++;
          out.stone_area_mm2.push_back(0.0);
        }
      }
      if (index[m] >= 0) labels.at<int>(r, c) = index[m], out.stone_area_mm2[index[m]] += px * px;
    }
  out.labels = labels;
  const double total = static_cast<double>(image.total());
  out.fraction[static_cast<int>(ImagePhase::air_void)] = cv::countNonZero(labels == -2) / total;
  out.fraction[static_cast<int>(ImagePhase::mastic)] = cv::countNonZero(labels == -1) / total;
  out.fraction[static_cast<int>(ImagePhase::stone)] = cv::countNonZero(labels >= 0) / total;
  // No stone large enough: a wrong scale, or (from grey levels) phases in
  // the wrong order, such as bright voids read as the stones under the
  // default void,mastic,stone, where only small bright specks are found.
  if (count == 0)
    throw std::invalid_argument(
        "no stone of " + detail::mm_text(s.smallest_stone_mm) + " mm or more in the image (" +
        std::to_string(out.stones_dropped) + " smaller ones taken as mastic): is the scale right (" +
        detail::mm_text(px) + " mm per pixel)?" +
        (s.label_image ? std::string()
                       : " Are the phases from dark to bright " + detail::phases_text(s.order) +
                             "? If not, give their order with --phases (bright voids: --phases mastic,stone,void, "
                             "say)"));
  return out;
}

// Each stone's outline, in mm with y up, counter-clockwise: its outer
// contour through the centres of its edge pixels, widened by half a pixel
// (so that its area is the pixels' area to about a pixel's perimeter).
inline std::vector<Aggregate> stone_outlines(const SegmentedImage& seg) {
  const double px = seg.mm_per_pixel, height = seg.height_mm();
  std::vector<Aggregate> out(seg.stone_area_mm2.size());
  // One pass per stone would be N full scans; the bounding boxes keep it local.
  std::vector<std::array<int, 4>> ext(out.size(), {1 << 30, 1 << 30, -1, -1});
  for (int r = 0; r < seg.labels.rows; ++r)
    for (int c = 0; c < seg.labels.cols; ++c) {
      const int k = seg.labels.at<int>(r, c);
      if (k < 0) continue;
      auto& e = ext[k];
      e[0] = std::min(e[0], c), e[1] = std::min(e[1], r), e[2] = std::max(e[2], c), e[3] = std::max(e[3], r);
    }
  for (std::size_t k = 0; k < out.size(); ++k) {
    const auto& e = ext[k];
    const cv::Rect roi(e[0], e[1], e[2] - e[0] + 1, e[3] - e[1] + 1);
    cv::Mat mask = seg.labels(roi) == static_cast<int>(k), padded;
    cv::copyMakeBorder(mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(padded, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    std::size_t largest = 0;
    for (std::size_t i = 1; i < contours.size(); ++i)
      if (cv::contourArea(contours[i]) > cv::contourArea(contours[largest])) largest = i;
    std::vector<cv::Point> simple;
    cv::approxPolyDP(contours[largest], simple, 0.5, true);
    if (simple.size() < 3) simple = contours[largest];
    Polygon poly;
    for (const cv::Point& p : simple)
      poly.vertices.emplace_back((p.x - 1 + roi.x + 0.5) * px, height - (p.y - 1 + roi.y + 0.5) * px);
    if (poly.area() < 0.0) std::reverse(poly.vertices.begin(), poly.vertices.end());
    // Half a pixel outwards, along each vertex's direction from the centroid.
    Point centre(0, 0);
    for (const Point& v : poly.vertices) centre += v / static_cast<double>(poly.vertices.size());
    for (Point& v : poly.vertices) {
      const Point d = v - centre;
      const double len = d.norm();
      if (len > 0) v += 0.5 * px * d / len;
    }
    out[k].polygon = poly;
    out[k].area = seg.stone_area_mm2[k];
    out[k].diameter = std::sqrt(4.0 * out[k].area / M_PI);
    out[k].size_class = -1;
  }
  return out;
}

// The specimen: the section is the image's, each stone one aggregate, the
// disks by the phase under their centres. `name` names it in messages.
inline Specimen specimen_from_segmented(const SegmentedImage& seg, const ImageSettings& s, const std::string& name) {
  Specimen sp;
  sp.width = seg.width_mm();
  sp.height = seg.height_mm();
  sp.name = name;
  sp.settings.placement.width = sp.width;
  sp.settings.placement.height = sp.height;
  sp.settings.disk_radius = s.disk_radius;
  sp.settings.air_voids = s.air_voids;
  sp.settings.seed = s.seed;
  sp.placement.aggregates = stone_outlines(seg);
  sp.placement.achieved_fraction = seg.fraction[static_cast<int>(ImagePhase::stone)];
  sp.placement.target_fraction = sp.placement.achieved_fraction;
  const double px = seg.mm_per_pixel;
  const int n = static_cast<int>(s.order.size());
  auto site_of = [&](const Point& c) {
    const int col = std::clamp(static_cast<int>(c.x() / px), 0, seg.labels.cols - 1);
    const int row = std::clamp(static_cast<int>((sp.height - c.y()) / px), 0, seg.labels.rows - 1);
    const int l = seg.labels.at<int>(row, col);
    if (s.label_image) return l >= 0 ? l : l == -2 ? void_site : mastic_site;
    // A grey image: the phase at the centre itself, from the grey level
    // interpolated between the four nearest pixels' centres. An edge pixel's
    // grey is the mix of the phases it covers, so this places an edge to a
    // fraction of a pixel, where the pixel's own phase places it to a pixel.
    const double gx = std::clamp(c.x() / px - 0.5, 0.0, seg.grey.cols - 1.0);
    const double gy = std::clamp((sp.height - c.y()) / px - 0.5, 0.0, seg.grey.rows - 1.0);
    const int x0 = std::min(static_cast<int>(gx), seg.grey.cols - 2), y0 = std::min(static_cast<int>(gy), seg.grey.rows - 2);
    const double fx = gx - x0, fy = gy - y0;
    auto g = [&](int dy, int dx) { return static_cast<double>(seg.grey.at<std::uint8_t>(y0 + dy, x0 + dx)); };
    const double grey = (1 - fy) * ((1 - fx) * g(0, 0) + fx * g(0, 1)) + fy * ((1 - fx) * g(1, 0) + fx * g(1, 1));
    const int k = (grey >= seg.thresholds[0]) + (n == 3 && grey >= seg.thresholds[1]);
    const ImagePhase phase = s.order[k];
    if (phase == ImagePhase::air_void) return void_site;
    if (phase == ImagePhase::mastic) return mastic_site;
    if (l >= 0) return l;
    // Stone at the centre, in a pixel that is not: the stone of the nearest
    // of the four pixels that is one (none: a stone too small to keep).
    int best = mastic_site;
    double nearest = 1e9;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const int m = seg.labels.at<int>(y0 + dy, x0 + dx);
        const double d = std::hypot(gx - x0 - dx, gy - y0 - dy);
        if (m >= 0 && d < nearest) nearest = d, best = m;
      }
    return best;
  };
  std::mt19937_64 voids_rng(s.seed ^ 0x9e3779b97f4a7c15ULL);
  sp.disks = pack_disks_by(site_of, sp.width, sp.height, s.disk_radius, s.air_voids, voids_rng);
  return sp;
}

inline Specimen specimen_from_image(const std::string& path, const ImageSettings& s) {
  const SegmentedImage seg = segment_image(read_section_image(path, s.label_image), s);
  return specimen_from_segmented(seg, s, "image " + path);
}

}  // namespace vrut
