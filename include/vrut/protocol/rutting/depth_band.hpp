#pragma once
// Where a 3D plate lies across the box's periodic depth: all of it (a strip,
// the model's), or a band about the box's middle (a patch, test.hpp's
// WheelTracking::patch). A 2D section has no depth: every particle lies in it.
#include <vrut/data/vec2.hpp>
#include <vrut/data/vec3.hpp>

#include <cmath>

namespace vrut {

struct DepthBand {
  double centre = 0.0, half = 0.0, period = 0.0;  // m; half 0: the whole depth

  // Whether depth z (m, a particle's continuous path: not wrapped) lies within
  // `margin` of the band, through the nearest periodic image.
  bool contains(double z, double margin = 0.0) const {
    if (!(half > 0.0)) return true;
    double s = z - centre;
    s -= period * std::floor(s / period + 0.5);
    return std::abs(s) <= half + margin;
  }
};

inline bool in_depth_band(const DepthBand&, const Vec2&, double = 0.0) { return true; }
inline bool in_depth_band(const DepthBand& band, const Vec3& x, double margin = 0.0) {
  return band.contains(x.z, margin);
}

// Whether a particle (its continuous path, radius r) lies within the band
// only through a periodic image: under a patch's image, which a plate (a
// wall, seeing the continuous path) does not hold.
inline bool in_band_image_only(const DepthBand&, const Vec2&, double) { return false; }
inline bool in_band_image_only(const DepthBand& band, const Vec3& x, double r) {
  return band.half > 0.0 && band.contains(x.z, r) && !(std::abs(x.z - band.centre) <= band.half + r);
}

}  // namespace vrut
