#pragma once
// The binder film's thickness of a mix, from its gradation and volumetrics,
// as mix design works it out (the Asphalt Institute's MS-2, "Asphalt Mix
// Design Methods"): the aggregate's surface area from the surface area
// factors of the sieves, and the effective binder spread over it:
//   SA = sum over the sieves of P_i / 100 F_i   (m^2 per kg of aggregate),
//   T  = P_be / (P_s G_b SA) 1000               (micrometres),
// P_i the percent passing sieve i, F_i its factor (0.41 for the total, then
// 0.41 at 4.75 mm, 0.82 at 2.36, 1.64 at 1.18, 2.87 at 0.600, 6.14 at
// 0.300, 12.29 at 0.150 and 32.77 at 0.075 mm); P_be the effective binder
// and P_s the aggregate, percent by mass of the mix; G_b the binder's
// specific gravity.
//
// Assumptions (the source gives neither):
//   - the gradation below 2.36 mm (below its smallest sieve, where a table
//     gives finer ones) follows the 0.45-power maximum-density line through
//     that sieve's point, down to 0.075 mm (specimen/fine_gradation.hpp);
//   - no binder is absorbed into the stones (P_be = the asphalt content),
//     and G_b = 1.03.
// Host-only; mm, micrometres.
#include <vrut/specimen/fine_gradation.hpp>
#include <vrut/specimen/gradation.hpp>
#include <vrut/specimen/stereology.hpp>

#include <array>
#include <cmath>
#include <stdexcept>

namespace vrut {

struct BinderFilm {
  static constexpr std::array<double, 7> sieve_mm{4.75, 2.36, 1.18, 0.600, 0.300, 0.150, 0.075};
  static constexpr std::array<double, 7> factor{0.41, 0.82, 1.64, 2.87, 6.14, 12.29, 32.77};  // m^2/kg
  static constexpr double total_factor = 0.41;
  std::array<double, 7> passing{};      // percent, at sieve_mm
  double surface_area = 0.0;            // m^2 per kg of aggregate
  double thickness_um = 0.0;            // of the film on one stone
};

inline BinderFilm binder_film(const Gradation& g, const MixVolumetrics& mix, double binder_specific_gravity = 1.03,
                              double absorbed_binder = 0.0 /* mass fraction of the mix */) {
  mix.validate();
  if (!(binder_specific_gravity > 0.0)) throw std::invalid_argument("the binder's specific gravity must be positive");
  const double effective = mix.asphalt_content - absorbed_binder;
  if (!(effective > 0.0)) throw std::invalid_argument("the binder film needs some effective binder");
  BinderFilm f;
  f.surface_area = BinderFilm::total_factor;
  for (std::size_t i = 0; i < f.sieve_mm.size(); ++i) {
    f.passing[i] = fine_passing_percent(g, f.sieve_mm[i]);  // below 2.36 mm, the 0.45-power line
    f.surface_area += f.passing[i] / 100.0 * f.factor[i];
  }
  const double binder_percent = 100.0 * effective, aggregate_percent = 100.0 * (1.0 - mix.asphalt_content);
  f.thickness_um = binder_percent / (aggregate_percent * binder_specific_gravity * f.surface_area) * 1000.0;
  return f;
}

}  // namespace vrut
