#pragma once
// What reading a specimen from an image takes (specimen/image.hpp does the
// reading, with OpenCV): the phases' order, the scale, the thresholds. Kept
// apart so that a program built without OpenCV (VRUT_IMAGES=OFF) still knows
// the options. Host-only; mm.
#include <cstdint>
#include <vector>

namespace vrut {

enum class ImagePhase { air_void, mastic, stone };

struct ImageSettings {
  double mm_per_pixel = 0.0;  // the scale; or 0 and ...
  double width_mm = 0.0;      // ... the section's width, the scale from the image's
  // The phases from dark to bright: 2 or 3 of them, each once.
  std::vector<ImagePhase> order = {ImagePhase::air_void, ImagePhase::mastic, ImagePhase::stone};
  // Grey levels (0-255) where a phase begins, counted from the mastic's side
  // in `order`; -1: Otsu's.
  int stone_threshold = -1, void_threshold = -1;
  bool label_image = false;  // 0 mastic, each other value one stone
  int void_label = -1;       // in a label image, the voids' value (-1: none)
  bool separate_stones = true;
  double separation_depth_mm = 0.3;   // see 2. above
  double smallest_stone_mm = 2.36;    // equivalent diameter below which a stone is mastic
  double disk_radius = 0.5;           // mm
  double air_voids = 0.0;             // added at random in the mastic, besides the image's own
  std::uint64_t seed = 1;             // for those random voids
};

}  // namespace vrut
