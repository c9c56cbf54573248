#pragma once
// What holds a rutting specimen up (the skeleton's diagnostics), in 2D and 3D:
//   - the load path: the vertical force that crosses a horizontal cut (the
//     runs put it half way between the floor and the plate), under the
//     plate, by the class of contact
//     that carries it: two stones bearing on the stones' spring (their
//     overlap beyond the film between them, or no film at all), two stones
//     on their film alone, and contacts with mastic;
//   - the stones' film census: the contacts between two stones' particles
//     by the thickness of the film between them (as the reach bins give it),
//     and how many of them bear on the stones' spring.
// Host-only: it copies the particles and the contact list to the host.
//
// The cut. A particle lies above or below it by its centre; a stone's
// particles (one rigid body, or the method's bonded disks) all lie where the
// stone's centroid lies, so that the load a stone carries inside itself
// from one side to the other is counted where it enters the stone. Then
// every force from below to above the cut acts in a contact between a
// particle below and one above (overlapping, or held across a gap by a
// bond). Over the whole width those forces sum to what the part above
// passes down: the plate's load and the weight above, less what the
// mould's walls hold (nothing where they are frictionless). Under the plate
// alone (the contact's point between the plate's ends, and in 3D within
// its width across the depth), as measured here,
// the cut is not a closed free body: the load spreads sideways past the
// plate's ends. The shares are of what crosses under the plate.
#include <vrut/protocol/rutting/depth_band.hpp>
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/skeleton_record.hpp>
#include <vrut/specimen/specimen.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vrut {

static_assert(film_census_bins == film_reach_classes + 1, "the census has a bin for each film thickness the reach bins give");

// Where a specimen is cut (m), and its particles' diameter (m), which the
// films' thickness is counted in.
struct SkeletonCut {
  double height = 0.0;         // the cut's
  double x0 = 0.0, x1 = 0.0;   // the plate's ends
  DepthBand depth;             // 3D: where the plate lies across the depth (all of it: a strip)
  double diameter = 0.0;
};

// How a contact between particles of groups a and b, overlapping by
// `overlap` (m), carries its load under a rutting table.
enum class ContactClass { stone_spring, stone_film, mastic };

inline ContactClass classify_contact(const RuttingLaw::params_type& p, int group_a, int group_b, double overlap) {
  if (group_a == mastic_group || group_b == mastic_group) return ContactClass::mastic;
  if (p.use_second) return ContactClass::stone_spring;  // stones meeting bare (no film)
  const auto& film = p.first.normal;
  return film.stone_stiffness > 0.0 && overlap > film.thickness ? ContactClass::stone_spring : ContactClass::stone_film;
}

// The film between two stones' particles, in diameters (0 where they meet bare).
inline double film_thickness(const RuttingLaw::params_type& p, double diameter) {
  return p.use_second ? 0.0 : p.first.normal.thickness / diameter;
}

struct SkeletonSnapshot {
  LoadPath load;
  FilmCensus films;
};

// The load path across `cut` and the film census of specimen e of `sim`, its
// contact table `table`, at the contacts' last computed loads. stone[i]: the
// stone of the specimen's particle i (-1 for mastic), as the specimen gives
// it (Specimen::disks.aggregate, Specimen3::spheres.stone).
template <class Sim>
SkeletonSnapshot skeleton_snapshot(const Sim& sim, const AssignmentTable<RuttingLaw>& table, int e,
                                   const SkeletonCut& cut, const std::vector<int>& stone) {
  const auto& ps = sim.particles();
  const auto& cl = sim.contacts();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.position);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.radius);
  auto group = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.group);
  auto partner = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cl.partner);
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cl.count);
  auto load = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cl.load);
  const auto box = cl.box;  // the nearest image across a periodic axis
  // Not a structured binding: the lambda below uses `first` (C++17 lets no lambda capture one).
  const auto range = sim.specimen_range(e);
  const int first = range.first, last = range.second;

  // Each stone's centroid height: its particles' mean (they share a size and
  // a density, so that is its centre of mass). A rigid stone is one body;
  // the method's bonded stones (--exact-stones) are stones all the same.
  std::vector<double> stone_height, stone_members;
  for (int i = first; i < last; ++i) {
    const int a = stone[i - first];
    if (a < 0) continue;
    if (a >= static_cast<int>(stone_height.size())) stone_height.resize(a + 1, 0.0), stone_members.resize(a + 1, 0.0);
    stone_height[a] += x(i).y;
    stone_members[a] += 1.0;
  }
  auto above = [&](int i) {
    const int a = stone[i - first];
    return (a >= 0 ? stone_height[a] / stone_members[a] : x(i).y) > cut.height;
  };

  SkeletonSnapshot out;
  for (int i = first; i < last; ++i)
    for (int k = 0; k < count(i); ++k) {
      const int j = partner(i, k);
      const auto d = box.separation(x(i), x(j));  // from i to j
      const double dist = norm(d);
      const double overlap = r(i) + r(j) - dist;
      const auto force = load(i, k).force;  // on j
      // A contact acts where it overlaps, or where a bond holds it across a
      // gap (the mastic's bonds pull, and their Burger's history can push).
      if (!(overlap > 0.0) && !(dot(force, force) > 0.0)) continue;
      const auto& p = table(group(i), group(j));
      const ContactClass c = classify_contact(p, group(i), group(j), overlap);
      const int stone_i = stone[i - first], stone_j = stone[j - first];
      if (stone_i >= 0 && stone_j >= 0 && stone_i != stone_j && overlap > 0.0) {
        const double t = film_thickness(p, cut.diameter);
        const int bin = std::min(film_census_bins - 1, std::max(0, static_cast<int>(std::lround(t / film_census_step))));
        ++out.films.contacts[bin];
        if (c == ContactClass::stone_spring) ++out.films.bearing[bin];
      }
      const bool i_above = above(i), j_above = above(j);
      if (i_above == j_above) continue;  // within one stone, or on one side
      // The contact's point: the middle of the overlap (or gap) on the line of centres.
      const auto point = x(i) + ((r(i) - 0.5 * overlap) / dist) * d;
      if (point.x < cut.x0 || point.x > cut.x1 || !in_depth_band(cut.depth, point)) continue;
      // The part above takes the force from below.
      const double up = j_above ? force.y : -force.y;
      if (c == ContactClass::stone_spring)
        out.load.stone_spring += up;
      else if (c == ContactClass::stone_film)
        out.load.stone_film += up;
      else
        out.load.mastic += up;
    }
  return out;
}

}  // namespace vrut
