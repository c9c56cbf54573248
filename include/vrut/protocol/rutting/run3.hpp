#pragma once
// The rutting test of 3D boxes (box.hpp) by the one driver (driver.hpp): an
// ensemble side by side in one Simulation, or one specimen. progress, stop,
// checkpoints and settling as driver.hpp says.
#include <vrut/protocol/rutting/box.hpp>
#include <vrut/protocol/rutting/driver.hpp>

#include <functional>
#include <vector>

namespace vrut {

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

template <class Space, class Checkpoints = NoCheckpoints>
RuttingResult3 run_rutting3(const Specimen3& sp, const WheelTracking& wt, const RuttingMaterials& mat,
                            const RuttingNumerics& num, const Space& space = Space(),
                            const std::function<void(double, long)>& progress = {},
                            const std::function<bool()>& stop = {}, Checkpoints* checkpoints = nullptr) {
  return run_rutting_ensemble3(std::vector<Specimen3>{sp}, wt, mat, num, space, progress, stop, checkpoints).front();
}

}  // namespace vrut
