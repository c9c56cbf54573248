#pragma once
// Wall controllers: policies that set a wall's velocity once per step from
// the load the particles put on it (control/velocity.hpp has the engine's
// default, which leaves it as it is). They act on a 2D segment (Wall) or a 3D
// plate (Wall3) alike: along its inward normal.
#include <vrut/contact/geometry.hpp>
#include <vrut/control/velocity.hpp>
#include <vrut/data/walls.hpp>
#include <vrut/data/walls3.hpp>
#include <vrut/integrate/central_difference.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

// PFC-style servo with integral action: moves the wall along its inward
// normal to bring the normal force the disks exert on it to a target. With
// the error as a length, e = (F_target - F_measured) / (k_n N_c),
//   v = alpha e / dt + v_i,    v_i += integral * alpha e / dt,
// PFC's proportional term (the velocity that would close the gap in one step
// if the N_c touching contacts of stiffness k_n were the only compliance,
// relaxed by alpha < 1) plus an integral term. A proportional servo alone
// lags by e = v dt / alpha when the specimen keeps creeping at speed v; the
// integral term learns that speed, so the force settles on its target. It
// integrates only while something touches the wall (no wind-up on approach).
// Speeds are capped by max_speed.
struct ServoControl {
  struct params_type {
    int enabled = 0;
    double target_force = 0.0;       // N, compressive
    double alpha = 0.5;              // relaxation factor, (0, 1]
    double contact_stiffness = 0.0;  // k_n of one wall contact, N/m
    double max_speed = 1.0;          // m/s
    double integral = 0.05;          // integral gain, a fraction of alpha per step; 0: PFC's servo
  };
  struct state_type {
    double velocity = 0.0;  // the integral term v_i, along the inward normal
  };

  // Stress to force for a plate of the given length and out-of-plane thickness.
  static params_type for_stress(double stress, double plate_length, double thickness, double contact_stiffness,
                                double alpha = 0.5, double max_speed = 1.0) {
    params_type p;
    p.enabled = 1;
    p.target_force = stress * plate_length * thickness;
    p.alpha = alpha;
    p.contact_stiffness = contact_stiffness;
    p.max_speed = max_speed;
    return p;
  }

  template <class W, class Load>
  KOKKOS_INLINE_FUNCTION static double compressive_force(const W& w, const Load& load) {
    return -dot(load.force, inward_normal(w));
  }

  template <class W, class Load>
  KOKKOS_INLINE_FUNCTION static void control(const params_type& p, state_type& s, W& w, const Load& load, double dt) {
    if (!p.enabled) return;
    const double contacts = load.contacts > 1.0 ? load.contacts : 1.0;
    const double error = (p.target_force - compressive_force(w, load)) / (p.contact_stiffness * contacts);
    if (load.contacts > 0.0)
      s.velocity = clamp_magnitude(s.velocity + p.integral * p.alpha * error / dt, p.max_speed);
    w.velocity = clamp_magnitude(p.alpha * error / dt + s.velocity, p.max_speed) * inward_normal(w);
  }
};

// A plate carrying a dead load: it moves along its inward normal as a rigid
// body of the given mass under the target force and the disks' reaction,
//   m dv/dt = F_target - F_measured,
// the constant-stress loading of a laboratory creep frame. Unlike the servo it
// applies the full load from the first step.
struct LoadControl {
  struct params_type {
    int enabled = 0;
    double target_force = 0.0;  // N, compressive
    double mass = 0.0;          // kg
    double damping = 0.0;       // local damping of the plate's unbalanced force, as for the disks
  };
  struct state_type {};

  static params_type for_stress(double stress, double plate_length, double thickness, double mass,
                                double damping = 0.0) {
    params_type p;
    p.enabled = 1;
    p.target_force = stress * plate_length * thickness;
    p.mass = mass;
    p.damping = damping;
    return p;
  }

  template <class W, class Load>
  KOKKOS_INLINE_FUNCTION static void control(const params_type& p, state_type&, W& w, const Load& load, double dt) {
    if (!p.enabled) return;
    const auto n = inward_normal(w);
    const double v = dot(w.velocity, n);
    const double unbalanced = p.target_force - ServoControl::compressive_force(w, load);
    const double speed = v + CentralDifference::damped(unbalanced, v, p.damping) / p.mass * dt;
    w.velocity = speed * n;
  }
};

}  // namespace vrut
