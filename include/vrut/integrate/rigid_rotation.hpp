#pragma once
// The rotation of a 3D rigid body over one time step, usable in Kokkos
// kernels. The body's orientation is a unit quaternion q (body frame to
// world), its inertia diagonal in its own frame (principal axes), and the
// state carried is the angular momentum L in the world frame, which a
// torque changes and a free rotation keeps.
//
// The scheme is the splitting of Dullweber, Leimkuhler and McLachlan (J.
// Chem. Phys. 107, 5840, 1997), the free-rotor part of LAMMPS' NO_SQUISH
// (Miller et al., J. Chem. Phys. 116, 8649, 2002): the free rotor's energy
// is the sum of pi_k^2 / (2 I_k) over the body axes k (pi = q* L q, the
// body-frame momentum), and the flow of each term alone is exact: a turn
// of the body about its axis k by theta = h pi_k / I_k, which turns pi by
// -theta about the same axis. Composed symmetrically, x(h/2) y(h/2) z(h)
// y(h/2) x(h/2), the step is second order, time-reversible and symplectic,
// and keeps L (and |pi|) exactly up to rounding: a torque-free body keeps
// its angular momentum and its energy does not drift. The torque enters as
// in central differences: L(n+1/2) = L(n-1/2) + dt torque(n), then the free
// rotation over dt with L(n+1/2).
#include <vrut/data/quaternion.hpp>
#include <vrut/data/vec3.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

namespace detail {

// The exact flow of pi_k^2 / (2 I_k) over h: the body turns by theta about
// its axis k, and the body-frame momentum by -theta about the same axis.
KOKKOS_INLINE_FUNCTION void turn_about_body_axis(int k, Quaternion& q, Vec3& pi, Vec3 inertia, double h) {
  const double theta = h * component(pi, k) / component(inertia, k);
  const double c = cos(theta), s = sin(theta);
  const int a = (k + 1) % 3, b = (k + 2) % 3;  // the plane turned, right-handed about k
  const double pa = component(pi, a), pb = component(pi, b);
  component(pi, a) = c * pa + s * pb;
  component(pi, b) = -s * pa + c * pb;
  Vec3 axis{0.0, 0.0, 0.0};
  component(axis, k) = 1.0;
  q = q * axis_angle(axis, theta);
}

}  // namespace detail

// A free rotation over h: the orientation q moves, and the body-frame
// momentum pi with it (the world-frame L = q pi q* stays).
KOKKOS_INLINE_FUNCTION void free_rotation(Quaternion& q, Vec3& pi, Vec3 inertia, double h) {
  detail::turn_about_body_axis(0, q, pi, inertia, 0.5 * h);
  detail::turn_about_body_axis(1, q, pi, inertia, 0.5 * h);
  detail::turn_about_body_axis(2, q, pi, inertia, h);
  detail::turn_about_body_axis(1, q, pi, inertia, 0.5 * h);
  detail::turn_about_body_axis(0, q, pi, inertia, 0.5 * h);
}

// One step: the torque's kick to the world-frame angular momentum, then the
// free rotation; q is renormalised against rounding.
KOKKOS_INLINE_FUNCTION void rotate_rigid_body(Quaternion& q, Vec3& angular_momentum, Vec3 torque, Vec3 inertia,
                                              double dt) {
  angular_momentum += dt * torque;
  Vec3 pi = rotate_back(q, angular_momentum);
  free_rotation(q, pi, inertia, dt);
  q = normalized(q);
}

// The angular velocity in the world frame: q (I^-1 pi) q*.
KOKKOS_INLINE_FUNCTION Vec3 angular_velocity(Quaternion q, Vec3 angular_momentum, Vec3 inertia) {
  return rotate(q, over_each(rotate_back(q, angular_momentum), inertia));
}

// The kinetic energy of the rotation, sum of pi_k^2 / (2 I_k).
KOKKOS_INLINE_FUNCTION double rotational_energy(Quaternion q, Vec3 angular_momentum, Vec3 inertia) {
  const Vec3 pi = rotate_back(q, angular_momentum);
  return 0.5 * dot(pi, over_each(pi, inertia));
}

}  // namespace vrut
