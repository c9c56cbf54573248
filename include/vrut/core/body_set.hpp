#pragma once
// Rigid bodies in the engine (data/bodies.hpp): built from ParticleSet::body,
// advanced from their members' summed loads, and their members placed again.
// A member's contact forces and moments are summed as any particle's
// (core/sum_and_advance.hpp), but the member does not advance: its body sums
// its members' loads in a fixed order (the members' ascending order),
// advances, and places them again. Two members of one body never touch.
#include <vrut/core/geometry.hpp>
#include <vrut/data/bodies.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/data/particles.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

// Puts body b's members where it says, with its motion at that point:
// x = X + R offset, v = V + omega x (R offset).
template <class Particles, class Bodies>
KOKKOS_INLINE_FUNCTION void place_members_of(const Particles& ps, const Bodies& bs, int b) {
  using Dim = typename Bodies::dimension;
  using vector = typename Dim::vector;
  const vector X = bs.position(b), V = bs.velocity(b);
  const typename Dim::orientation theta = bs.rotation(b);
  const typename Dim::spin w = bs.angular_velocity(b);
  for (int k = bs.member_begin(b); k < bs.member_begin(b + 1); ++k) {
    const int i = bs.member(k);
    vector off, turning;  // the offset in the world frame, and the body's velocity there less V
    Geometry<Dim>::member_motion(theta, w, bs.offset(k), off, turning);
    const vector x = X + off;
    ps.displacement(i) += x - ps.position(i);
    ps.position(i) = x;
    ps.velocity(i) = V + turning;
    ps.angular_velocity(i) = w;
    ps.rotation(i) = theta;
  }
}

template <class Space, class Particles, class Bodies>
void place_members(const Space& space, const Particles& ps, const Bodies& bs) {
  if (bs.size() == 0) return;
  Kokkos::parallel_for("vrut::place_members", Kokkos::RangePolicy<Space>(space, 0, bs.size()),
      KOKKOS_LAMBDA(const int b) { place_members_of(ps, bs, b); });
}

// Each body sums its members' forces and their moments about its centre, in
// the members' order, advances, and places its members again.
template <class Integrator, class Space, class Particles, class Bodies>
void advance_bodies(const Space& space, const Particles& ps, const Bodies& bs,
                    const typename Integrator::params_type& integrator, double dt) {
  using Dim = typename Bodies::dimension;
  Kokkos::parallel_for("vrut::advance_bodies", Kokkos::RangePolicy<Space>(space, 0, bs.size()),
      KOKKOS_LAMBDA(const int b) {
        const typename Dim::vector X = bs.position(b);
        typename Dim::vector f;
        typename Dim::spin m{};
        for (int k = bs.member_begin(b); k < bs.member_begin(b + 1); ++k) {
          const int i = bs.member(k);
          f += ps.force(i);
          m += ps.moment(i) + cross(ps.position(i) - X, ps.force(i));
        }
        bs.force(b) = f;
        bs.moment(b) = m;
        Integrator::advance_body(integrator, bs, b, f, m, dt);
        place_members_of(ps, bs, b);
      });
}

// The bodies of ParticleSet::body over the particles built from the same set
// (their centres, masses and inertias already on the device): each body's
// mass is its members', its centre their centre of mass, its inertia theirs
// about it (Geometry::clump). A body's members are given where they lie
// together, not wrapped across a periodic face. Sets each particle's body
// and the mass a contact on it moves (its body's, or its own).
template <class MemorySpace, class Dim>
struct BodySet {
  Bodies<MemorySpace, Dim> bodies;
  // Per group, the lightest mass a contact moves (0: the group is absent): a
  // free particle's own, a member's body as felt at its centre. For the time step.
  std::vector<double> lightest_contact_mass;

  void build(const ParticleSet& set, Particles<MemorySpace, Dim>& particles) {
    const int n = static_cast<int>(set.size());
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.position);
    auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.mass);
    auto inertia = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.inertia);
    auto specimen = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), particles.specimen);
    auto hcm = Kokkos::create_mirror_view(particles.contact_mass);
    for (int i = 0; i < n; ++i) hcm(i) = mass(i);
    const int nb = set.bodies();
    std::vector<std::vector<int>> members(nb);
    for (int i = 0; i < n && !set.body.empty(); ++i)
      if (set.body[i] >= 0) members[set.body[i]].push_back(i);
    std::size_t total = 0;
    for (int b = 0; b < nb; ++b) {
      if (members[b].empty()) throw std::invalid_argument("vrut::Simulation: body " + std::to_string(b) + " has no member");
      total += members[b].size();
    }
    std::vector<double> member_mass(n, 0.0);
    if (nb > 0) {
      bodies = Bodies<MemorySpace, Dim>(nb, total);
      auto hx = Kokkos::create_mirror_view(bodies.position);
      auto hm = Kokkos::create_mirror_view(bodies.mass);
      auto hi = Kokkos::create_mirror_view(bodies.inertia);
      auto hq = Kokkos::create_mirror_view(bodies.rotation);
      auto hbegin = Kokkos::create_mirror_view(bodies.member_begin);
      auto hmember = Kokkos::create_mirror_view(bodies.member);
      auto hoff = Kokkos::create_mirror_view(bodies.offset);
      auto hbody = Kokkos::create_mirror_view(particles.body);
      Kokkos::deep_copy(hbody, -1);
      int slot = 0;
      for (int b = 0; b < nb; ++b) {
        for (int i : members[b])
          if (specimen(i) != specimen(members[b].front()))
            throw std::invalid_argument("vrut::Simulation: body " + std::to_string(b) + " has members in two specimens");
        hbegin(b) = slot;
        const auto c = Geometry<Dim>::clump(members[b], x, set.radius, mass, inertia);
        hx(b) = c.centre, hm(b) = c.mass, hi(b) = c.inertia, hq(b) = c.rotation;
        for (std::size_t k = 0; k < members[b].size(); ++k) {
          const int i = members[b][k];
          hmember(slot) = i;
          hoff(slot) = c.offsets[k];
          hbody(i) = b;
          hcm(i) = c.mass;
          member_mass[i] = c.felt_mass[k];
          ++slot;
        }
      }
      hbegin(nb) = slot;
      Kokkos::deep_copy(bodies.rotation, hq);
      Kokkos::deep_copy(bodies.position, hx);
      Kokkos::deep_copy(bodies.mass, hm);
      Kokkos::deep_copy(bodies.inertia, hi);
      Kokkos::deep_copy(bodies.member_begin, hbegin);
      Kokkos::deep_copy(bodies.member, hmember);
      Kokkos::deep_copy(bodies.offset, hoff);
      Kokkos::deep_copy(particles.body, hbody);
    }
    Kokkos::deep_copy(particles.contact_mass, hcm);
    int groups = 0;
    for (int g : set.group) groups = std::max(groups, g + 1);
    lightest_contact_mass.assign(groups, 0.0);
    for (int i = 0; i < n; ++i) {
      const double m = nb > 0 && !set.body.empty() && set.body[i] >= 0 ? member_mass[i] : mass(i);
      double& l = lightest_contact_mass[set.group[i]];
      l = l > 0.0 ? std::min(l, m) : m;
    }
  }

  // The bodies' part of a checkpoint (core/simulation.hpp, visit_state):
  // only where there are bodies, so that checkpoints without stay as they were.
  template <class Archive>
  void visit(Archive& a) {
    if (bodies.size() == 0) return;
    a.view("body_position", bodies.position);
    a.view("body_velocity", bodies.velocity);
    a.view("body_force", bodies.force);
    a.view("body_rotation", bodies.rotation);
    a.view("body_angular_velocity", bodies.angular_velocity);
    a.view("body_moment", bodies.moment);
    Geometry<Dim>::visit_body_state(a, bodies);
  }

  // Sets body b's velocity and angular velocity (in 3D the angular momentum
  // that gives it). The caller places the members.
  void set_motion(int b, typename Dim::vector velocity, typename Dim::spin angular_velocity) {
    if (b < 0 || b >= static_cast<int>(bodies.size()))
      throw std::invalid_argument("vrut::Simulation: no body " + std::to_string(b));
    Kokkos::deep_copy(Kokkos::subview(bodies.velocity, b), velocity);
    Kokkos::deep_copy(Kokkos::subview(bodies.angular_velocity, b), angular_velocity);
    Geometry<Dim>::set_angular_momentum(bodies, b, angular_velocity);
  }
};

}  // namespace vrut
