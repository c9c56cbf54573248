#pragma once
/// \file
/// The 3D digital specimen: gradation -> polyhedral stones -> spheres on an
/// FCC packing (docs/specimen.md, "In 3D"). Same settings and seed, same
/// specimen. Host-only; mm. Needs the target vrut::stones3.
#include <vrut/data/particle_set.hpp>
#include <vrut/specimen/compaction3.hpp>
#include <vrut/specimen/fcc_packing.hpp>
#include <vrut/specimen/placement3.hpp>
#include <vrut/specimen/specimen.hpp>

#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace vrut {

/// How the stones reach their volume fraction: random addition with local
/// jiggling (placement3.hpp), compaction (compaction3.hpp), or the first and,
/// where it jams short of the fraction (3#), the second.
enum class StonePacking3 { automatic, random_addition, compaction };

struct SpecimenSettings3 {
  Gradation gradation = builtin_gradation(2);
  MixVolumetrics mix;
  PlacementSettings3 placement;  // the box (its depth is rounded to whole FCC cells), shape, tries
  StonePacking3 packing = StonePacking3::automatic;
  CompactionSettings3 compaction;
  double sphere_radius = 1.0;    // mm
  double air_voids = 0.04;       // fraction of the box
  std::uint64_t seed = 1;
};

struct Specimen3 {
  double width = 0.0, height = 0.0, depth = 0.0;  // mm; the depth periodic
  std::string name;
  SpecimenSettings3 settings;
  Stereology stereology;  // only its classes and volume fractions: no sections in 3D
  Placement3 placement;
  SpherePacking spheres;
};

/// The stone (index into placement.stones) that holds a point, or
/// mastic_site; the depth is periodic.
class StoneLocator3 {
 public:
  StoneLocator3(const Placement3& p, double width, double height)
      : placement_(p), grid_(width, height, p.depth, 4.0) {
    for (std::size_t s = 0; s < p.stones.size(); ++s) grid_.insert(static_cast<int>(s), p.stones[s].shape.bounds());
  }
  int operator()(const Point3& x) {
    int in = mastic_site;
    for (double image : {0.0, -placement_.depth, placement_.depth}) {
      const Point3 y = x + Point3(0.0, 0.0, image);
      grid_.any_near(Eigen::AlignedBox3d(y, y), [&](int id) {
        if (placement_.stones[id].shape.contains(y)) in = id;
        return in >= 0;
      });
      if (in >= 0) break;
    }
    return in;
  }

 private:
  const Placement3& placement_;
  detail::StoneGrid3 grid_;
};

namespace detail {
/// The specimen's box and classes, before its stones.
inline Specimen3 specimen3_frame(const SpecimenSettings3& s) {
  validate_gradation(s.gradation, [&](std::size_t i) { return s.gradation.name + " row " + std::to_string(i + 1); });
  Specimen3 out;
  out.settings = s;
  out.name = "seed " + std::to_string(s.seed);
  out.width = s.placement.width;
  out.height = s.placement.height;
  out.depth = fcc_cells_deep(s.placement.depth, s.sphere_radius) * fcc_cell(s.sphere_radius);
  out.stereology = stereology(s.gradation, s.mix);
  return out;
}

/// The spheres, once the stones are placed. One stream for the stones, one
/// for the voids, as in 2D: the voids' does not depend on how the stones
/// were placed.
inline void pack_specimen3_spheres(Specimen3& out) {
  const SpecimenSettings3& s = out.settings;
  std::mt19937_64 voids_rng(s.seed ^ 0x9e3779b97f4a7c15ULL);
  StoneLocator3 locate(out.placement, out.width, out.height);
  out.spheres = pack_spheres_by(locate, out.width, out.height, fcc_cells_deep(s.placement.depth, s.sphere_radius),
                                s.sphere_radius, s.air_voids, voids_rng);
}
}  // namespace detail

/// progress(placed, total): the stones' placement, which takes most of the
/// time; compacting(step, total): a compaction's steps, where there is one.
inline Specimen3 generate_specimen3(const SpecimenSettings3& s,
                                    const std::function<void(std::size_t, std::size_t)>& progress = {},
                                    const std::function<void(long, long)>& compacting = {}) {
  Specimen3 out = detail::specimen3_frame(s);
  PlacementSettings3 placement = s.placement;
  placement.depth = out.depth;
  std::mt19937_64 stones_rng(s.seed);
  bool compact = s.packing == StonePacking3::compaction;
  if (!compact) {
    try {
      out.placement = place_stones3(out.stereology, placement, stones_rng, progress);
    } catch (const std::runtime_error&) {  // jammed short of the fraction
      if (s.packing != StonePacking3::automatic) throw;
      compact = true;  // the stream goes on from where the jam left it: the same seed, the same specimen
    }
  }
  if (compact)
    out.placement = compact_stones3(out.stereology, placement, s.compaction, stones_rng, progress, compacting);
  detail::pack_specimen3_spheres(out);
  return out;
}

/// The specimen of these settings on stones placed before (a resumed run's,
/// io/stones3_state.hpp): the same stones give the same specimen as
/// generate_specimen3 gave. Stones of another depth are refused.
inline Specimen3 specimen3_on_stones(const SpecimenSettings3& s, Placement3 stones) {
  Specimen3 out = detail::specimen3_frame(s);
  if (stones.depth != out.depth)
    throw std::invalid_argument("stones placed in a box " + std::to_string(stones.depth) + " mm deep do not fit a "
                                "specimen " + std::to_string(out.depth) + " mm deep");
  out.placement = std::move(stones);
  detail::pack_specimen3_spheres(out);
  return out;
}

/// The spheres as DEM input, in metres; groups as in 2D (SpecimenGroup). A
/// stone across the periodic depth keeps its spheres together: each takes
/// the image nearest its stone's centroid (the engine's positions need not
/// lie in the box), so that a stone's spheres can make one rigid body.
inline ParticleSet to_particle_set(const Specimen3& sp, double mastic_density, double aggregate_density) {
  ParticleSet set;
  const double r = sp.spheres.radius * 1e-3;
  for (std::size_t i = 0; i < sp.spheres.centers.size(); ++i) {
    const int s = sp.spheres.stone[i];
    const bool stone = s >= 0;
    Point3 c = sp.spheres.centers[i];
    if (stone) c.z() += sp.depth * std::round((sp.placement.stones[s].shape.centroid.z() - c.z()) / sp.depth);
    set.add_sphere(c.x() * 1e-3, c.y() * 1e-3, c.z() * 1e-3, r, stone ? aggregate_density : mastic_density,
                   stone ? aggregate_group : mastic_group);
  }
  return set;
}

}  // namespace vrut
