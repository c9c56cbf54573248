#pragma once
// Bonds on the contact list (a law's optional bond(), contact/concept.hpp),
// and counts of its contacts. The list must have been built.
#include <vrut/contact/concept.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace vrut {

// Bonds every listed pair whose gap is at most tolerance (m). Returns the count.
template <class Law, class Space, class Particles, class Contacts, class Box>
int bond_touching_contacts(const Space& space, const Particles& ps, const Contacts& contacts, const Box& box,
                           double tolerance) {
  auto partner = contacts.partner;
  auto count = contacts.count;
  auto state = contacts.state;
  int bonded = 0;
  Kokkos::parallel_reduce("vrut::bond", Kokkos::RangePolicy<Space>(space, 0, ps.size()),
      KOKKOS_LAMBDA(const int i, int& sum) {
        for (int k = 0; k < count(i); ++k) {
          const int j = partner(i, k);
          const double gap = norm(box.separation(ps.position(i), ps.position(j))) - ps.radius(i) - ps.radius(j);
          if (gap <= tolerance) {
            make_bonded<Law>(state(i, k));
            if (is_bonded<Law>(state(i, k))) ++sum;
          }
        }
      },
      bonded);
  return bonded;
}

// Bonds the given pairs (each i != j), and only those. Returns how many were
// listed (in contact range) and got a bond.
template <class Law, class Space, class Contacts>
int bond_pairs(const Space& space, const Contacts& contacts, const std::vector<std::pair<int, int>>& pairs) {
  Kokkos::View<int* [2], typename Space::memory_space> dev("bond_pairs", pairs.size());
  auto host = Kokkos::create_mirror_view(dev);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    host(k, 0) = std::min(pairs[k].first, pairs[k].second);
    host(k, 1) = std::max(pairs[k].first, pairs[k].second);
  }
  Kokkos::deep_copy(dev, host);
  auto partner = contacts.partner;
  auto count = contacts.count;
  auto state = contacts.state;
  int bonded = 0;
  Kokkos::parallel_reduce("vrut::bond_pairs", Kokkos::RangePolicy<Space>(space, 0, pairs.size()),
      KOKKOS_LAMBDA(const int k, int& sum) {
        const int i = dev(k, 0), j = dev(k, 1);
        for (int q = 0; q < count(i); ++q)
          if (partner(i, q) == j) {
            make_bonded<Law>(state(i, q));
            if (is_bonded<Law>(state(i, q))) ++sum;
          }
      },
      bonded);
  return bonded;
}

// The listed pairs of particles [first, last) that touch (or are bonded), or
// with bonds_only those with an intact bond.
template <class Law, class Space, class Particles, class Contacts, class Box>
int count_contacts(const Space& space, const Particles& ps, const Contacts& contacts, const Box& box, bool bonds_only,
                   int first, int last) {
  auto partner = contacts.partner;
  auto count = contacts.count;
  auto state = contacts.state;
  int total = 0;
  Kokkos::parallel_reduce("vrut::count_contacts", Kokkos::RangePolicy<Space>(space, first, last),
      KOKKOS_LAMBDA(const int i, int& sum) {
        for (int k = 0; k < count(i); ++k) {
          const bool bonded = is_bonded<Law>(state(i, k));
          const int j = partner(i, k);
          const bool touching = norm(box.separation(ps.position(i), ps.position(j))) < ps.radius(i) + ps.radius(j);
          if (bonds_only ? bonded : (bonded || touching)) ++sum;
        }
      },
      total);
  return total;
}

}  // namespace vrut
