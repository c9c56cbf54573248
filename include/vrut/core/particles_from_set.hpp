#pragma once
// The engine's particles from a ParticleSet (data/particle_set.hpp), checked:
// each particle's centre, radius, mass and inertia (Geometry<Dim>), material
// group and specimen; and where each specimen's particles begin. And the
// particles' part of a checkpoint.
#include <vrut/core/geometry.hpp>
#include <vrut/data/particle_set.hpp>
#include <vrut/data/particles.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct ParticlesFromSet {
  std::vector<int> specimen_begin;  // specimen s: particles specimen_begin[s] .. specimen_begin[s + 1] - 1
  double largest_radius = 0.0;

  template <class MemorySpace>
  Kokkos::View<int*, MemorySpace> specimen_begin_view() const {
    Kokkos::View<int*, MemorySpace> view("specimen_begin", specimen_begin.size());
    auto host = Kokkos::create_mirror_view(view);
    for (std::size_t k = 0; k < specimen_begin.size(); ++k) host(k) = specimen_begin[k];
    Kokkos::deep_copy(view, host);
    return view;
  }
};

// Fills `particles` (of set.size()) from the set; groups: the law table's.
// thickness: a 2D disk's width (Geometry<Dim2>::mass).
template <class MemorySpace, class Dim>
ParticlesFromSet fill_particles(const ParticleSet& set, int groups, double thickness,
                                Particles<MemorySpace, Dim>& particles) {
  using G = Geometry<Dim>;
  if (set.size() == 0) throw std::invalid_argument("vrut::Simulation: no particles");
  G::check(set, thickness);
  const int n = static_cast<int>(set.size());
  auto h = Kokkos::create_mirror_view(particles.position);
  auto hr = Kokkos::create_mirror_view(particles.radius);
  auto hm = Kokkos::create_mirror_view(particles.mass);
  auto hi = Kokkos::create_mirror_view(particles.inertia);
  auto hg = Kokkos::create_mirror_view(particles.group);
  auto hs = Kokkos::create_mirror_view(particles.specimen);
  if (!set.specimen.empty() && set.specimen.size() != set.size())
    throw std::invalid_argument("vrut::Simulation: the specimen index list has the wrong length");
  if (!set.body.empty() && set.body.size() != set.size())
    throw std::invalid_argument("vrut::Simulation: the body index list has the wrong length");
  ParticlesFromSet out;
  out.specimen_begin.assign(1, 0);
  for (int i = 0; i < n; ++i) {
    if (set.group[i] >= groups)
      throw std::invalid_argument("vrut::Simulation: disk " + std::to_string(i) + " has group " +
                                  std::to_string(set.group[i]) + " but the table has " + std::to_string(groups) +
                                  " groups");
    h(i) = G::centre(set, i);
    hm(i) = G::mass(set.density[i], set.radius[i], thickness);
    hi(i) = G::inertia(hm(i), set.radius[i]);
    hr(i) = set.radius[i];
    hg(i) = set.group[i];
    hs(i) = set.specimen.empty() ? 0 : set.specimen[i];
    const int previous = i == 0 ? 0 : hs(i - 1);
    if (hs(i) != previous && hs(i) != previous + 1)
      throw std::invalid_argument("vrut::Simulation: disk " + std::to_string(i) + " has specimen " +
                                  std::to_string(hs(i)) + " after " + std::to_string(previous) +
                                  " (each specimen's disks must be contiguous, in order from 0)");
    if (hs(i) != previous) out.specimen_begin.push_back(i);
    out.largest_radius = std::max(out.largest_radius, set.radius[i]);
  }
  out.specimen_begin.push_back(n);
  Kokkos::deep_copy(particles.position, h);
  Kokkos::deep_copy(particles.radius, hr);
  Kokkos::deep_copy(particles.mass, hm);
  Kokkos::deep_copy(particles.inertia, hi);
  Kokkos::deep_copy(particles.group, hg);
  Kokkos::deep_copy(particles.specimen, hs);
  return out;
}

// The particles' part of a checkpoint (core/simulation.hpp, visit_state):
// what changes as they move; what the set fixes is built again.
template <class Archive, class MemorySpace, class Dim>
void visit_particles(Archive& a, Particles<MemorySpace, Dim>& p) {
  a.view("position", p.position);
  a.view("velocity", p.velocity);
  a.view("force", p.force);
  a.view("external_force", p.external_force);
  a.view("displacement", p.displacement);
  a.view("rotation", p.rotation);
  a.view("angular_velocity", p.angular_velocity);
  a.view("moment", p.moment);
  a.view("fixity", p.fixity);
}

}  // namespace vrut
