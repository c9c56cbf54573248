#pragma once
// A Serial = OpenMP test proves nothing when OpenMP runs one thread: the
// sums would be in one order on both. It must run on several wherever the
// machine has several cores; on a one-core machine it is skipped, saying so.
#include <Kokkos_Core.hpp>

#include <catch2/catch.hpp>

#include <thread>

namespace vrut_test {

#ifdef KOKKOS_ENABLE_OPENMP
// True where the comparison can run; fails the test where the machine has
// several cores but OpenMP was given one (OMP_NUM_THREADS=1, say).
inline bool openmp_runs_several_threads() {
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores == 1) {
    WARN("SKIPPED: one core, so OpenMP runs one thread and Serial = OpenMP would prove nothing");
    return false;
  }
  INFO(cores << " cores; OpenMP runs " << Kokkos::OpenMP().concurrency()
             << " threads (set OMP_NUM_THREADS=2 or more)");
  REQUIRE(Kokkos::OpenMP().concurrency() > 1);
  return true;
}
#endif

}  // namespace vrut_test
