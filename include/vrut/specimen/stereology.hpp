#pragma once
// From a mass gradation to the 2D quantity gradation of a section, docs/method.md
// sections 2 and 3. Host-only; lengths in mm.
//
// Coarse aggregate (retained on the coarse limit, 2.36 mm) in sieve classes
// [D_i, D_i+1); each class taken as spheres of the mean diameter,
// R_i = (D_i + D_i+1)/4. The volume fraction of class i in the mix follows
// from the mass gradation and the volumetrics (equal densities within the
// aggregate):  P_i = G_mb (1 - AC) / G_sb * (pass(D_i+1) - pass(D_i)) / 100,
// N_V,i = P_i / V_i,  V_i = pi (D_i + D_i+1)^3 / 48.
// A plane cuts a sphere whose centre lies within R of it; the section radius
// is sqrt(R^2 - h^2), h uniform in [0, R]. Sections per unit area with
// radius in [r_j, r_j+1):
//   N_A,j = 2 sum_i N_V,i ( sqrt(R_i^2 - r_j^2) - sqrt(R_i^2 - r_j+1^2) ),
// a negative square root counting as 0.
#include <vrut/specimen/gradation.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct MixVolumetrics {
  double asphalt_content = 0.048;            // mass fraction of the mix
  double aggregate_specific_gravity = 2.70;  // G_sb
  double mix_specific_gravity = 2.40;        // G_mb
  double coarse_limit_mm = 2.36;

  void validate() const {
    if (!(asphalt_content >= 0.0 && asphalt_content < 1.0))
      throw std::invalid_argument("asphalt content must lie in [0, 1) (a mass fraction), got " +
                                  std::to_string(asphalt_content));
    if (!(aggregate_specific_gravity > 0.0) || !(mix_specific_gravity > 0.0))
      throw std::invalid_argument("specific gravities must be positive");
    if (!(coarse_limit_mm > 0.0)) throw std::invalid_argument("the coarse limit must be positive");
  }
};

struct SizeClass {
  double lower_mm = 0.0, upper_mm = 0.0;
  double mean_radius() const { return 0.25 * (lower_mm + upper_mm); }
};

struct Stereology {
  std::vector<SizeClass> classes;           // coarse classes, ascending
  std::vector<double> volume_fraction;      // P_i, of the mix
  std::vector<double> number_per_volume;    // N_V,i, 1/mm^3
  std::vector<double> sections_per_area;    // N_A,j, 1/mm^2, same classes (sections >= the limit)
  double fine_sections_per_area = 0.0;      // sections below the limit (they go to the mastic)
  double coarse_volume_fraction = 0.0;      // sum of P_i
  double target_area_fraction = 0.0;        // area of sections >= the limit per unit section area

  // Percent passing by number among the sections >= the limit, at each class bound (descending).
  std::vector<std::pair<double, double>> quantity_gradation() const {
    double total = 0.0;
    for (double n : sections_per_area) total += n;
    std::vector<std::pair<double, double>> out;
    double below = total;
    for (std::size_t j = classes.size(); j-- > 0;) {
      out.emplace_back(classes[j].upper_mm, 100.0 * below / total);
      below -= sections_per_area[j];
    }
    out.emplace_back(classes.front().lower_mm, 0.0);
    return out;
  }
};

namespace detail {
inline double root_or_zero(double x) { return x > 0.0 ? std::sqrt(x) : 0.0; }
}  // namespace detail

// Sections per unit area of spheres of radius R, number density nv, with radius in [r0, r1).
inline double sections_in_range(double nv, double R, double r0, double r1) {
  return 2.0 * nv * (detail::root_or_zero(R * R - r0 * r0) - detail::root_or_zero(R * R - r1 * r1));
}

inline Stereology stereology(const Gradation& g, const MixVolumetrics& mix) {
  mix.validate();
  const double limit = mix.coarse_limit_mm;
  if (!(g.sieve_mm.front() > limit))
    throw std::invalid_argument("gradation " + g.name + " has no aggregate above the coarse limit");
  // Found by fuzzing: without a sieve at or below the limit the coarse
  // fraction is unknown (it surfaced as an out-of-range error deep inside).
  if (!(g.sieve_mm.back() <= limit))
    throw std::invalid_argument("gradation " + g.name + " must reach the " + std::to_string(limit) +
                                " mm sieve (coarse aggregate is everything retained on it): its smallest sieve is " +
                                std::to_string(g.sieve_mm.back()) + " mm");
  std::vector<double> bounds;  // ascending: limit, then every sieve above it
  bounds.push_back(limit);
  for (std::size_t i = g.sieve_mm.size(); i-- > 0;)
    if (g.sieve_mm[i] > limit) bounds.push_back(g.sieve_mm[i]);

  Stereology s;
  const double scale = mix.mix_specific_gravity * (1.0 - mix.asphalt_content) / mix.aggregate_specific_gravity;
  for (std::size_t i = 0; i + 1 < bounds.size(); ++i) {
    const SizeClass c{bounds[i], bounds[i + 1]};
    const double p = scale * (g.passing_at(c.upper_mm) - g.passing_at(c.lower_mm)) / 100.0;
    const double v = M_PI * std::pow(c.lower_mm + c.upper_mm, 3) / 48.0;
    s.classes.push_back(c);
    s.volume_fraction.push_back(p);
    s.number_per_volume.push_back(p / v);
    s.coarse_volume_fraction += p;
  }
  // Refused rather than run: with nothing retained on the coarse limit the
  // section has no stone, and the rutting model is a skeleton of stones in
  // mastic. A pure mastic is what the creep test (vrut-creep) models.
  if (!(s.coarse_volume_fraction > 0.0))
    throw std::invalid_argument("gradation " + g.name + " retains nothing on the " + std::to_string(limit) +
                                " mm sieve (it all passes): it has no stones to place, and the virtual rutting "
                                "test needs a skeleton of stones in mastic; a mastic alone is vrut-creep's test");
  for (const SizeClass& sec : s.classes) {
    double n = 0.0;
    for (std::size_t i = 0; i < s.classes.size(); ++i)
      n += sections_in_range(s.number_per_volume[i], s.classes[i].mean_radius(), 0.5 * sec.lower_mm,
                             0.5 * sec.upper_mm);
    s.sections_per_area.push_back(n);
  }
  for (std::size_t i = 0; i < s.classes.size(); ++i) {
    const double R = s.classes[i].mean_radius(), r = 0.5 * limit;
    s.fine_sections_per_area += sections_in_range(s.number_per_volume[i], R, 0.0, r);
    // Area of the sections with radius >= r: 2 N_V pi int_0^h0 (R^2 - h^2) dh, h0 = sqrt(R^2 - r^2).
    const double h0 = detail::root_or_zero(R * R - r * r);
    s.target_area_fraction += 2.0 * s.number_per_volume[i] * M_PI * (R * R * h0 - h0 * h0 * h0 / 3.0);
  }
  return s;
}

}  // namespace vrut
