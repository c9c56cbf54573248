#pragma once
// The filler's stiffening of the binder, by mix: part of the frozen 3D
// model (protocol/rutting/model3.hpp), not of the 2D
// model; screened as a candidate (docs/studies/2026-12-05-mastic-by-mix.md).
//
// The method gives every mix one mastic. At one binder content a mix with
// more filler (passing 0.075 mm) has a stiffer mastic: the filler is a
// suspension in the binder, and under rigid grains every modulus and
// viscosity of a suspension scales by one factor (the correspondence
// principle), Krieger-Dougherty's
//   f(phi) = (1 - phi / phi_m)^(-2.5 phi_m),
// phi = V_filler / (V_filler + V_binder), phi_m the dry-compacted filler's
// packing, 1 - its Rigden voids (EN 1097-4). The mastic's Burger's values
// are those of the calibration mix (2#), so a mix's mastic is scaled by
// f(phi_mix) / f(phi_calibration).
//
// Only the filler: the fines between 0.075 and 2.36 mm of 1# and 2# fill
// their mastic about as full as a compacted aggregate packs, a mortar whose
// grains touch, where no suspension law holds.
//
// Assumptions: the filler's specific gravity is the aggregate's; no binder
// is absorbed (as specimen/binder_film.hpp); a gradation that stops above
// 0.075 mm goes on along the 0.45-power line (specimen/fine_gradation.hpp).
// Host-only.
#include <vrut/specimen/fine_gradation.hpp>
#include <vrut/specimen/gradation.hpp>
#include <vrut/specimen/stereology.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vrut {

struct FillerMastic {
  double filler_percent = 0.0;  // passing 0.075 mm, percent of the aggregate's mass
  double phi = 0.0;             // the filler's volume fraction of the filler-binder mastic
  double phi_m = 0.0;           // its maximum packing, 1 - the Rigden voids
  double free_binder = 0.0;     // 1 - phi / phi_m; Anderson (1987): the grains stay apart from 0.3 up
  double stiffening = 0.0;      // f(phi), against the bare binder
};

// Krieger-Dougherty's relative viscosity (intrinsic viscosity 2.5, rigid
// spheres); phi in [0, phi_m).
inline double krieger_dougherty(double phi, double phi_m) {
  if (!(phi_m > 0.0 && phi_m <= 1.0)) throw std::invalid_argument("the maximum packing must lie in (0, 1]");
  if (!(phi >= 0.0 && phi < phi_m))
    throw std::invalid_argument("the filler's fraction " + std::to_string(phi) + " of the mastic reaches its maximum packing " +
                                std::to_string(phi_m) + ": the filler is jammed, not a suspension");
  return std::pow(1.0 - phi / phi_m, -2.5 * phi_m);
}

inline FillerMastic filler_mastic(double filler_percent, const MixVolumetrics& mix, double rigden_voids,
                                  double binder_specific_gravity = 1.03) {
  mix.validate();
  if (!(filler_percent >= 0.0 && filler_percent <= 100.0))
    throw std::invalid_argument("the filler content (passing 0.075 mm) must lie in [0, 100] percent of the aggregate");
  if (!(rigden_voids > 0.0 && rigden_voids < 1.0))
    throw std::invalid_argument("the Rigden voids must lie in (0, 1), a fraction of the dry-compacted filler");
  if (!(binder_specific_gravity > 0.0)) throw std::invalid_argument("the binder's specific gravity must be positive");
  if (!(mix.asphalt_content > 0.0)) throw std::invalid_argument("a mastic needs some binder");
  FillerMastic m;
  m.filler_percent = filler_percent;
  const double filler = (1.0 - mix.asphalt_content) * filler_percent / 100.0 / mix.aggregate_specific_gravity;
  const double binder = mix.asphalt_content / binder_specific_gravity;  // volumes per unit mass of mix
  m.phi = filler / (filler + binder);
  m.phi_m = 1.0 - rigden_voids;
  m.stiffening = krieger_dougherty(m.phi, m.phi_m);
  m.free_binder = 1.0 - m.phi / m.phi_m;
  return m;
}

// The factor on every Burger's constant of a mix's mastic: its filler's
// stiffening over the calibration mix's, at the same volumetrics and
// Rigden voids. Each mix's filler content is its gradation's at 0.075 mm.
inline double mastic_scale_by_filler(const Gradation& mix_gradation, const Gradation& calibration,
                                     const MixVolumetrics& mix, double rigden_voids) {
  const FillerMastic here = filler_mastic(fine_passing_percent(mix_gradation, 0.075), mix, rigden_voids);
  const FillerMastic there = filler_mastic(fine_passing_percent(calibration, 0.075), mix, rigden_voids);
  return here.stiffening / there.stiffening;
}

}  // namespace vrut
