#pragma once
// The mix's materials and the conversion from their macro parameters to
// each contact class's micro parameters (docs/method.md sections 5 and 6;
// docs/validation.md for the choices): one function a class,
//   mastic on mastic         mastic_mastic_params
//   mastic on stone          mastic_stone_params
//   stone on stone           stone_law_params (bare), stone_film_params (through a film)
//   particle on a wall       rutting_wall_params
// on the lengths a dimension gives them (ContactScales: the disk width t in
// 2D; in 3D the sphere diameter d for the mastic, d / c for the stones).
// Which class meets which is the test's (protocol/rutting/materials.hpp).
#include <vrut/contact/composite.hpp>
#include <vrut/contact/film.hpp>
#include <vrut/material/burgers_parameters.hpp>
#include <vrut/material/time_temperature.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vrut {

// How two stones meet: see RuttingMaterials::stone_film.
enum class StoneFilm { none, mean, per_contact };

struct RuttingMaterials {
  BurgersMacro mastic;                  // at the test temperature, 60 C
  double mastic_nu = 0.35;
  bool calibrated_conversion = false;   // MicroConversion::calibrated instead of the method's rules
  // The calibration on mix 2# (docs/validation.md, "The 2D model,
  // calibrated on 2#"): with the film per contact, 4 brings 2# to the
  // laboratory's rut. It is a fitted constant, declared as such. (2, the
  // value frozen before with no film, reads the micro parameters as two
  // Burger's disks in series, one of them rigid: docs/method.md section 6;
  // the source's value is 1.)
  double mastic_aggregate_factor = 4.0;
  double aggregate_modulus = 55.5e9;    // Pa
  double aggregate_nu = 0.25;
  double mastic_density = 2400.0, aggregate_density = 2700.0;  // kg/m^3
  double friction = 1.0;                // disk-disk, where no bond holds (calibrated, crushed stone)
  // Aggregate on aggregate only, where no bond holds; < 0: `friction`, as
  // the 2D model has it. The frozen 3D model's one fitted constant, 0.6
  // (protocol/rutting/model3.hpp; docs/validation.md, "The frozen 3D model").
  double stone_friction = -1.0;
  // How two stones meet (docs/validation.md, the gradation study): the
  // contact between disks of two different aggregates.
  //   none: method.md's rigid linear stone law (the older 2D model's);
  //   mean: a mastic film of film_gap diameters (contact/film.hpp; no bond,
  //         stone friction) that squeezes out to the stone law;
  //   per_contact (the default): each pair of stones meets
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
  // model): a candidate of the fidelity study (docs/validation.md,
  // "Candidates"), not adopted unless that table says so. With
  // the film per contact every pair of stones' particles meets through at
  // least this much binder, so the stones' spring engages only past it: two
  // coated stones touch through two binder films (specimen/binder_film.hpp
  // gives one's thickness from the mix's volumetrics; --least-film binder).
  double least_film = 0.0;
  // The binder film that a touching pair of stones' shear relaxes through, m
  // (0: none, the frozen models): a candidate of the fidelity study, not
  // adopted unless docs/validation.md's table says so. Two coated stones
  // that bear on each other still meet through their binder (two films,
  // specimen/binder_film.hpp), and a sheared film relaxes a shear force
  // where a Coulomb cap holds it for ever. The stones' shear spring goes in
  // series with the dashpot of that film: the mastic's Maxwell viscosity in
  // shear over the film's thickness, by the same lattice rule as every
  // mastic contact (the model knows no other viscous binder; a binder
  // without its filler would relax faster still). No constant is fitted.
  // With the film per contact only.
  double stone_shear_film = 0.0;
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
inline DampedLinear::params_type rutting_wall_params(const RuttingMaterials& m, double thickness) {
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

// What sets the classes' stiffnesses in a dimension: the mastic's
// micro-parameter rule and the length it multiplies E by, the length the
// stones' spring takes, the particle diameter (which sizes the films
// between stones), and the time shift alpha_T.
struct ContactScales {
  MicroConversion conversion;
  double mastic_length = 0.0, stone_length = 0.0;
  double diameter = 0.0;  // m; only the films need it
  double shift = 1.0;
};

inline double stone_friction_of(const RuttingMaterials& m) { return m.stone_friction < 0.0 ? m.friction : m.stone_friction; }

// Two mastic particles: the mastic's Burger's law, reduced by alpha_T.
inline BurgersFilmBonded::params_type mastic_mastic_params(const RuttingMaterials& m, const ContactScales& s) {
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(s.shift));
  return film_params(mastic_params(reduced, s.mastic_length, m.mastic_nu, s.conversion, 1.0, m.friction));
}

// Mastic on a stone: the same, scaled by the mastic-aggregate factor.
inline BurgersFilmBonded::params_type mastic_stone_params(const RuttingMaterials& m, const ContactScales& s) {
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(s.shift));
  return film_params(
      mastic_params(reduced, s.mastic_length, m.mastic_nu, s.conversion, m.mastic_aggregate_factor, m.friction));
}

// The time constant (s, at the table's shift) of the stones' shear spring
// `stone_shear` (N/m) in series with the dashpot of a binder film of
// m.stone_shear_film: the film's Maxwell viscosity in shear, the mastic's
// over that film's thickness (a factor of the particle diameter over it, as
// stone_film_params sizes every film), over the spring.
inline double stone_shear_relaxation_time(const RuttingMaterials& m, const ContactScales& s, double stone_shear) {
  if (!(m.stone_shear_film > 0.0) || !std::isfinite(m.stone_shear_film) || !(m.stone_shear_film < s.diameter))
    throw std::invalid_argument("the binder film a stone contact's shear relaxes through must be positive and "
                                "thinner than a particle's diameter");
  if (!m.film_per_contact())
    throw std::invalid_argument("a stone contact's shear relaxes through its binder film with the film per contact "
                                "(stone film 'per-contact')");
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(s.shift));
  const BurgersElement film = burgers_element(reduced, s.mastic_length, s.diameter / m.stone_shear_film /
                                              (2.0 * (1.0 + m.mastic_nu)), s.conversion);
  return film.maxwell_viscosity / stone_shear;
}

// Two stones through a film `gap` particle diameters thick: the mastic's
// Burger's law over that length (per contact, never thinner than
// film_least_gap), the stones' springs beyond it; or, endless, the film alone.
inline BurgersFilmBonded::params_type stone_film_params(const RuttingMaterials& m, const ContactScales& s, double gap) {
  const BurgersMacro reduced = m.mastic.shifted(TimeShift(s.shift));
  const double stone_friction = stone_friction_of(m);
  const auto stone = stone_law_params(m, s.stone_length, stone_friction);
  const double length = m.film_per_contact() ? std::max(gap, film_least_gap) : gap;
  const auto mastic = mastic_params(reduced, s.mastic_length, m.mastic_nu, s.conversion, 1.0 / length, stone_friction);
  if (m.film_endless) return film_params(mastic);
  auto p = film_params(mastic, gap * s.diameter, stone.normal.stiffness, stone.shear.stiffness);
  if (m.stone_shear_film > 0.0)
    p.shear.stone_relaxation_time = stone_shear_relaxation_time(m, s, stone.shear.stiffness);
  return p;
}

}  // namespace vrut
