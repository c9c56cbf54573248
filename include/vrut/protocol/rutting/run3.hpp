#pragma once
/// \file
/// The rutting test of 3D boxes (box.hpp) by the one driver (driver.hpp): an
/// ensemble side by side in one Simulation, or one specimen. progress, stop,
/// checkpoints and settling as driver.hpp says.
#include <vrut/protocol/rutting/box.hpp>
#include <vrut/protocol/rutting/driver.hpp>

#include <functional>
#include <vector>

namespace vrut {

/// The 3D rutting test of several specimens side by side in one
/// simulation (they must share one box and sphere size): one result each,
/// in their order, each the same as its own single run would give.
template <class Space, class Checkpoints = NoCheckpoints>
std::vector<RuttingResult3> run_rutting_ensemble3(const std::vector<Specimen3>& specimens, const WheelTracking& wt,
                                                  const RuttingMaterials& mat, const RuttingNumerics& num,
                                                  const Space& space = Space(),
                                                  const std::function<void(double, long)>& progress = {},
                                                  const std::function<bool()>& stop = {},
                                                  Checkpoints* checkpoints = nullptr,
                                                  const std::function<void(long, long)>& settling = {}) {
  return run_rutting_test(BoxSetup(specimens, wt, mat, num), wt, num, space, progress, stop, checkpoints, settling);
}

/// The 3D rutting test of one specimen (box.hpp): settling under gravity,
/// then the plate held at the wheel's pressure for the test's loading time;
/// the deformation curve, the rut depth and the DS (RuttingResult).
template <class Space, class Checkpoints = NoCheckpoints>
RuttingResult3 run_rutting3(const Specimen3& sp, const WheelTracking& wt, const RuttingMaterials& mat,
                            const RuttingNumerics& num, const Space& space = Space(),
                            const std::function<void(double, long)>& progress = {},
                            const std::function<bool()>& stop = {}, Checkpoints* checkpoints = nullptr) {
  return run_rutting_ensemble3(std::vector<Specimen3>{sp}, wt, mat, num, space, progress, stop, checkpoints).front();
}

}  // namespace vrut
