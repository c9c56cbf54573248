#pragma once
// The steps of segmenting a section image (specimen/image.hpp), each a
// function of its own: the phases' names, Otsu's thresholds for three
// classes, morphological reconstruction and the h-maxima of the distance
// (one marker per stone), the flood of the markers by distance levels, and
// the split of touching stones between the concave corners of their
// outline. Host-only; needs OpenCV (core, imgproc).
#include <vrut/specimen/image_settings.hpp>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

namespace detail {

inline const char* phase_name(ImagePhase p) {
  return p == ImagePhase::stone ? "stone" : p == ImagePhase::mastic ? "mastic" : "void";
}

// The phases' order as --phases takes it: "void,mastic,stone".
inline std::string phases_text(const std::vector<ImagePhase>& order) {
  std::string text;
  for (ImagePhase p : order) text += (text.empty() ? "" : ",") + std::string(phase_name(p));
  return text;
}

// A length as a person writes it, in its shortest form: 2.36, 0.1, 1 (not
// std::to_string's 2.360000).
inline std::string mm_text(double mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", mm);
  return text;
}

// Otsu's criterion for three classes: the two thresholds t1 < t2 (class 0 is
// g < t1, class 1 t1 <= g < t2, class 2 g >= t2) that maximise the variance
// between the classes' means. OpenCV's THRESH_OTSU splits in two only.
inline std::array<int, 2> otsu_three_classes(const cv::Mat& grey) {
  std::array<double, 256> p{};
  for (int r = 0; r < grey.rows; ++r)
    for (int c = 0; c < grey.cols; ++c) p[grey.at<std::uint8_t>(r, c)] += 1.0;
  std::array<double, 257> w{}, m{};  // cumulative weight and first moment below g
  for (int g = 0; g < 256; ++g) w[g + 1] = w[g] + p[g], m[g + 1] = m[g] + g * p[g];
  double best = -1.0;
  std::array<int, 2> t{1, 2};
  for (int t1 = 1; t1 < 255; ++t1)
    for (int t2 = t1 + 1; t2 < 256; ++t2) {
      const double w0 = w[t1], w1 = w[t2] - w[t1], w2 = w[256] - w[t2];
      if (w0 <= 0 || w1 <= 0 || w2 <= 0) continue;
      const double m0 = m[t1], m1 = m[t2] - m[t1], m2 = m[256] - m[t2];
      const double between = m0 * m0 / w0 + m1 * m1 / w1 + m2 * m2 / w2;  // + a constant
      if (between > best) best = between, t = {t1, t2};
    }
  return t;
}

// Morphological reconstruction by dilation of `marker` under `mask`.
inline cv::Mat reconstruct(cv::Mat marker, const cv::Mat& mask) {
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  cv::Mat next;
  for (;;) {
    cv::dilate(marker, next, square);
    cv::min(next, mask, next);
    if (cv::norm(next, marker, cv::NORM_INF) == 0.0) return marker;
    std::swap(marker, next);  // two buffers: dilate cannot work in place
  }
}

// The extended maxima of a distance map: the regional maxima of its
// h-maxima transform HMAX = reconstruction of (d - h) under d, that is the
// tops of the maxima deeper than h, each one connected region.
inline cv::Mat deep_maxima(const cv::Mat& distance, float h) {
  const cv::Mat hmax = reconstruct(distance - h, distance);
  const float step = 1e-3f;  // far below a pixel's distance steps, far above float rounding
  const cv::Mat below = reconstruct(hmax - step, hmax);
  cv::Mat mask;
  cv::compare(hmax - below, 0.5f * step, mask, cv::CMP_GE);
  mask.setTo(0, distance <= 0);
  return mask;
}

// The watershed of the distance map, by immersion: from the markers (the
// deep maxima), every stone pixel is flooded level by level, from the
// largest distance down, by the marker it first connects to at its level;
// two floods meet on the saddles of the distance, the necks between stones.
// (cv::watershed orders its flooding by the grey step between neighbours,
// not by level, so from markers at the maxima its lines fall near the
// smaller stone's centre, not at the neck.) Levels every half pixel; each
// level grown by 3 x 3 dilations of the labels until no pixel is added.
inline void flood_by_levels(const cv::Mat& distance, const cv::Mat& stones, cv::Mat& markers) {
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  cv::Mat labels, grown, open_now, added;
  markers.convertTo(labels, CV_32F);  // labels dilate as float, exact to 2^24
  double top = 0.0;
  cv::minMaxLoc(distance, nullptr, &top);
  for (double level = top; level > -0.25; level -= 0.5) {
    const cv::Mat reachable = (distance >= level) & stones;
    for (;;) {
      cv::dilate(labels, grown, square);
      open_now = reachable & (labels == 0) & (grown > 0);
      if (cv::countNonZero(open_now) == 0) break;
      grown.copyTo(labels, open_now);
    }
  }
  labels.convertTo(markers, CV_32S);
}

// Where a small stone presses on a large one along a wide contact, the
// distance's saddle lies inside the small stone, not at the contact, and the
// flood gives the large stone a cap of the small one. The contact itself
// shows in the outline of the two stones together: it runs between two
// concave corners (convexity defects of the pair's outline). So each pair of
// touching regions is split again along the straight line between the
// defects nearest the two ends of their flooded boundary, where both exist,
// are at least `least_depth` pixels deep, and the line lies inside the pair.
// Only the pair's own pixels near that line (over its length, and as far to
// either side as it is long) change hands.
inline void split_at_concavities(cv::Mat& markers, double least_depth) {
  struct Pair {
    std::vector<cv::Point2f> boundary;  // midpoints between the two regions' 4-adjacent pixels
  };
  std::map<std::pair<int, int>, Pair> pairs;
  int most = 0;
  for (int r = 0; r < markers.rows; ++r)
    for (int c = 0; c < markers.cols; ++c) {
      const int a = markers.at<int>(r, c);
      most = std::max(most, a);
      if (a <= 0) continue;
      if (c + 1 < markers.cols) {
        const int b = markers.at<int>(r, c + 1);
        if (b > 0 && b != a) pairs[{std::min(a, b), std::max(a, b)}].boundary.emplace_back(c + 0.5f, static_cast<float>(r));
      }
      if (r + 1 < markers.rows) {
        const int b = markers.at<int>(r + 1, c);
        if (b > 0 && b != a) pairs[{std::min(a, b), std::max(a, b)}].boundary.emplace_back(static_cast<float>(c), r + 0.5f);
      }
    }
  // Each region's bounding box, kept a superset as pixels change hands.
  std::vector<cv::Rect> box(static_cast<std::size_t>(most) + 1);
  for (int r = 0; r < markers.rows; ++r)
    for (int c = 0; c < markers.cols; ++c) {
      const int a = markers.at<int>(r, c);
      if (a > 0) box[a] = box[a].area() ? box[a] | cv::Rect(c, r, 1, 1) : cv::Rect(c, r, 1, 1);
    }
  for (const auto& [ab, pair] : pairs) {
    const int a = ab.first, b = ab.second;
    // The two ends of the flooded boundary: its extremes along its own axis.
    cv::PCA axis(cv::Mat(pair.boundary).reshape(1), cv::Mat(), cv::PCA::DATA_AS_ROW);
    const cv::Point2f mean(axis.mean.at<float>(0), axis.mean.at<float>(1));
    const cv::Point2f dir(axis.eigenvectors.at<float>(0, 0), axis.eigenvectors.at<float>(0, 1));
    cv::Point2f ends[2] = {mean, mean};
    float lo = 0.0f, hi = 0.0f;
    for (const auto& p : pair.boundary) {
      const float t = (p - mean).dot(dir);
      if (t < lo) lo = t, ends[0] = p;
      if (t > hi) hi = t, ends[1] = p;
    }
    const float length = hi - lo;
    // The pair's outline and its concave corners.
    const cv::Rect roi = box[a] | box[b];
    cv::Mat both = (markers(roi) == a) | (markers(roi) == b), padded;
    cv::copyMakeBorder(both, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(padded, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    if (contours.empty()) continue;
    std::size_t largest = 0;
    for (std::size_t i = 1; i < contours.size(); ++i)
      if (contours[i].size() > contours[largest].size()) largest = i;
    const auto& outline = contours[largest];
    if (outline.size() < 4) continue;
    std::vector<int> hull;
    cv::convexHull(outline, hull, true, false);
    if (hull.size() < 3) continue;
    std::vector<cv::Vec4i> defects;
    try {
      cv::convexityDefects(outline, hull, defects);
    } catch (const cv::Exception&) {
      continue;  // a self-touching outline: leave the flood's split
    }
    // The deepest defect near each end (within half the boundary's length
    // and three pixels).
    const cv::Point2f offset(roi.x - 1.0f, roi.y - 1.0f);
    const float reach = 0.5f * length + 3.0f;
    cv::Point2f corner[2];
    bool found[2] = {false, false};
    float depth[2] = {0.0f, 0.0f};
    for (const auto& d : defects) {
      const float deep = d[3] / 256.0f;
      if (deep < least_depth) continue;
      const cv::Point2f p = cv::Point2f(outline[d[2]]) + offset;
      for (int e = 0; e < 2; ++e)
        if (cv::norm(p - ends[e]) <= reach && deep > depth[e]) corner[e] = p, depth[e] = deep, found[e] = true;
    }
    if (!found[0] || !found[1]) continue;
    const cv::Point2f line = corner[1] - corner[0];
    const float span = static_cast<float>(cv::norm(line));
    if (span < 1.0f) continue;
    // The line must run inside the pair: its points a or b.
    bool inside = true;
    for (int k = 1; k < static_cast<int>(span) && inside; ++k) {
      const cv::Point2f p = corner[0] + line * (k / span);
      const int v = markers.at<int>(cvRound(p.y), cvRound(p.x));
      inside = v == a || v == b;
    }
    if (!inside) continue;
    // Which side is whose: the side where most of each region's pixels near the line lie.
    const cv::Point2f unit = line / span, normal(-unit.y, unit.x);
    auto near_line = [&](int r, int c, float& side) {
      const cv::Point2f q = cv::Point2f(static_cast<float>(c), static_cast<float>(r)) - corner[0];
      const float along = q.dot(unit);
      side = q.dot(normal);
      return along >= 0.0f && along <= span && std::abs(side) <= span;
    };
    long votes[2] = {0, 0};  // a's pixels on the positive side minus the negative, b's likewise
    for (int r = roi.y; r < roi.y + roi.height; ++r)
      for (int c = roi.x; c < roi.x + roi.width; ++c) {
        const int v = markers.at<int>(r, c);
        float side = 0.0f;
        if ((v == a || v == b) && near_line(r, c, side) && side != 0.0f) votes[v == b] += side > 0.0f ? 1 : -1;
      }
    if ((votes[0] > 0) == (votes[1] > 0) || votes[0] == 0 || votes[1] == 0) continue;
    const int positive = votes[0] > 0 ? a : b, negative = positive == a ? b : a;
    for (int r = roi.y; r < roi.y + roi.height; ++r)
      for (int c = roi.x; c < roi.x + roi.width; ++c) {
        int& v = markers.at<int>(r, c);
        float side = 0.0f;
        if ((v == a || v == b) && near_line(r, c, side) && side != 0.0f) v = side > 0.0f ? positive : negative;
      }
    box[a] = box[b] = box[a] | box[b];
  }
}

}  // namespace detail

}  // namespace vrut
