#pragma once
// The rutting test's material model (docs/method.md sections 5 and 6): the
// mastic, the stones, the films between them and the mould, and the laws
// and assignment table they give a specimen's disks.
#include <vrut/contact/choice.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/contact/film.hpp>
#include <vrut/core/assignment.hpp>
#include <vrut/material/burgers_parameters.hpp>
#include <vrut/specimen/specimen.hpp>
#include <vrut/specimen/stone_reach.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

// How two stones meet: see RuttingMaterials::stone_film.
enum class StoneFilm { none, mean, per_contact };

struct RuttingMaterials {
  BurgersMacro mastic;                  // at the test temperature, 60 C
  double mastic_nu = 0.35;
  bool calibrated_conversion = false;   // MicroConversion::calibrated instead of the method's rules
  // The calibration on mix 2# (docs/validation.md, "The frozen model of
  // 2026-12-02"): with the film per contact, 4 brings 2# to the
  // laboratory's rut. It is a fitted constant, declared as such. (2, the
  // value frozen before with no film, reads the micro parameters as two
  // Burger's disks in series, one of them rigid: docs/method.md section 6;
  // the source's value is 1.)
  double mastic_aggregate_factor = 4.0;
  double aggregate_modulus = 55.5e9;    // Pa
  double aggregate_nu = 0.25;
  double mastic_density = 2400.0, aggregate_density = 2700.0;  // kg/m^3
  double friction = 1.0;                // disk-disk, where no bond holds (calibrated, crushed stone)
  // Aggregate on aggregate only, where no bond holds; < 0: `friction`. A
  // candidate of the gradation study: stone on stone against contacts
  // through mastic (docs/validation.md).
  double stone_friction = -1.0;
  // How two stones meet (docs/validation.md, the gradation study): the
  // contact between disks of two different aggregates.
  //   none: method.md's rigid linear stone law (the model until 2026-12-02);
  //   mean: a mastic film of film_gap diameters (contact/film.hpp; no bond,
  //         stone friction) that squeezes out to the stone law;
  //   per_contact (the default since 2026-12-02): each pair of stones meets
  //         through its own film: one diameter less the reaches of its two
  //         disks, how far each centre lies inside its stone's outline
  //         towards the other stone (specimen/stone_reach.hpp), in
  //         film_reach_classes bins. Nothing in it is fitted.
  StoneFilm stone_film = StoneFilm::per_contact;
  // The mean film's thickness, as a fraction of the disk diameter. Where two
  // stones' disks (1 mm radius) are neighbours, the stones' true outlines lie
  // 0.40 diameters apart on average in 2# (0.42 in 1#, 0.375 in 3#;
  // benchmarks/film_gaps.cpp): mastic that the disks cannot show. The film's
  // Burger's law is the mastic's over that length (factor 1 / film_gap), and
  // the stones' linear springs, normal and shear, bear once the overlap
  // exceeds it.
  double film_gap = 0.40;
  // The mean film never squeezes out: no stone spring (the study's first
  // film, not adopted: it creeps without end).
  bool film_endless = false;
  bool films() const { return stone_film != StoneFilm::none; }
  bool film_per_contact() const { return stone_film == StoneFilm::per_contact; }
  // The thinnest film two stones meet through, m (0: none, the frozen
  // model): a candidate of the fidelity study (docs/validation.md, "No
  // stone pair bears bare"), not adopted unless that section says so. With
  // the film per contact every pair of stones' particles meets through at
  // least this much binder, so the stones' spring engages only past it: two
  // coated stones touch through two binder films (specimen/binder_film.hpp
  // gives one's thickness from the mix's volumetrics; --least-film binder).
  double least_film = 0.0;
  double wall_friction = 0.0;           // mould walls and plate
  // Rigid stones (data/bodies.hpp), the default: each aggregate moves as one
  // body instead of method.md's bonded disks on the stone's 2 t E springs
  // (rigid_stones = false, --exact-stones). Stone on stone, and any disk on
  // a wall, meet on a linear spring of stone_contact_ratio times the
  // mastic's normal spring E1 t, a numerical stiffness: the rut depth is the
  // same from 30 to 1,000 and moves at 10 (docs/validation.md, "Rigid stones
  // and the time step"), and 100 takes a fifteenth of the exact model's
  // steps. Beside it a dashpot of stone_damping of the pair's critical
  // damping: real stone rings down, and the exact model's stones, undamped
  // on springs 12,000 times the mastic's, ring and shake the skeleton. The
  // time step follows from these springs and the bodies' masses
  // (Simulation::contact_timestep). A departure from the method, in
  // numerics, chosen by that study.
  bool rigid_stones = true;
  double stone_contact_ratio = 100.0;
  double stone_damping = 0.05;
};

// The normal spring between two rigid stones and of the walls, N/m.
inline double rigid_stone_stiffness(const RuttingMaterials& m, double thickness) {
  if (!(m.stone_contact_ratio > 0.0) || !std::isfinite(m.stone_contact_ratio))
    throw std::invalid_argument("the stone contact ratio must be positive and finite");
  if (!(m.stone_damping >= 0.0 && m.stone_damping < 1.0))
    throw std::invalid_argument("the stone damping must lie in [0, 1) of critical");
  return m.stone_contact_ratio * m.mastic.E1 * thickness;
}

using RuttingLaw = Choice<BurgersFilmBonded, DampedLinearBonded>;
using RuttingWallLaw = DampedLinear;

// The stone law: the method's aggregate spring (2 t E, undamped), or the
// rigid stones' contact spring with its dashpot.
inline DampedLinearBonded::params_type stone_law_params(const RuttingMaterials& m, double thickness, double friction) {
  const auto exact = aggregate_params(m.aggregate_modulus, thickness, m.aggregate_nu, friction);
  DampedLinearBonded::params_type p;
  p.normal.stiffness = exact.normal.stiffness;
  p.shear.stiffness = exact.shear.stiffness;
  p.bond = exact.bond;
  p.friction = exact.friction;
  if (m.rigid_stones) {
    p.normal.stiffness = rigid_stone_stiffness(m, thickness);
    p.shear.stiffness = p.normal.stiffness / (2.0 * (1.0 + m.aggregate_nu));
    p.normal.damping_ratio = m.stone_damping;
  }
  return p;
}

// The mould's and the plate's law: as stiff as the stones' (and as damped).
inline RuttingWallLaw::params_type rutting_wall_params(const RuttingMaterials& m, double thickness) {
  const auto stone = stone_law_params(m, thickness, m.wall_friction);
  return damped_linear_params(stone.normal.stiffness, stone.normal.stiffness / (2.0 * (1.0 + m.aggregate_nu)),
                              m.wall_friction, stone.normal.damping_ratio);
}

// The film per contact sorts the stone disks' reaches into this many bins
// of 0.2 diameters: its thickness is resolved to 0.2 diameters, about the
// spread of the reach over the lines of one disk's neighbours.
inline constexpr int film_reach_classes = 5;
// Below half a bin the film is thinner than the bins resolve: its Burger's
// element is taken over that length, and the stones' spring bears at once.
inline constexpr double film_least_gap = 0.5 / film_reach_classes;

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

// What sets a contact table's stiffnesses: the mastic's micro-parameter
// rule and the length it multiplies E by (the disk width t in 2D; the sphere
// diameter d in 3D, where the FCC rule carries the lattice's factor), the
// length the stones' spring takes (t in 2D; d / c in 3D, protocol/rutting/run3.hpp),
// and the particle diameter, which sizes the films between stones.
struct RuttingTableScales {
  MicroConversion conversion;
  double mastic_length = 0.0, stone_length = 0.0;
  double diameter = 0.0;  // m; only the films need it
};

// Group 0 is the mastic; the aggregates are groups 1 .. stone_colours, one
// per colour (specimen/colouring.hpp), so that the table can tell two stones
// from one; with the film per contact, one per colour and reach bin
// (stone_group). With one colour that is the method's two-group table.
// pairs_are_two_stones: every contact between two stone particles is one
// between two stones (rigid stones, whose members never touch, and no
// colours needed); the films then go between any two stone groups.
inline AssignmentTable<RuttingLaw> rutting_table_with(const RuttingMaterials& m, double shift,
                                                      const RuttingTableScales& scales, int stone_colours,
                                                      bool pairs_are_two_stones = false) {
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(shift));
  const MicroConversion& conv = scales.conversion;
  const double mastic_length = scales.mastic_length, disk_diameter = scales.diameter;
  const double stone_friction = m.stone_friction < 0.0 ? m.friction : m.stone_friction;
  const bool films = m.films();
  const int bins = m.film_per_contact() ? film_reach_classes : 1;
  AssignmentTable<RuttingLaw> table(1 + stone_colours * bins);
  table.set(mastic_group, mastic_group,
            RuttingLaw::make_first(film_params(mastic_params(reduced, mastic_length, m.mastic_nu, conv, 1.0, m.friction))));
  const auto mastic_stone = RuttingLaw::make_first(
      film_params(mastic_params(reduced, mastic_length, m.mastic_nu, conv, m.mastic_aggregate_factor, m.friction)));
  const auto stone_params = stone_law_params(m, scales.stone_length, stone_friction);
  const auto stone = RuttingLaw::make_second(stone_params);
  if (films) {
    if (!m.film_per_contact() && !(m.film_gap > 0.0 && m.film_gap < 1.0))
      throw std::invalid_argument("the film between stones must be thinner than a disk and positive (film gap in (0, 1))");
    if (m.film_per_contact() && m.film_endless)
      throw std::invalid_argument("a film per contact is sized by where the stones touch: it cannot be endless");
    if (!(disk_diameter > 0.0)) throw std::invalid_argument("the film between stones needs the disk diameter");
  } else if (m.film_endless) {
    throw std::invalid_argument("an endless film is a film between stones: it needs the mean film (stone film 'mean')");
  }
  // A film `gap` diameters thick: the mastic's Burger's law over that length
  // (per contact, never thinner than film_least_gap), the stones' springs
  // beyond it.
  auto film = [&](double gap) {
    const double length = m.film_per_contact() ? std::max(gap, film_least_gap) : gap;
    const auto mastic = mastic_params(reduced, mastic_length, m.mastic_nu, conv, 1.0 / length, stone_friction);
    return RuttingLaw::make_first(m.film_endless ? film_params(mastic)
                                                 : film_params(mastic, gap * disk_diameter,
                                                               stone_params.normal.stiffness,
                                                               stone_params.shear.stiffness));
  };
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
