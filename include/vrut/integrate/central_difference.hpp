#pragma once
// Central-difference (leapfrog) integration with PFC's local non-viscous
// damping: each force component is reduced by alpha*|F| against the motion,
//   F_d = F - alpha |F| sign(v),
// which removes energy in proportion to the unbalanced force, not to speed.
// Velocities live at half steps: v(t+dt/2) = v(t-dt/2) + F_d/m dt,
// x(t+dt) = x(t) + v(t+dt/2) dt.
//
// In 3D the same, component by component, for the translation and for a
// sphere's spin; a sphere's orientation turns by the angle |w| dt about w
// (to second order).
// A 3D rigid body turns by the splitting of integrate/rigid_rotation.hpp,
// kicked by the damped torque.
#include <vrut/data/bodies.hpp>
#include <vrut/data/dimension.hpp>
#include <vrut/data/particles.hpp>
#include <vrut/integrate/rigid_rotation.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

struct CentralDifference {
  struct params_type {
    double damping = 0.0;  // alpha, 0 (none) to < 1; PFC's default is 0.7
  };

  KOKKOS_INLINE_FUNCTION static double damped(double f, double v, double alpha) {
    const double sign = v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
    return f - alpha * (f < 0.0 ? -f : f) * sign;
  }
  KOKKOS_INLINE_FUNCTION static Vec2 damped(Vec2 f, Vec2 v, double alpha) {
    return {damped(f.x, v.x, alpha), damped(f.y, v.y, alpha)};
  }
  KOKKOS_INLINE_FUNCTION static Vec3 damped(Vec3 f, Vec3 v, double alpha) {
    return {damped(f.x, v.x, alpha), damped(f.y, v.y, alpha), damped(f.z, v.z, alpha)};
  }

  // v += F_d / m dt, component by component.
  KOKKOS_INLINE_FUNCTION static void kick(Vec2& v, Vec2 force, double inv_m, double dt, double alpha) {
    v.x += damped(force.x, v.x, alpha) * inv_m * dt;
    v.y += damped(force.y, v.y, alpha) * inv_m * dt;
  }
  KOKKOS_INLINE_FUNCTION static void kick(Vec3& v, Vec3 force, double inv_m, double dt, double alpha) {
    v.x += damped(force.x, v.x, alpha) * inv_m * dt;
    v.y += damped(force.y, v.y, alpha) * inv_m * dt;
    v.z += damped(force.z, v.z, alpha) * inv_m * dt;
  }
  // A sphere's (or disk's) spin and orientation.
  KOKKOS_INLINE_FUNCTION static void spin(double& w, double moment, double inertia, double dt, double alpha) {
    w += damped(moment, w, alpha) / inertia * dt;
  }
  KOKKOS_INLINE_FUNCTION static void spin(Vec3& w, Vec3 moment, double inertia, double dt, double alpha) {
    w.x += damped(moment.x, w.x, alpha) / inertia * dt;
    w.y += damped(moment.y, w.y, alpha) / inertia * dt;
    w.z += damped(moment.z, w.z, alpha) / inertia * dt;
  }
  KOKKOS_INLINE_FUNCTION static void turn(double& angle, double w, double dt) { angle += w * dt; }
  // q + dt/2 (0, w) q, normalised: the turn by |w| dt about w to second
  // order in the step (the half-angle comes out as atan(|w| dt / 2)), with
  // no trigonometry, as it is done for every sphere at every step.
  KOKKOS_INLINE_FUNCTION static void turn(Quaternion& q, Vec3 w, double dt) {
    const Quaternion rate = Quaternion{0.0, w.x, w.y, w.z} * q;
    const double h = 0.5 * dt;
    q = normalized(Quaternion{q.w + h * rate.w, q.x + h * rate.x, q.y + h * rate.y, q.z + h * rate.z});
  }

  template <class MemorySpace, class D>
  KOKKOS_INLINE_FUNCTION static void advance(const params_type& p, const Particles<MemorySpace, D>& ps, int i,
                                             typename D::vector force, typename D::spin moment, double dt) {
    const int fix = ps.fixity(i);
    typename D::vector v = ps.velocity(i);
    if (!(fix & prescribed_velocity)) {
      const double inv_m = 1.0 / ps.mass(i);
      kick(v, force, inv_m, dt, p.damping);
      ps.velocity(i) = v;
    }
    ps.position(i) += dt * v;
    ps.displacement(i) += dt * v;
    typename D::spin w = ps.angular_velocity(i);
    if (!(fix & (no_rotation | prescribed_velocity))) {
      spin(w, moment, ps.inertia(i), dt, p.damping);
      ps.angular_velocity(i) = w;
    }
    turn(ps.rotation(i), w, dt);
  }

  // A rigid body (data/bodies.hpp) translates as one particle does, with its
  // mass and the summed force. In 2D it turns as a disk, with its moment of
  // inertia and the moment about its centre; in 3D its angular momentum takes
  // the damped torque's kick and the body turns freely with it over the step.
  template <class MemorySpace, class D>
  KOKKOS_INLINE_FUNCTION static void advance_body(const params_type& p, const Bodies<MemorySpace, D>& bs, int b,
                                                  typename D::vector force, typename D::spin moment, double dt) {
    typename D::vector v = bs.velocity(b);
    const double inv_m = 1.0 / bs.mass(b);
    kick(v, force, inv_m, dt, p.damping);
    bs.velocity(b) = v;
    bs.position(b) += dt * v;
    if constexpr (is_3d<D>) {
      Quaternion q = bs.rotation(b);
      Vec3 momentum = bs.angular_momentum(b);
      rotate_rigid_body(q, momentum, damped(moment, bs.angular_velocity(b), p.damping), bs.inertia(b), dt);
      bs.rotation(b) = q;
      bs.angular_momentum(b) = momentum;
      bs.angular_velocity(b) = angular_velocity(q, momentum, bs.inertia(b));
    } else {
      double w = bs.angular_velocity(b);
      w += damped(moment, w, p.damping) / bs.inertia(b) * dt;
      bs.angular_velocity(b) = w;
      bs.rotation(b) += w * dt;
    }
  }
};

}  // namespace vrut
