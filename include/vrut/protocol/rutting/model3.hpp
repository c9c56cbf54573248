#pragma once
// The frozen 3D model (docs/validation.md, "The frozen 3D model"): what
// vrut-rutting --dim 3 runs at its defaults, for a program of its own. RuttingMaterials' values but three:
//   - the mastic-aggregate factor 1, the source's own (the 2D
//     calibration's 4 held only at 1.5 mm spheres);
//   - the stones' friction 0.6, the model's one constant, fitted on 2#'s
//     eight specimens at 1 mm spheres (two stones meet at points, through
//     binder; the 2D model's 1.0 was chosen for a section's lines);
//   - each mix's mastic stiffened by its filler over 2#'s, the mix the
//     mastic was calibrated on, at Rigden voids 0.35 (within EN 13043's
//     28 to 45 %, where the scale hardly moves; no fit:
//     specimen/filler_mastic.hpp).
// Its runs' numerics are RuttingNumerics with the 3D test's step safety,
// timestep_safety_3d (loading.hpp), as vrut-rutting --dim 3 runs them; the
// library's default 0.3 gives the same answer in more steps.
// The 3D model before it is RuttingMaterials with the factor 1 (its stones'
// friction that of the mastic, one mastic for every mix), which
// tests/test_rutting3.cpp's first pins hold.
// Host-only.
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/specimen/filler_mastic.hpp>
#include <vrut/specimen/gradation.hpp>
#include <vrut/specimen/stereology.hpp>

namespace vrut {

struct RuttingModel3 {
  static constexpr double mastic_aggregate_factor = 1.0;
  static constexpr double stone_friction = 0.6;
  static constexpr double filler_rigden_voids = 0.35;
  static constexpr int calibration_mix = 2;  // the built-in gradation the mastic and the friction were fitted on
};

// The frozen 3D model's materials for a mix of this gradation and these
// volumetrics; `base` gives everything the model does not set (the mastic
// before its filler's scale, the stones' modulus, the wall).
inline RuttingMaterials rutting_model3_materials(const Gradation& mix_gradation, const MixVolumetrics& mix,
                                                 RuttingMaterials base = {}) {
  base.mastic_aggregate_factor = RuttingModel3::mastic_aggregate_factor;
  base.stone_friction = RuttingModel3::stone_friction;
  scale_mastic(base, mastic_scale_by_filler(mix_gradation, builtin_gradation(RuttingModel3::calibration_mix), mix,
                                            RuttingModel3::filler_rigden_voids));
  return base;
}

}  // namespace vrut
