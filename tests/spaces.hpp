#pragma once
// The execution spaces every backend-generic test runs on.
#include <Kokkos_Core.hpp>

#include <tuple>

namespace vrut_test {

using ExecutionSpaces = std::tuple<
#ifdef KOKKOS_ENABLE_SERIAL
    Kokkos::Serial
#endif
#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP)
    ,
#endif
#ifdef KOKKOS_ENABLE_OPENMP
    Kokkos::OpenMP
#endif
#if defined(KOKKOS_ENABLE_CUDA) && (defined(KOKKOS_ENABLE_SERIAL) || defined(KOKKOS_ENABLE_OPENMP))
    ,
#endif
#ifdef KOKKOS_ENABLE_CUDA
    Kokkos::Cuda
#endif
    >;

template <class View>
auto to_host(const View& v) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
}

}  // namespace vrut_test
