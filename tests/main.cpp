// Catch2 runner that brings Kokkos up for the whole run.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <Kokkos_Core.hpp>

#include <cstdlib>

int main(int argc, char* argv[]) {
  ::setenv("OMP_PROC_BIND", "false", 0);  // quiets Kokkos 3's warning; the runtime already read it
  Kokkos::ScopeGuard kokkos(argc, argv);
  return Catch::Session().run(argc, argv);
}
