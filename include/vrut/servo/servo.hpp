#pragma once
// Wall controllers: policies that set a wall's velocity once per step from
// the load the disks put on it.
#include <vrut/core/walls.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

// Leaves every wall at the velocity it was given (velocity control).
struct VelocityControl {
  struct params_type {};
  KOKKOS_INLINE_FUNCTION static void control(const params_type&, Wall&, const WallLoad&, double) {}
};

// PFC-style servo: moves the wall along its inward normal to bring the normal
// force the disks exert on it to a target,
//   v = alpha (F_target - F_measured) / (k_n N_c dt),
// the velocity that would close the gap in one step if the N_c touching
// contacts of stiffness k_n were the only compliance, relaxed by alpha < 1.
// The speed is capped by max_speed.
struct ServoControl {
  struct params_type {
    int enabled = 0;
    double target_force = 0.0;       // N, compressive
    double alpha = 0.5;              // relaxation factor, (0, 1]
    double contact_stiffness = 0.0;  // k_n of one wall contact, N/m
    double max_speed = 1.0;          // m/s
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

  KOKKOS_INLINE_FUNCTION static double compressive_force(const Wall& w, const WallLoad& load) {
    return -dot(load.force, inward_normal(w));
  }

  KOKKOS_INLINE_FUNCTION static void control(const params_type& p, Wall& w, const WallLoad& load, double dt) {
    if (!p.enabled) return;
    const double contacts = load.contacts > 1.0 ? load.contacts : 1.0;
    double speed = p.alpha * (p.target_force - compressive_force(w, load)) / (p.contact_stiffness * contacts * dt);
    if (speed > p.max_speed) speed = p.max_speed;
    if (speed < -p.max_speed) speed = -p.max_speed;
    w.velocity = speed * inward_normal(w);
  }
};

}  // namespace vrut
