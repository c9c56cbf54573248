#pragma once
// A box whose faces may be periodic, axis by axis, as the 3D rutting slab is
// along its depth: a particle that leaves through one face comes back
// through the other, and two particles see each other through the face by
// the nearest image. Usable in Kokkos kernels.
#include <vrut/data/dimension.hpp>
#include <vrut/data/vec2.hpp>
#include <vrut/data/vec3.hpp>

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace vrut {

struct PeriodicBox3 {
  Vec3 low, high;                         // the box's corners
  bool periodic[3] = {false, false, false};  // per axis x, y, z

  KOKKOS_INLINE_FUNCTION double length(int k) const { return component(high, k) - component(low, k); }

  // The separation a -> b through the nearest image along the periodic
  // axes (each component within half the box's length there).
  KOKKOS_INLINE_FUNCTION Vec3 separation(Vec3 a, Vec3 b) const {
    Vec3 d = b - a;
    for (int k = 0; k < 3; ++k)
      if (periodic[k]) {
        const double l = length(k);
        component(d, k) -= l * floor(component(d, k) / l + 0.5);
      }
    return d;
  }

  // x brought back into the box along the periodic axes.
  KOKKOS_INLINE_FUNCTION Vec3 wrapped(Vec3 x) const {
    for (int k = 0; k < 3; ++k)
      if (periodic[k]) {
        const double l = length(k), lo = component(low, k);
        double& c = component(x, k);
        c -= l * floor((c - lo) / l);
        if (c >= lo + l) c = lo;  // rounding can land it on the far face
      }
    return x;
  }
};

// The plane has no periodic axis (yet): the separation is the difference.
struct OpenBox2 {
  bool periodic[2] = {false, false};
  Vec2 low, high;
  KOKKOS_INLINE_FUNCTION double length(int k) const { return component(high, k) - component(low, k); }
  KOKKOS_INLINE_FUNCTION Vec2 separation(Vec2 a, Vec2 b) const { return b - a; }
};

// The box an engine of dimension D keeps its particles in.
template <class D>
using PeriodicBox = std::conditional_t<is_3d<D>, PeriodicBox3, OpenBox2>;

}  // namespace vrut
