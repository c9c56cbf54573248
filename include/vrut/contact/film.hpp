#pragma once
/// \file
/// A mastic film between two stones: the normal slot of a composed law (see
/// composite.hpp). The film's Burger's element carries the load in parallel
/// with the stones' linear spring, and the spring bears only once the overlap
/// exceeds the film's thickness: the film has squeezed out and the stones
/// touch. A film creeps, but not without end, as BurgersNormal alone would.
///
/// With no stone spring (stone_stiffness 0, the default) the slot is
/// BurgersNormal, bit for bit: the mastic contacts of the rutting table use
/// it that way.
#include <vrut/contact/burgers.hpp>
#include <vrut/contact/composite.hpp>
#include <vrut/contact/geometry.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>

namespace vrut {

struct FilmNormal {
  struct params_type {
    BurgersElement film;
    double thickness = 0.0;        // m: the overlap at which the stones touch
    double stone_stiffness = 0.0;  // N/m, the stones' spring beyond it; 0: no stones
  };
  /// Only the film's force is history; the stones' spring is elastic.
  using state_type = BurgersHistory;

  template <class Geometry>
  KOKKOS_INLINE_FUNCTION static double force(const params_type& p, state_type& s, const Geometry& g) {
    double f = burgers_step(p.film, s, g.normal_increment, g.dt);
    if (p.stone_stiffness > 0.0 && g.overlap > p.thickness) f += p.stone_stiffness * (g.overlap - p.thickness);
    return f;
  }
  static void prepare(params_type& p, double dt) { burgers_prepare(p.film, dt); }
  /// The total can pull only where the film does (the spring never pulls).
  KOKKOS_INLINE_FUNCTION static void cut_tension(const params_type&, state_type& s) {
    if (s.force < 0.0) s.force = 0.0;
  }
  /// In parallel, the two springs add (this bounds the critical time step).
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) {
    return p.film.maxwell_stiffness + p.stone_stiffness;
  }
};

/// The shear slot of the same film: the film's Burger's element in parallel
/// with the stones' shear spring, which holds while the stones touch (the
/// overlap exceeds the thickness) and lets go when they part. Stones that
/// bear on each other do not slide below their friction, as a creeping film
/// alone would. The Coulomb cap takes the stones' part first (they slide),
/// then the film's.
struct FilmShearParams {
  BurgersElement film;
  double thickness = 0.0;        // m, as FilmNormal's
  double stone_stiffness = 0.0;  // N/m; 0: no stones
  /// A candidate, not the model (docs/validation.md): touching stones still
  /// meet through the binder that coats them, so their shear spring sits in
  /// series with that film's dashpot, a Maxwell element of this time
  /// constant (s); 0: none, the spring holds its force until the stones
  /// slide or part.
  double stone_relaxation_time = 0.0;
  /// Prepared for the time step (prepare): over a step of constant shear
  /// rate the Maxwell element's force is decay times the last plus gain
  /// times the spring's increment, exactly: decay = exp(-dt / tau),
  /// gain = (1 - decay) / (dt / tau).
  double stone_decay = 1.0, stone_gain = 1.0;
};

template <class D>
struct FilmShearIn {
  using dimension = D;
  using params_type = FilmShearParams;
  using shear_type = typename D::shear;
  struct state_type {
    BurgersHistoryOf<shear_type> film;
    shear_type stone{};  // the stones' shear force
  };
  KOKKOS_INLINE_FUNCTION static shear_type force(const params_type& p, state_type& s, const ContactGeometryIn<D>& g) {
    const shear_type f = burgers_step(p.film, s.film, -g.shear_increment, g.dt);
    if (p.stone_stiffness > 0.0 && g.overlap > p.thickness) {
      if (p.stone_relaxation_time > 0.0)
        s.stone = p.stone_decay * s.stone - (p.stone_gain * p.stone_stiffness) * g.shear_increment;
      else
        s.stone -= p.stone_stiffness * g.shear_increment;
    } else {
      s.stone = shear_type{};
    }
    return f + s.stone;
  }
  static void prepare(params_type& p, double dt) {
    burgers_prepare(p.film, dt);
    if (p.stone_relaxation_time > 0.0) {
      const double steps = dt / p.stone_relaxation_time;
      p.stone_decay = std::exp(-steps);
      p.stone_gain = -std::expm1(-steps) / steps;
    }
  }
  KOKKOS_INLINE_FUNCTION static shear_type limit(const params_type&, state_type& s, double max_abs) {
    const shear_type film = cap_magnitude(s.film.force, max_abs);
    s.film.force = film;
    s.stone = cap_magnitude(s.stone, max_abs - magnitude(film));
    return film + s.stone;
  }
  template <class Turn>
  KOKKOS_INLINE_FUNCTION static void turn(state_type& s, const Turn& turn) {
    s.film.force = turn(s.film.force);
    s.film.kelvin = turn(s.film.kelvin);
    s.stone = turn(s.stone);
  }
  KOKKOS_INLINE_FUNCTION static double stiffness(const params_type& p) {
    return p.film.maxwell_stiffness + p.stone_stiffness;
  }
};
using FilmShear = FilmShearIn<Dim2>;

/// The rutting test's mastic law: Burger's with a bond, and a film where the
/// table gives it stones.
using BurgersFilmBonded = Composite<FilmNormal, FilmShear, ContactBond>;

/// A mastic law as a film law: with no stone stiffness the same law.
inline BurgersFilmBonded::params_type film_params(const BurgersBonded::params_type& mastic, double thickness = 0.0,
                                                  double stone_stiffness = 0.0, double stone_shear_stiffness = 0.0) {
  BurgersFilmBonded::params_type p;
  p.normal.film = mastic.normal;
  p.normal.thickness = thickness;
  p.normal.stone_stiffness = stone_stiffness;
  p.shear.film = mastic.shear;
  p.shear.thickness = thickness;
  p.shear.stone_stiffness = stone_shear_stiffness;
  p.bond = mastic.bond;
  p.friction = mastic.friction;
  return p;
}

}  // namespace vrut
