// Time to generate a digital specimen (gradation 2#, 300 x 50 mm section):
// the budget is 2 s at the default 0.5 mm disk radius and 15 s at
// 0.125 mm on a 2-core machine.
//
//   ./build/benchmarks/vrut-bench-specimen
#include <vrut/specimen/specimen.hpp>

#include <benchmark/benchmark.h>

namespace {

void generate(benchmark::State& state) {
  vrut::SpecimenSettings s;
  s.gradation = vrut::builtin_gradation(static_cast<int>(state.range(0)));
  s.disk_radius = state.range(1) / 1000.0;
  std::size_t disks = 0;
  for (auto _ : state) {
    const vrut::Specimen sp = vrut::generate_specimen(s);
    disks = sp.disks.centers.size();
    ++s.seed;
  }
  state.counters["disks"] = static_cast<double>(disks);
}

BENCHMARK(generate)->ArgsProduct({{1, 2, 3}, {500, 125}})->ArgNames({"gradation", "radius_um"})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
