#pragma once
/// \file
/// The digital specimen: gradation -> stereology -> aggregates -> disks.
/// Same settings and seed, same specimen. Host-only; mm.
#include <vrut/data/particle_set.hpp>
#include <vrut/specimen/packing.hpp>
#include <vrut/specimen/placement.hpp>
#include <vrut/specimen/stereology.hpp>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>

namespace vrut {

struct SpecimenSettings {
  Gradation gradation = builtin_gradation(2);
  MixVolumetrics mix;
  PlacementSettings placement;  // section size, shape, attempts
  double disk_radius = 0.5;     // mm
  double air_voids = 0.04;      // fraction of the section
  std::uint64_t seed = 1;
};

/// A specimen as the protocols see it: the section's size, the stones (their
/// outlines) and the disks. A source fills it: the generator here, or an image
/// (specimen/image.hpp). `settings` and `stereology` are the generator's, and
/// hold the defaults for a specimen from an image.
struct Specimen {
  double width = 0.0, height = 0.0;  // the section, mm
  std::string name;                  // what it is, for messages: "seed 3", "image core.png"
  SpecimenSettings settings;
  Stereology stereology;
  Placement placement;
  DiskPacking disks;

  std::size_t aggregate_disks() const {
    std::size_t n = 0;
    for (int a : disks.aggregate) n += a >= 0;
    return n;
  }
};

inline Specimen generate_specimen(const SpecimenSettings& s) {
  validate_gradation(s.gradation, [&](std::size_t i) { return s.gradation.name + " row " + std::to_string(i + 1); });
  Specimen out;
  out.width = s.placement.width;
  out.height = s.placement.height;
  out.name = "seed " + std::to_string(s.seed);
  out.settings = s;
  out.stereology = stereology(s.gradation, s.mix);
  /// One stream for the aggregates, one for the voids: changing the void
  /// fraction leaves the aggregates where they were.
  std::mt19937_64 aggregates_rng(s.seed), voids_rng(s.seed ^ 0x9e3779b97f4a7c15ULL);
  out.placement = place_aggregates(out.stereology, s.placement, aggregates_rng);
  out.disks = pack_disks(out.placement, s.placement.width, s.placement.height, s.disk_radius, s.air_voids, voids_rng);
  return out;
}

/// Material groups for the DEM: 0 mastic, 1 aggregate.
enum SpecimenGroup : int { mastic_group = 0, aggregate_group = 1 };

/// The disks as DEM input, in metres.
inline ParticleSet to_particle_set(const Specimen& sp, double mastic_density, double aggregate_density) {
  ParticleSet set;
  const double r = sp.disks.radius * 1e-3;
  for (std::size_t i = 0; i < sp.disks.centers.size(); ++i) {
    const bool agg = sp.disks.aggregate[i] >= 0;
    set.add(sp.disks.centers[i].x() * 1e-3, sp.disks.centers[i].y() * 1e-3, r,
            agg ? aggregate_density : mastic_density, agg ? aggregate_group : mastic_group);
  }
  return set;
}

}  // namespace vrut
