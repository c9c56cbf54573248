#pragma once
// The engine's 2D geometry (core/geometry.hpp): disks of thickness t, segment
// walls, spins about the out-of-plane axis, orientations as angles.
#include <vrut/core/contact_load.hpp>
#include <vrut/core/geometry.hpp>
#include <vrut/data/bodies.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/data/walls.hpp>

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace vrut {

template <>
struct Geometry<Dim2> {
  using wall_type = Wall;

  // --- particles (host) ------------------------------------------------------
  static void check(const ParticleSet&, double thickness) {
    if (!(thickness > 0.0)) throw std::invalid_argument("vrut::Simulation: thickness must be positive");
  }
  static Vec2 centre(const ParticleSet& set, std::size_t i) { return {set.x[i], set.y[i]}; }
  // A disk of width t: m = rho pi r^2 t, I = m r^2 / 2.
  static double mass(double density, double r, double thickness) {
    return density * 3.14159265358979323846 * r * r * thickness;
  }
  static double inertia(double mass, double r) { return 0.5 * mass * r * r; }
  static void describe(char* text, std::size_t size, std::size_t i, int specimen, Vec2 x) {
    std::snprintf(text, size, "disk %zu (specimen %d), now at (%.4g, %.4g) m", i, specimen, x.x, x.y);
  }

  // --- walls ----------------------------------------------------------------
  static void check(const Wall& wall) {
    if (!(length(wall) > 0.0)) throw std::invalid_argument("vrut::Simulation: a wall needs two distinct ends");
  }
  // Whether a particle may reach the wall before its distance is measured:
  // in 2D the distance decides alone.
  KOKKOS_INLINE_FUNCTION static bool may_reach(const Wall&, Vec2, Vec2, double) { return true; }

  // --- contacts ---------------------------------------------------------------
  // In 2D every listed pair gets its distance measured.
  KOKKOS_INLINE_FUNCTION static bool apart_at_a_glance(Vec2, double) { return false; }

  // A contact between disks i and j, g's normal and overlap set: the
  // increments, the law, and the load.
  template <class Law, class Particles>
  KOKKOS_FORCEINLINE_FUNCTION static ContactLoadIn<Dim2> pair_load(const typename Law::params_type& p,
                                                             typename Law::state_type& s, ContactGeometryIn<Dim2>& g,
                                                             Vec2, const Particles& ps, int i, int j, double dt) {
    const Vec2 t = perp(g.normal);
    // Lever arms to the contact point, the middle of the overlap.
    const double arm_i = ps.radius(i) - 0.5 * g.overlap, arm_j = ps.radius(j) - 0.5 * g.overlap;
    const Vec2 v_rel = (ps.velocity(j) - (ps.angular_velocity(j) * arm_j) * t) -
                       (ps.velocity(i) + (ps.angular_velocity(i) * arm_i) * t);
    g.normal_increment = -dot(v_rel, g.normal) * dt;
    g.shear_increment = dot(v_rel, t) * dt;
    describe_pair<Law>(g, ps, i, j, dt);
    const ContactForceIn<Dim2> f = Law::force(p, s, g);
    ContactLoadIn<Dim2> l;
    l.force = f.normal * g.normal + f.shear * t;
    l.moment_first = -arm_i * f.shear;
    l.moment_second = -arm_j * f.shear;
    return l;
  }

  // The contact of disk i (the second body) with a wall (the first, at rest
  // but for its velocity), g's normal (wall -> disk) and overlap set; the
  // contact point lies on the wall, arm = r - overlap from the centre.
  template <class Law, class Particles>
  KOKKOS_FORCEINLINE_FUNCTION static WallPushIn<Dim2> wall_push(const typename Law::params_type& p,
                                                           typename Law::state_type& s, ContactGeometryIn<Dim2>& g,
                                                           Vec2 wall_velocity, const Particles& ps, int i, double dt) {
    const double arm = ps.radius(i) - g.overlap;
    describe_wall_pair<Law>(g, ps, i, dt);
    const Vec2 t = perp(g.normal);
    const Vec2 v_rel = ps.velocity(i) - (ps.angular_velocity(i) * arm) * t - wall_velocity;
    g.normal_increment = -dot(v_rel, g.normal) * dt;
    g.shear_increment = dot(v_rel, t) * dt;
    const ContactForceIn<Dim2> cf = Law::force(p, s, g);
    return {cf.normal * g.normal + cf.shear * t, arm * cf.shear};
  }

  // --- rigid bodies -----------------------------------------------------------
  // A member at `offset` (body frame) of a body turned by theta and spinning
  // at w: its offset in the world, and the body's velocity there less V.
  KOKKOS_INLINE_FUNCTION static void member_motion(double theta, double w, Vec2 offset, Vec2& off, Vec2& turning) {
    off = rotated(offset, theta);
    turning = w * perp(off);
  }
  // A body's angular momentum: not carried in 2D.
  template <class Bodies>
  static void set_angular_momentum(Bodies&, int, double) {}
  template <class Archive, class Bodies>
  static void visit_body_state(Archive&, Bodies&) {}

  // A clump's mass properties from its members (centres x, masses, inertias):
  // the mass, the centre of mass, the moment about it; each member's offset
  // from the centre and the body's mass as felt at the member's centre,
  // 1 / (1 / M + d^2 / I), for the time step.
  struct Clump {
    Vec2 centre;
    double mass = 0.0, inertia = 0.0, rotation = 0.0;
    std::vector<Vec2> offsets;
    std::vector<double> felt_mass;
  };
  template <class HostVector, class HostDouble>
  static Clump clump(const std::vector<int>& members, const HostVector& x, const std::vector<double>&,
                     const HostDouble& mass, const HostDouble& inertia) {
    Clump c;
    double M = 0.0, mx = 0.0, my = 0.0;
    for (int i : members) M += mass(i), mx += mass(i) * x(i).x, my += mass(i) * x(i).y;
    const Vec2 X{mx / M, my / M};
    double I = 0.0;
    for (int i : members) I += inertia(i) + mass(i) * dot(x(i) - X, x(i) - X);
    c.centre = X, c.mass = M, c.inertia = I;
    for (int i : members) {
      c.offsets.push_back(x(i) - X);
      c.felt_mass.push_back(1.0 / (1.0 / M + dot(x(i) - X, x(i) - X) / I));
    }
    return c;
  }
};

}  // namespace vrut
