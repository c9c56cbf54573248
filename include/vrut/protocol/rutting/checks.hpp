#pragma once
// What the rutting run checks and counts on its specimens, in 2D and 3D
// alike (driver.hpp): that every particle stays in its mould, and which
// stones touch at the end. What a specimen's particles are called and how
// their places are written, section.hpp and box.hpp say
// (mould_particle_radius_mm, mould_particle_word, mould_position_text, found
// by their argument types).
#include <vrut/core/simulation.hpp>
#include <vrut/protocol/rutting/depth_band.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vrut {

// Throws SimulationUnstable when a disk (a sphere in 3D) has left its mould
// (through a wall or over the top): a run with too large a time step can push
// disks through the stiff walls without any single step jumping far enough
// for the engine's own check. Called at every sample.
template <class Sim, class SpecimenT>
void check_inside_moulds(Sim& sim, const std::vector<SpecimenT>& specimens, long step, double dt) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  for (int e = 0; e < static_cast<int>(specimens.size()); ++e) {
    const double w = specimens[e].width * 1e-3, h = specimens[e].height * 1e-3;
    const double r = mould_particle_radius_mm(specimens[e]) * 1e-3;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i) {
      const auto p = x(i);
      const double px = p.x, py = p.y;
      if (!(px > -r && px < w + r && py > -r && py < 2.0 * h)) {
        char where[400];
        std::snprintf(where, sizeof where, "%s %d of specimen %d (%.200s) is at %s mm, outside its %g x %g mm mould",
                      mould_particle_word(specimens[e]), i - first, e, specimens[e].name.c_str(),
                      mould_position_text(p).c_str(), w * 1e3, h * 1e3);
        char text[700];
        std::snprintf(text, sizeof text,
                      "vrut: the rutting run became unstable by loading step %ld: %s. The time step is %.3g of "
                      "sqrt(m_min / k_max); lower the time-step safety (RuttingNumerics::timestep_safety, 0.3 by default).",
                      step, where, dt / sim.critical_timestep());
        throw SimulationUnstable(text, step);
      }
    }
  }
}

// Throws when a sphere under a 3D patch plate's span along the travel (x0 to
// x1, m) has flowed across the periodic depth under the patch's image, which
// the plate does not hold (box.hpp): the box is too shallow for the run. A
// strip plate (and a 2D section) has no image to reach. Called at every sample.
template <class Sim, class SpecimenT>
void check_clear_of_plate_images(Sim& sim, const std::vector<SpecimenT>& specimens, const DepthBand& band,
                                 double x0, double x1, long step) {
  if (!(band.half > 0.0)) return;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  for (int e = 0; e < static_cast<int>(specimens.size()); ++e) {
    const double r = mould_particle_radius_mm(specimens[e]) * 1e-3;
    const auto [first, last] = sim.specimen_range(e);
    for (int i = first; i < last; ++i)
      if (x(i).x > x0 - r && x(i).x < x1 + r && in_band_image_only(band, x(i), r)) {
        char text[600];
        std::snprintf(text, sizeof text,
                      "vrut: by loading step %ld %s %d of specimen %d is at %s mm, under the patch plate's periodic "
                      "image a box's depth away, which the plate does not hold; give a deeper box (--depth-mm)",
                      step, mould_particle_word(specimens[e]), i - first, e, mould_position_text(x(i)).c_str());
        throw std::runtime_error(text);
      }
  }
}

// The pairs of stones of specimen e that touch at the end, found in the
// contact list (every overlapping pair of particles is in it), and the
// stones that hold particles. stone[i]: particle i's stone in the specimen
// (-1 for mastic), of stone_count.
template <class Sim>
std::pair<int, int> touching_stones(const Sim& sim, const std::vector<int>& stone, std::size_t stone_count, int e) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().position);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.particles().radius);
  auto partner = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.contacts().partner);
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sim.contacts().count);
  const auto box = sim.contacts().box;  // the nearest image across a periodic axis
  const auto [first, last] = sim.specimen_range(e);
  std::vector<std::pair<int, int>> pairs;
  std::vector<char> holds(stone_count, 0);
  for (int i = first; i < last; ++i) {
    if (stone[i - first] >= 0) holds[stone[i - first]] = 1;
    for (int k = 0; k < count(i); ++k) {
      const int j = partner(i, k);
      const int a = stone[i - first], b = stone[j - first];
      if (a >= 0 && b >= 0 && a != b && norm(box.separation(x(i), x(j))) < r(i) + r(j))
        pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  const int distinct = static_cast<int>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  int stones = 0;
  for (char h : holds) stones += h;
  return {stones, distinct};
}

}  // namespace vrut
