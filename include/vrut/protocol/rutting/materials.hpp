#pragma once
// The rutting test's material model (docs/method.md sections 5 and 6): the
// laws, and which contact class meets which in the assignment table of a
// specimen's particles. The mix's materials and each class's micro
// parameters are material/contact_classes.hpp's.
#include <vrut/contact/choice.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/contact/film.hpp>
#include <vrut/core/assignment.hpp>
#include <vrut/material/burgers_parameters.hpp>
#include <vrut/material/contact_classes.hpp>
#include <vrut/specimen/specimen.hpp>
#include <vrut/specimen/stone_reach.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

using RuttingLaw = Choice<BurgersFilmBonded, DampedLinearBonded>;
using RuttingWallLaw = DampedLinear;

// A mix's mastic stiffer or softer by k (every Burger's constant times k:
// under rigid fillers a suspension's moduli and viscosities scale alike),
// and the rigid stones' contact ratio divided by k, so that the stones' and
// walls' spring (the ratio times the mastic's E1 t) stays where it was:
// only the mastic changes (specimen/filler_mastic.hpp).
inline void scale_mastic(RuttingMaterials& m, double k) {
  if (!(k > 0.0) || !std::isfinite(k)) throw std::invalid_argument("the mastic's scale must be positive and finite");
  m.mastic.E1 *= k, m.mastic.eta1 *= k, m.mastic.E2 *= k, m.mastic.eta2 *= k;
  m.stone_contact_ratio /= k;
}

// The contact table's group of a stone disk: each stone colour holds one
// group per reach bin where the film is per contact, one otherwise.
inline int stone_group(const RuttingMaterials& m, int colour, double reach) {
  if (!m.film_per_contact()) return aggregate_group + colour;
  return aggregate_group + colour * film_reach_classes + reach_class(reach, film_reach_classes);
}

// Each disk's group in the contact table: the mastic's, or its stone's
// (`colour`, one per aggregate, from colour_aggregates), and the bin of its
// reach where the film is per contact.
inline std::vector<int> rutting_groups(const Specimen& sp, const RuttingMaterials& m, const std::vector<int>& colour) {
  const std::size_t n = sp.disks.centers.size();
  const std::vector<double> reach = m.film_per_contact() ? stone_reach(sp.disks, sp.placement) : std::vector<double>(n, 0.0);
  std::vector<int> group(n, mastic_group);
  for (std::size_t i = 0; i < n; ++i)
    if (sp.disks.aggregate[i] >= 0) group[i] = stone_group(m, colour[sp.disks.aggregate[i]], reach[i]);
  return group;
}

// Rigid stones: each aggregate that holds a disk becomes one body, numbered
// in the aggregates' order; mastic disks are free (-1). (A stone too small
// to hold a disk's centre is mastic, as the method's packing has it.)
inline std::vector<int> stone_bodies(const Specimen& sp) {
  std::vector<int> body_of(sp.placement.aggregates.size(), -1), body(sp.disks.aggregate.size(), -1);
  for (int a : sp.disks.aggregate)
    if (a >= 0) body_of[a] = 0;
  int bodies = 0;
  for (int& b : body_of)
    if (b == 0) b = bodies++;
  for (std::size_t i = 0; i < body.size(); ++i)
    if (sp.disks.aggregate[i] >= 0) body[i] = body_of[sp.disks.aggregate[i]];
  return body;
}

// A table's scales (material/contact_classes.hpp, ContactScales): in 2D the
// disk width t for the mastic and the stones; in 3D the sphere diameter d
// for the mastic (the FCC rule carries the lattice's factor) and d / c for
// the stones (protocol/rutting/box.hpp). Its shift is the table's.
using RuttingTableScales = ContactScales;

// Group 0 is the mastic; the aggregates are groups 1 .. stone_colours, one
// per colour (specimen/colouring.hpp), so that the table can tell two stones
// from one; with the film per contact, one per colour and reach bin
// (stone_group). With one colour that is the method's two-group table.
// pairs_are_two_stones: every contact between two stone particles is one
// between two stones (rigid stones, whose members never touch, and no
// colours needed); the films then go between any two stone groups.
inline AssignmentTable<RuttingLaw> rutting_table_with(const RuttingMaterials& m, double shift,
                                                      const ContactScales& given, int stone_colours,
                                                      bool pairs_are_two_stones = false) {
  ContactScales scales = given;
  scales.shift = shift;
  const double disk_diameter = scales.diameter;
  const bool films = m.films();
  const int bins = m.film_per_contact() ? film_reach_classes : 1;
  AssignmentTable<RuttingLaw> table(1 + stone_colours * bins);
  table.set(mastic_group, mastic_group, RuttingLaw::make_first(mastic_mastic_params(m, scales)));
  const auto mastic_stone = RuttingLaw::make_first(mastic_stone_params(m, scales));
  const auto stone = RuttingLaw::make_second(stone_law_params(m, scales.stone_length, stone_friction_of(m)));
  if (films) {
    if (!m.film_per_contact() && !(m.film_gap > 0.0 && m.film_gap < 1.0))
      throw std::invalid_argument("the film between stones must be thinner than a disk and positive (film gap in (0, 1))");
    if (m.film_per_contact() && m.film_endless)
      throw std::invalid_argument("a film per contact is sized by where the stones touch: it cannot be endless");
    if (!(disk_diameter > 0.0)) throw std::invalid_argument("the film between stones needs the disk diameter");
  } else if (m.film_endless) {
    throw std::invalid_argument("an endless film is a film between stones: it needs the mean film (stone film 'mean')");
  }
  auto film = [&](double gap) { return RuttingLaw::make_first(stone_film_params(m, scales, gap)); };
  if (m.least_film != 0.0) {
    if (!(m.least_film > 0.0) || !std::isfinite(m.least_film))
      throw std::invalid_argument("the least film between stones must be positive, got " + std::to_string(m.least_film) + " m");
    if (!m.film_per_contact())
      throw std::invalid_argument("a least film between stones goes with the film per contact (stone film 'per-contact')");
    if (!(m.least_film < disk_diameter))
      throw std::invalid_argument("the least film between stones must be thinner than a particle's diameter");
  }
  const double least_gap = m.least_film > 0.0 ? m.least_film / disk_diameter : 0.0;  // diameters
  auto film_between_bins = [&](int p, int q) {
    return film(std::max(least_gap, 1.0 - reach_class_middle(p, bins) - reach_class_middle(q, bins)));
  };
  const auto mean_film = films && !m.film_per_contact() ? film(m.film_gap) : RuttingLaw::params_type{};
  for (int a = 1; a < table.groups(); ++a) {
    table.set(mastic_group, a, mastic_stone);
    const int colour_a = (a - 1) / bins, bin_a = (a - 1) % bins;
    for (int b = a; b < table.groups(); ++b) {
      const int colour_b = (b - 1) / bins, bin_b = (b - 1) % bins;
      if (!films || (colour_a == colour_b && !pairs_are_two_stones))
        table.set(a, b, stone);
      else
        table.set(a, b, m.film_per_contact() ? film_between_bins(bin_a, bin_b) : mean_film);
    }
  }
  return table;
}

// The 2D table: disks of width t (thickness) and diameter disk_diameter (m;
// only the films need it), by the method's rules or the calibrated ones.
inline AssignmentTable<RuttingLaw> rutting_table(const RuttingMaterials& m, double thickness, double shift,
                                                 int stone_colours = 1, double disk_diameter = 0.0) {
  RuttingTableScales scales;
  scales.conversion = m.calibrated_conversion ? MicroConversion::calibrated(m.mastic_nu) : MicroConversion::seed();
  scales.mastic_length = scales.stone_length = thickness;
  scales.diameter = disk_diameter;
  return rutting_table_with(m, shift, scales, stone_colours);
}

}  // namespace vrut
