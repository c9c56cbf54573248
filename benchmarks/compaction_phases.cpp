// A 3D specimen's stones, made as vrut-rutting --dim 3 makes them (random
// addition, then the compaction where it jams: 3#), timed by phase: the
// placement (random addition, and the loose placement a compaction starts
// from), the compaction's steps, and the whole. Prints a stone's centroid to
// the last bit, so that two builds can be shown to make the same specimen
// (docs/specimen.md, "Compaction"; docs/performance.md).
//
//   ./build/benchmarks/vrut-compaction-phases --gradation 3 --threads 2
#include <vrut/specimen/gradation.hpp>
#include <vrut/specimen/specimen3.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>

int main(int argc, char** argv) {
  CLI::App app{"vrut-compaction-phases: the time of a 3D specimen's stones, by phase"};
  int mix = 3, threads = 1;
  std::uint64_t seed = 1;
  double width = 300.0;
  app.add_option("--gradation", mix, "built-in mix")->check(CLI::Range(1, 3));
  app.add_option("--width-mm", width, "the box's width (50 mm high, 40 mm deep at 1 mm spheres)")
      ->check(CLI::Range(40.0, 10000.0));
  app.add_option("--threads", threads, "the compaction's threads")->check(CLI::Range(1, 1024));
  app.add_option("--seed", seed, "random seed");
  CLI11_PARSE(app, argc, argv);

  vrut::SpecimenSettings3 s;
  s.gradation = vrut::builtin_gradation(mix);
  s.placement.width = width;
  s.placement.height = 50.0;
  s.placement.depth = 40.0;
  s.seed = seed;
  s.compaction.threads = threads;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  double compaction_began = -1.0, compaction_ended = -1.0;
  const vrut::Specimen3 out = vrut::generate_specimen3(s, {}, [&](long, long) {
    if (compaction_began < 0.0) compaction_began = seconds();
    compaction_ended = seconds();
  });
  const double all = seconds();
  const vrut::Placement3& p = out.placement;
  std::printf("%d# %g mm wide, seed %llu, %d thread(s): %zu stones, %ld compaction steps\n", mix, width,
              static_cast<unsigned long long>(seed), threads, p.stones.size(), p.compaction_steps);
  if (p.compaction_steps > 0)
    std::printf("placement %.1f s, compaction %.1f s (%.0f steps/s), all %.1f s\n", compaction_began,
                compaction_ended - compaction_began, p.compaction_steps / (compaction_ended - compaction_began), all);
  else
    std::printf("placement %.1f s (no compaction), all %.1f s\n", all, all);
  const vrut::Point3& c = p.stones.front().shape.centroid;
  std::printf("first stone at (%.17g, %.17g, %.17g)\n", c.x(), c.y(), c.z());
}
