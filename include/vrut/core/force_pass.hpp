#pragma once
// Where a contact force is computed: for every listed pair (i, j) of the
// contact list, from the positions at t and the velocities at t - dt/2, its
// law's force and the load it leaves in the pair's slot (core/contact_load.hpp).
// The loads are summed per particle in core/sum_and_advance.hpp.
#include <vrut/contact/concept.hpp>
#include <vrut/core/contact_load.hpp>
#include <vrut/core/geometry.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

// params(a, b): the law's parameters between material groups a and b; box:
// the separation through the nearest periodic image.
template <class Law, class Space, class Particles, class Contacts, class Params, class Box>
void contact_forces(const Space& space, const Particles& ps, const Contacts& contacts, const Params& params,
                    const Box& box, double dt) {
  using Dim = typename Particles::dimension;
  using vector = typename Dim::vector;
  auto partner = contacts.partner;
  auto count = contacts.count;
  auto state = contacts.state;
  auto load = contacts.load;
  Kokkos::parallel_for("vrut::contact_forces", Kokkos::RangePolicy<Space>(space, 0, ps.size()),
      KOKKOS_LAMBDA(const int i) {
        for (int k = 0; k < count(i); ++k) {
          const int j = partner(i, k);
          const vector d = box.separation(ps.position(i), ps.position(j));
          if (Geometry<Dim>::apart_at_a_glance(d, ps.radius(i) + ps.radius(j)) && !is_bonded<Law>(state(i, k))) {
            forget_contact<Law>(state(i, k));
            load(i, k) = ContactLoadIn<Dim>{};
            continue;
          }
          const double dist = norm(d);
          ContactGeometryIn<Dim> g;
          g.normal = (1.0 / dist) * d;
          g.overlap = ps.radius(i) + ps.radius(j) - dist;
          if (g.overlap <= 0.0 && !is_bonded<Law>(state(i, k))) {
            forget_contact<Law>(state(i, k));
            load(i, k) = ContactLoadIn<Dim>{};
            continue;
          }
          load(i, k) = Geometry<Dim>::template pair_load<Law>(params(ps.group(i), ps.group(j)), state(i, k), g, d, ps,
                                                              i, j, dt);
        }
      });
}

}  // namespace vrut
