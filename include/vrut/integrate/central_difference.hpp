#pragma once
// Central-difference (leapfrog) integration with PFC's local non-viscous
// damping: each force component is reduced by alpha*|F| against the motion,
//   F_d = F - alpha |F| sign(v),
// which removes energy in proportion to the unbalanced force, not to speed.
// Velocities live at half steps: v(t+dt/2) = v(t-dt/2) + F_d/m dt,
// x(t+dt) = x(t) + v(t+dt/2) dt.
#include <vrut/data/bodies.hpp>
#include <vrut/data/particles.hpp>

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

  template <class MemorySpace>
  KOKKOS_INLINE_FUNCTION static void advance(const params_type& p, const Particles<MemorySpace>& ps, int i,
                                             Vec2 force, double moment, double dt) {
    const int fix = ps.fixity(i);
    Vec2 v = ps.velocity(i);
    if (!(fix & prescribed_velocity)) {
      const double inv_m = 1.0 / ps.mass(i);
      v.x += damped(force.x, v.x, p.damping) * inv_m * dt;
      v.y += damped(force.y, v.y, p.damping) * inv_m * dt;
      ps.velocity(i) = v;
    }
    ps.position(i) += dt * v;
    ps.displacement(i) += dt * v;
    double w = ps.angular_velocity(i);
    if (!(fix & (no_rotation | prescribed_velocity))) {
      w += damped(moment, w, p.damping) / ps.inertia(i) * dt;
      ps.angular_velocity(i) = w;
    }
    ps.rotation(i) += w * dt;
  }

  // A rigid body (data/bodies.hpp) advances as one disk does, with its mass
  // and moment of inertia, the summed force and the moment about its centre.
  template <class MemorySpace>
  KOKKOS_INLINE_FUNCTION static void advance_body(const params_type& p, const Bodies<MemorySpace>& bs, int b,
                                                  Vec2 force, double moment, double dt) {
    Vec2 v = bs.velocity(b);
    const double inv_m = 1.0 / bs.mass(b);
    v.x += damped(force.x, v.x, p.damping) * inv_m * dt;
    v.y += damped(force.y, v.y, p.damping) * inv_m * dt;
    bs.velocity(b) = v;
    bs.position(b) += dt * v;
    double w = bs.angular_velocity(b);
    w += damped(moment, w, p.damping) / bs.inertia(b) * dt;
    bs.angular_velocity(b) = w;
    bs.rotation(b) += w * dt;
  }
};

}  // namespace vrut
