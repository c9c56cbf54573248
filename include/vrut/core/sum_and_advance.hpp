#pragma once
// Where the forces on a particle are summed, and a free particle advances:
// its external force and weight, its contacts' loads from both sides of the
// contact list in a fixed order (no atomics: the same sum on any backend and
// thread count), and its contacts with its specimen's walls, computed here
// (core/wall_set.hpp holds their state). A rigid body's member is summed but
// does not advance: its body does (core/body_set.hpp).
#include <vrut/contact/concept.hpp>
#include <vrut/core/contact_load.hpp>
#include <vrut/core/geometry.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

template <class Integrator, class WallLaw, class Space, class Particles, class Contacts, class Walls>
void sum_and_advance(const Space& space, const Particles& ps, const Contacts& contacts, const Walls& walls,
                     typename Particles::vector gravity, const typename Integrator::params_type& integrator, double dt) {
  using Dim = typename Particles::dimension;
  using vector = typename Dim::vector;
  using spin = typename Dim::spin;
  using WallMask = typename Walls::WallMask;
  using wall_state_type = typename Walls::state_type;
  using wall_load_type = typename Walls::wall_load_type;
  auto count = contacts.count;
  auto load = contacts.load;
  auto rev = contacts.reverse;
  auto rcount = contacts.reverse_count;
  const int cap = contacts.capacity;
  auto wall_view = walls.walls;
  auto wnormal = walls.normal;
  auto wparams = walls.params;
  auto wstate = walls.state;
  auto wload = walls.load;
  auto wtouch = walls.touch;
  auto swalls = walls.specimen_walls;
  auto swall_count = walls.specimen_wall_count;
  Kokkos::parallel_for("vrut::sum_and_advance", Kokkos::RangePolicy<Space>(space, 0, ps.size()),
      KOKKOS_LAMBDA(const int i) {
        vector f = ps.external_force(i) + ps.mass(i) * gravity;
        spin m{};
        for (int k = 0; k < count(i); ++k) {
          f -= load(i, k).force;
          m += load(i, k).moment_first;
        }
        for (int q = 0; q < rcount(i); ++q) {
          const int c = rev(i, q);
          const ContactLoadIn<Dim>& l = load(c / cap, c % cap);
          f += l.force;
          m += l.moment_second;
        }
        // The walls of this particle's specimen, by slot: (particle, slot)
        // indexes the wall state and load. A slot whose bit in wall_touch is
        // clear holds the default state and a zero load: most particles touch
        // no wall, and skipping their slots saves most of the memory traffic
        // the walls would cost.
        const int sp = ps.specimen(i);
        const WallMask held = wtouch(i);
        WallMask holds = 0;
        for (int q = 0; q < swall_count(sp); ++q) {
          const int w = swalls(sp, q);
          if (!((held >> q) & 1u) && !Geometry<Dim>::may_reach(wall_view(w), wnormal(w), ps.position(i), ps.radius(i)))
            continue;
          ContactGeometryIn<Dim> g;
          const double dist = wall_distance(wall_view(w), ps.position(i), g.normal);
          g.overlap = ps.radius(i) - dist;
          if (g.overlap <= 0.0 && !((held >> q) & 1u)) continue;
          if (g.overlap <= 0.0 && !is_bonded<WallLaw>(wstate(i, q))) {
            wstate(i, q) = wall_state_type{};
            wload(i, q) = wall_load_type{};
            continue;
          }
          holds |= WallMask(1) << q;
          const WallPushIn<Dim> push =
              Geometry<Dim>::template wall_push<WallLaw>(wparams(w), wstate(i, q), g, wall_view(w).velocity, ps, i, dt);
          f += push.force;
          m -= push.lever;
          wall_load_type wl;
          wl.force = -push.force;
          wl.contacts = g.overlap > 0.0 ? 1.0 : 0.0;
          wload(i, q) = wl;
        }
        wtouch(i) = holds;
        ps.force(i) = f;
        ps.moment(i) = m;
        if (ps.body(i) < 0) Integrator::advance(integrator, ps, i, f, m, dt);  // a member moves with its body
      });
}

}  // namespace vrut
