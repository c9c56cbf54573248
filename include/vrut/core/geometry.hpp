#pragma once
// What differs between 2D and 3D in the engine, in one place per dimension:
// Geometry<Dim2> (core/geometry2.hpp) and Geometry<Dim3> (core/geometry3.hpp).
// Each says
//   - what a particle is: its centre from a ParticleSet, its mass and inertia;
//   - what a wall is (wall_type) and when one is well formed;
//   - the kinematics of a contact between two particles and of a particle
//     with a wall: the relative motion, the increments, the law, the load;
//   - how a rigid body's members move with it, and a clump's mass properties;
// and the engine (core/simulation.hpp and its rooms) is written once on top.
// The data types of a dimension (vector, spin, orientation, shear) are in
// data/dimension.hpp, below this.
#include <vrut/contact/concept.hpp>
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

template <class Dim>
struct Geometry;  // specialized in core/geometry2.hpp and core/geometry3.hpp

// A wall's push on a particle: the force, and the lever whose negative is its
// moment about the particle's centre.
template <class D>
struct WallPushIn {
  typename D::vector force;
  typename D::spin lever;
};

// What a law reads of a pair besides its motion: dt, the radii and, for a
// law that reads them, the masses the contact moves.
template <class Law, class Particles, class D>
KOKKOS_INLINE_FUNCTION void describe_pair(ContactGeometryIn<D>& g, const Particles& ps, int i, int j, double dt) {
  g.dt = dt;
  g.radius_1 = ps.radius(i);
  g.radius_2 = ps.radius(j);
  if constexpr (law_uses_mass<Law>()) {
    g.mass_1 = ps.contact_mass(i);
    g.mass_2 = ps.contact_mass(j);
  }
}

// The same for a particle (the second body) on a wall (the first: no radius,
// no mass).
template <class Law, class Particles, class D>
KOKKOS_INLINE_FUNCTION void describe_wall_pair(ContactGeometryIn<D>& g, const Particles& ps, int i, double dt) {
  g.dt = dt;
  g.radius_1 = 0.0;
  g.radius_2 = ps.radius(i);
  if constexpr (law_uses_mass<Law>()) g.mass_2 = ps.contact_mass(i);  // mass_1 = 0: a wall
}

}  // namespace vrut
