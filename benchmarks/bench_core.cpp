// Throughput of the DEM core in particle-steps per second, per backend, on a
// bonded hex-packed block under a servo plate (the demo's job). Compare the
// backends by the ratios within one run: the machines are shared and noisy.
//
//   ./build/benchmarks/vrut-bench-core --benchmark_counters_tabular=true
#include <vrut/backend.hpp>
#include <vrut/vrut.hpp>

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

template <class Space>
void step_block(benchmark::State& state) {
  using namespace vrut;
  const int columns = static_cast<int>(state.range(0)), rows = columns / 2;
  const double r = 0.5e-3, t = 0.05, kn = 2.0 * t * 55.5e6;
  AssignmentTable<LinearBonded> table;
  table.set_all(linear_bonded_params(kn, kn / 2.7, 0.5, 1e30, 1e30));
  SimulationSettings settings;
  settings.thickness = t;
  Simulation<LinearBonded, Space, CentralDifference, ServoControl> sim(hex_packing(columns, rows, r, 2700.0), table,
                                                                       settings, {0.7});
  sim.bond_touching_contacts(1e-9 * r);
  const double width = 2.0 * r * columns + r, top = r * (2.0 + std::sqrt(3.0) * (rows - 1));
  sim.add_wall(Wall{{0.0, 0.0}, {width, 0.0}, {}}, linear_params(kn, 0.0, 0.0));
  sim.add_wall(Wall{{width, top}, {0.0, top}, {}}, linear_params(kn, 0.0, 0.0),
               ServoControl::for_stress(0.7e6, width, t, kn, 0.2, 0.05));
  const double dt = 0.2 * sim.critical_timestep();
  sim.run(100, dt);  // first list build and warm caches
  for (auto _ : state) {
    sim.step(dt);
  }
  Kokkos::fence();
  state.counters["particles"] = static_cast<double>(sim.particles().size());
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(static_cast<double>(sim.particles().size()) * state.iterations(), benchmark::Counter::kIsRate);
}

#ifdef KOKKOS_ENABLE_SERIAL
BENCHMARK_TEMPLATE(step_block, Kokkos::Serial)->Arg(50)->Arg(180)->Unit(benchmark::kMicrosecond)->UseRealTime();
#endif
#ifdef KOKKOS_ENABLE_OPENMP
BENCHMARK_TEMPLATE(step_block, Kokkos::OpenMP)->Arg(50)->Arg(180)->Unit(benchmark::kMicrosecond)->UseRealTime();
#endif
#ifdef KOKKOS_ENABLE_CUDA
BENCHMARK_TEMPLATE(step_block, Kokkos::Cuda)->Arg(180)->Arg(1000)->Unit(benchmark::kMicrosecond)->UseRealTime();
#endif

}  // namespace

int main(int argc, char** argv) {
  vrut::KokkosSession kokkos;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
