#pragma once
// The engine's 3D geometry (core/geometry.hpp): spheres, rectangular plates
// (Wall3), spins as vectors, orientations as quaternions. A contact's stored
// shear turns with it (contact/geometry3.hpp): over a step the normal turns
// from the one the pair had a step ago, which the leapfrog gives exactly,
// d(t - dt) = d(t) - dt (v_j - v_i), and the pair spins about the mean of the
// two normals by dt times its mean angular velocity there.
#include <vrut/contact/geometry3.hpp>
#include <vrut/core/contact_load.hpp>
#include <vrut/core/geometry.hpp>
#include <vrut/data/bodies.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/data/walls.hpp>
#include <vrut/data/walls3.hpp>
#include <vrut/geometry/clump3.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace vrut {

template <>
struct Geometry<Dim3> {
  using wall_type = Wall3;

  // --- particles (host) ------------------------------------------------------
  static void check(const ParticleSet& set, double) {
    if (set.z.size() != set.size())
      throw std::invalid_argument("vrut::Simulation: a 3D simulation needs a z for every particle (ParticleSet::z)");
  }
  static Vec3 centre(const ParticleSet& set, std::size_t i) { return {set.x[i], set.y[i], set.z[i]}; }
  // A sphere: m = rho 4/3 pi r^3, I = 2/5 m r^2.
  static double mass(double density, double r, double) {
    return density * (4.0 / 3.0 * 3.14159265358979323846) * r * r * r;
  }
  static double inertia(double mass, double r) { return 0.4 * mass * r * r; }
  static void describe(char* text, std::size_t size, std::size_t i, int specimen, Vec3 x) {
    std::snprintf(text, size, "sphere %zu (specimen %d), now at (%.4g, %.4g, %.4g) m", i, specimen, x.x, x.y, x.z);
  }

  // --- walls ----------------------------------------------------------------
  static void check(const Wall3& wall) {
    const double u = norm(wall.half_u), v = norm(wall.half_v);
    if (!(area(wall) > 0.0) || !(std::abs(dot(wall.half_u, wall.half_v)) <= 1e-12 * u * v))
      throw std::invalid_argument("vrut::Simulation: a plate needs two orthogonal half-edges of nonzero length");
  }
  // Whether a sphere (centre c, radius r) may reach plate w, of inward unit
  // normal n: one farther from the plate's plane than r cannot (one dot
  // product; most spheres are far from every plate). For one nearer,
  // wall_distance measures the plate's edges too.
  KOKKOS_INLINE_FUNCTION static bool may_reach(const Wall3& w, Vec3 n, Vec3 c, double r) {
    const double height = dot(c - w.centre, n);
    return height < r && height > -r;
  }

  // --- contacts ---------------------------------------------------------------
  // A listed pair apart is found without a square root (most listed pairs are).
  KOKKOS_INLINE_FUNCTION static bool apart_at_a_glance(Vec3 d, double reach) { return dot(d, d) >= reach * reach; }

  // A contact between spheres i and j, their separation d (through the
  // nearest image) and g's normal and overlap set: the stored shear turned
  // into the contact's new frame, the increments, the law, and the load.
  template <class Law, class Particles>
  KOKKOS_FORCEINLINE_FUNCTION static ContactLoadIn<Dim3> pair_load(const typename Law::params_type& p,
                                                             typename Law::state_type& s, ContactGeometryIn<Dim3>& g,
                                                             Vec3 d, const Particles& ps, int i, int j, double dt) {
    const double arm_i = ps.radius(i) - 0.5 * g.overlap, arm_j = ps.radius(j) - 0.5 * g.overlap;
    const Vec3 w_i = ps.angular_velocity(i), w_j = ps.angular_velocity(j);
    const Vec3 v_rel = (ps.velocity(j) + cross(w_j, -arm_j * g.normal)) - (ps.velocity(i) + cross(w_i, arm_i * g.normal));
    // The leapfrog moved the centres by dt v: a step ago they were d - dt (v_j - v_i) apart.
    // The pair's mean spin about the step's mean normal (second order):
    // |n + n'| = sqrt(2 (1 + n . n')).
    const Vec3 before = d - dt * (ps.velocity(j) - ps.velocity(i));
    const double before_length = norm(before);
    if (before_length > 0.0) {
      const Vec3 old_normal = (1.0 / before_length) * before, mid = old_normal + g.normal;
      const double mid_length = sqrt(2.0 * (1.0 + dot(old_normal, g.normal)));
      const double twist = mid_length > 0.0 ? 0.5 * dt * dot(w_i + w_j, mid) / mid_length : 0.0;
      turn_history<Law>(s, ContactTurn(old_normal, g.normal, twist));
    }
    const double along = dot(v_rel, g.normal);
    g.normal_increment = -along * dt;
    g.shear_increment = dt * (v_rel - along * g.normal);
    describe_pair<Law>(g, ps, i, j, dt);
    const ContactForceIn<Dim3> f = Law::force(p, s, g);
    ContactLoadIn<Dim3> l;
    l.force = f.normal * g.normal + f.shear;
    // The force on j acts at -arm_j n from its centre, its reaction on i at +arm_i n.
    l.moment_first = cross(arm_i * g.normal, -l.force);
    l.moment_second = cross(-arm_j * g.normal, l.force);
    return l;
  }

  // The contact of sphere i (the second body) with a plate (the first, at
  // rest but for its velocity), g's normal (plate -> sphere) and overlap set;
  // the contact point lies on the plate, arm = r - overlap from the centre.
  template <class Law, class Particles>
  KOKKOS_FORCEINLINE_FUNCTION static WallPushIn<Dim3> wall_push(const typename Law::params_type& p,
                                                           typename Law::state_type& s, ContactGeometryIn<Dim3>& g,
                                                           Vec3 wall_velocity, const Particles& ps, int i, double dt) {
    const double arm = ps.radius(i) - g.overlap;
    describe_wall_pair<Law>(g, ps, i, dt);
    const Vec3 w = ps.angular_velocity(i);
    const Vec3 v_rel = ps.velocity(i) + cross(w, -arm * g.normal) - wall_velocity;
    // A plate does not turn: the frame turns only as the sphere spins about the normal.
    turn_history<Law>(s, ContactTurn(g.normal, g.normal, 0.5 * dt * dot(w, g.normal)));
    const double along = dot(v_rel, g.normal);
    g.normal_increment = -along * dt;
    g.shear_increment = dt * (v_rel - along * g.normal);
    const ContactForceIn<Dim3> cf = Law::force(p, s, g);
    return {cf.normal * g.normal + cf.shear, arm * cross(g.normal, cf.shear)};
  }

  // --- rigid bodies -----------------------------------------------------------
  // A member at `offset` (principal frame) of a body turned by q and spinning
  // at w: its offset in the world, and the body's velocity there less V.
  KOKKOS_INLINE_FUNCTION static void member_motion(const Quaternion& q, Vec3 w, Vec3 offset, Vec3& off, Vec3& turning) {
    off = rotate(q, offset);
    turning = cross(w, off);
  }
  // The world-frame angular momentum that gives body b the angular velocity
  // w: L = q I (q* w q) q*.
  template <class Bodies>
  static void set_angular_momentum(Bodies& bodies, int b, Vec3 w) {
    Quaternion q;
    Vec3 inertia;
    Kokkos::deep_copy(q, Kokkos::subview(bodies.rotation, b));
    Kokkos::deep_copy(inertia, Kokkos::subview(bodies.inertia, b));
    const Vec3 momentum = rotate(q, times_each(inertia, rotate_back(q, w)));
    Kokkos::deep_copy(Kokkos::subview(bodies.angular_momentum, b), momentum);
  }
  template <class Archive, class Bodies>
  static void visit_body_state(Archive& a, Bodies& bodies) {
    a.view("body_angular_momentum", bodies.angular_momentum);
  }

  // A clump's mass properties from its members (geometry/clump3.hpp): the
  // mass, the centre of mass, the principal moments and axes; each member's
  // offset in the principal frame and the body's mass as felt at the
  // member's centre, for the time step.
  struct Clump {
    Vec3 centre, inertia;
    double mass = 0.0;
    Quaternion rotation;
    std::vector<Vec3> offsets;
    std::vector<double> felt_mass;
  };
  template <class HostVector, class HostDouble>
  static Clump clump(const std::vector<int>& members, const HostVector& x, const std::vector<double>& radius,
                     const HostDouble& mass, const HostDouble&) {
    std::vector<Vec3> centres;
    std::vector<double> radii, masses;
    for (int i : members) centres.push_back(x(i)), radii.push_back(radius[i]), masses.push_back(mass(i));
    const ClumpProperties3 p = clump_properties_of_masses(centres, radii, masses);
    Clump c;
    c.centre = p.centre, c.mass = p.mass, c.inertia = p.principal_moments, c.rotation = p.orientation;
    c.offsets = p.offsets;
    for (const Vec3& o : p.offsets) c.felt_mass.push_back(mass_felt_at_member(p, o));
    return c;
  }
};

}  // namespace vrut
