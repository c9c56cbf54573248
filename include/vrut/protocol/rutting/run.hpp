#pragma once
/// \file
/// The rutting test of 2D sections (section.hpp) by the one driver
/// (driver.hpp): an ensemble side by side in one Simulation, or one specimen.
/// progress, stop, checkpoints and settling as driver.hpp says.
#include <vrut/protocol/rutting/driver.hpp>
#include <vrut/protocol/rutting/section.hpp>

#include <functional>
#include <vector>

namespace vrut {

/// The 2D rutting test of several specimens side by side in one simulation:
/// one result each, in their order, each the same as its own single run.
template <class Space, class Checkpoints = NoCheckpoints>
std::vector<RuttingResult> run_rutting_ensemble(const std::vector<Specimen>& specimens, const WheelTracking& wt,
                                                const RuttingMaterials& mat, const RuttingNumerics& num,
                                                const Space& space = Space(),
                                                const std::function<void(double, long)>& progress = {},
                                                const std::function<bool()>& stop = {},
                                                Checkpoints* checkpoints = nullptr,
                                                const std::function<void(long, long)>& settling = {}) {
  return run_rutting_test(SectionSetup(specimens, wt, mat, num), wt, num, space, progress, stop, checkpoints, settling);
}

/// The 2D rutting test of one section (section.hpp): settling under
/// gravity, then the plate held at the wheel's pressure for the test's
/// loading time; the deformation curve, the rut depth and the DS.
template <class Space, class Checkpoints = NoCheckpoints>
RuttingResult run_rutting(const Specimen& sp, const WheelTracking& wt, const RuttingMaterials& mat,
                          const RuttingNumerics& num, const Space& space = Space(),
                          const std::function<void(double, long)>& progress = {},
                          const std::function<bool()>& stop = {}, Checkpoints* checkpoints = nullptr) {
  return run_rutting_ensemble(std::vector<Specimen>{sp}, wt, mat, num, space, progress, stop, checkpoints).front();
}

}  // namespace vrut
