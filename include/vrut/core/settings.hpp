#pragma once
/// \file
/// A simulation's settings: a 2D disk's thickness, gravity, the contact
/// list's skin, and in 3D the box with its periodic axes.
#include <vrut/data/dimension.hpp>
#include <vrut/neighbor/periodic_box3.hpp>

namespace vrut {

template <class D>
struct SimulationSettingsIn {
  double thickness = 1.0;     // 2D: out-of-plane disk width t, m: mass = rho pi r^2 t (3D: rho 4/3 pi r^3)
  typename D::vector gravity;  // m/s^2
  double skin = -1.0;         // neighbour-list margin, m; < 0: 0.2 * the largest radius
  // 3D: the box, and which of its axes are periodic (none by default).
  PeriodicBox<D> box;
};
using SimulationSettings = SimulationSettingsIn<Dim2>;

}  // namespace vrut
