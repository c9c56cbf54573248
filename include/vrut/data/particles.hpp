#pragma once
// Particle state as a structure of arrays, one Kokkos::View per quantity:
// disks in 2D, spheres in 3D (data/dimension.hpp says what a vector, a spin
// and an orientation are in each).
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

#include <cstddef>
#include <string>

namespace vrut {

// Bits of Particles::fixity.
enum Fixity : int {
  free_motion = 0,
  prescribed_velocity = 1,  // translation follows the given velocity; forces ignored
  no_rotation = 2,          // angular velocity stays as given
};

template <class MemorySpace, class D = Dim2>
struct Particles {
  using memory_space = MemorySpace;
  using dimension = D;
  using vector = typename D::vector;
  using spin = typename D::spin;
  template <class T>
  using view = Kokkos::View<T*, MemorySpace>;

  view<vector> position, velocity, force, external_force, displacement;
  view<double> radius, mass, inertia;  // inertia: about any axis through the centre
  view<typename D::orientation> rotation;
  view<spin> angular_velocity, moment;
  view<int> group, fixity, specimen;  // specimen: index in an ensemble (ParticleSet::specimen)
  // The rigid body a disk is a member of (data/bodies.hpp), -1 for a free
  // particle; and the mass a contact on it moves: its body's, or its own.
  view<int> body;
  view<double> contact_mass;

  Particles() = default;
  explicit Particles(std::size_t n)
      : position("position", n), velocity("velocity", n), force("force", n),
        external_force("external_force", n), displacement("displacement", n),
        radius("radius", n), mass("mass", n), inertia("inertia", n), rotation("rotation", n),
        angular_velocity("angular_velocity", n), moment("moment", n), group("group", n),
        fixity("fixity", n), specimen("specimen", n), body("body", n), contact_mass("contact_mass", n) {
    Kokkos::deep_copy(body, -1);
  }

  std::size_t size() const { return position.extent(0); }
};

}  // namespace vrut
