#pragma once
// Rigid bodies (clumps): sets of member disks that move as one, as PFC's
// clumps and YADE's clumps do. A body carries the motion (centre of mass,
// velocity, orientation, angular velocity) and its members follow it: each
// member sits at a fixed offset from the centre in the body's frame. The
// members' contact forces and moments are summed into the body, the body
// advances, and the members are placed again from it (core/simulation.hpp).
// In 2D the orientation is an angle and the inertia a scalar. In 3D the
// orientation is a quaternion from the body's principal frame to the world,
// the inertia the principal moments, the offsets lie in the principal frame,
// and the body carries its angular momentum, from which the rotation step
// works (integrate/rigid_rotation.hpp).
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

#include <cstddef>

namespace vrut {

template <class MemorySpace, class D = Dim2>
struct Bodies {
  using memory_space = MemorySpace;
  using dimension = D;
  template <class T>
  using view = Kokkos::View<T*, MemorySpace>;

  view<typename D::vector> position, velocity, force;  // centre of mass, its velocity, the summed force
  view<double> mass;
  view<typename D::spin> inertia;  // about the centre of mass: 2D the moment, 3D the principal moments
  view<typename D::orientation> rotation;
  view<typename D::spin> angular_velocity, moment;  // about the centre of mass
  view<typename D::spin> angular_momentum;         // 3D only (empty in 2D), world frame
  view<int> member_begin;  // body b's members are member(member_begin(b)) .. member(member_begin(b + 1) - 1)
  view<int> member;        // particle indices, ascending within a body: a fixed order of the sums
  view<typename D::vector> offset;  // per member slot: the member's centre from the body's, in the body's frame

  Bodies() = default;
  Bodies(std::size_t bodies, std::size_t members)
      : position("body_position", bodies), velocity("body_velocity", bodies), force("body_force", bodies),
        mass("body_mass", bodies), inertia("body_inertia", bodies), rotation("body_rotation", bodies),
        angular_velocity("body_angular_velocity", bodies), moment("body_moment", bodies),
        angular_momentum("body_angular_momentum", is_3d<D> ? bodies : 0),
        member_begin("body_member_begin", bodies + 1), member("body_member", members),
        offset("body_member_offset", members) {}

  std::size_t size() const { return position.extent(0); }
};

// The offset `o` turned by the angle `theta`.
KOKKOS_INLINE_FUNCTION Vec2 rotated(Vec2 o, double theta) {
  const double c = cos(theta), s = sin(theta);
  return {c * o.x - s * o.y, s * o.x + c * o.y};
}

}  // namespace vrut
