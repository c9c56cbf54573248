#pragma once
// Run-time choice of the Kokkos backend, made once in main and dispatched
// into the templates. Host-only.
#include <Kokkos_Core.hpp>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

// Names of the execution spaces this Kokkos was built with, in order of preference.
inline std::vector<std::string> available_backends() {
  std::vector<std::string> names;
#ifdef KOKKOS_ENABLE_SERIAL
  names.push_back("serial");
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  names.push_back("openmp");
#endif
#ifdef KOKKOS_ENABLE_CUDA
  names.push_back("cuda");
#endif
  return names;
}

// Calls f(space) with an instance of the execution space named `name`.
// Throws std::invalid_argument for a name this build does not have.
template <class F>
decltype(auto) dispatch_backend(const std::string& name, F&& f) {
#ifdef KOKKOS_ENABLE_SERIAL
  if (name == "serial") return f(Kokkos::Serial());
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  if (name == "openmp") return f(Kokkos::OpenMP());
#endif
#ifdef KOKKOS_ENABLE_CUDA
  if (name == "cuda") return f(Kokkos::Cuda());
#endif
  std::string known;
  for (const auto& n : available_backends()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown backend '" + name + "' (this build has: " + known + ")");
}

// Starts the Kokkos runtime; threads <= 0 leaves the choice to Kokkos
// (OMP_NUM_THREADS).
inline void initialize_kokkos(int threads) {
  // Kokkos 3 warns when OMP_PROC_BIND is unset. The OpenMP runtime has read
  // its environment already, so this only quiets the warning; the runtime's
  // default (no binding) stays.
  ::setenv("OMP_PROC_BIND", "false", 0);
#if KOKKOS_VERSION >= 30700
  Kokkos::InitializationSettings settings;
  if (threads > 0) settings.set_num_threads(threads);
  Kokkos::initialize(settings);
#else
  Kokkos::InitArguments args;
  if (threads > 0) args.num_threads = threads;
  Kokkos::initialize(args);
#endif
}

// Kokkos for the lifetime of the object, unless it runs already (the Python
// module keeps one runtime for its process): then this session neither
// starts nor ends it.
class KokkosSession {
 public:
  explicit KokkosSession(int threads = 0) {
    if (Kokkos::is_initialized()) return;
    owner_ = true;
    initialize_kokkos(threads);
  }
  ~KokkosSession() {
    if (owner_) Kokkos::finalize();
  }
  KokkosSession(const KokkosSession&) = delete;
  KokkosSession& operator=(const KokkosSession&) = delete;

 private:
  bool owner_ = false;
};

template <class Space>
int concurrency(const Space& space) {
#if KOKKOS_VERSION >= 40000
  return space.concurrency();
#else
  (void)space;
  return Space::concurrency();
#endif
}

}  // namespace vrut
