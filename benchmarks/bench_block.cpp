// vrut-bench-block: a hex-packed block of disks settling under gravity in a
// box of three walls (linear contacts with Coulomb friction, no damping), the
// job benchmarks/lammps_side_by_side.sh runs in both vrut and LAMMPS. Prints
// the set-up and the throughput in particle-steps per second, and can write
// the same block as a LAMMPS data file.
#include <vrut/backend.hpp>
#include <vrut/vrut.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  int columns = 180, rows = 90, threads = 0;
  long steps = 2000;
  double radius = 0.5e-3, density = 2700.0, thickness = 0.05, kn = 1e7, friction = 0.5;
  std::string backend = "openmp", lammps_data;
  CLI::App app("vrut-bench-block: throughput of a settling hex block (the LAMMPS side-by-side job)");
  app.add_option("--columns", columns)->check(CLI::Range(2, 100000))->capture_default_str();
  app.add_option("--rows", rows)->check(CLI::Range(2, 100000))->capture_default_str();
  app.add_option("--steps", steps)->check(CLI::Range(1L, 100000000L))->capture_default_str();
  app.add_option("--backend", backend)->check(CLI::IsMember(vrut::available_backends()))->capture_default_str();
  app.add_option("--threads", threads)->capture_default_str();
  app.add_option("--write-lammps", lammps_data, "write the block as a LAMMPS data file (atom_style sphere) and stop");
  CLI11_PARSE(app, argc, argv);

  const vrut::ParticleSet set = vrut::hex_packing(columns, rows, radius, density);
  const double width = 2.0 * radius * columns + radius, height = 4.0 * radius * rows;
  const double mass = density * M_PI * radius * radius * thickness, ks = kn * 2.0 / 7.0;
  const double dt = 0.2 * std::sqrt(mass / kn);
  std::printf("particles %zu\nwidth %.10g\nheight %.10g\nmass %.10g\nkn %.10g\nks %.10g\nfriction %.10g\ndt %.10g\n",
              set.size(), width, height, mass, kn, ks, friction, dt);
  if (!lammps_data.empty()) {
    std::ofstream f(lammps_data);
    f << "vrut hex block (SI)\n\n" << set.size() << " atoms\n1 atom types\n\n0 " << width << " xlo xhi\n0 " << height
      << " ylo yhi\n-0.5 0.5 zlo zhi\n\nAtoms # sphere\n\n";
    f.precision(17);
    for (std::size_t i = 0; i < set.size(); ++i)
      f << i + 1 << " 1 " << 2.0 * set.radius[i] << " 1.0 " << set.x[i] << ' ' << set.y[i] << " 0\n";
    return f ? 0 : 1;
  }

  vrut::KokkosSession kokkos(threads);
  return vrut::dispatch_backend(backend, [&](auto space) {
    using Space = decltype(space);
    vrut::AssignmentTable<vrut::Linear> table;
    table.set_all(vrut::linear_params(kn, ks, friction));
    vrut::SimulationSettings settings;
    settings.thickness = thickness;
    settings.gravity = {0.0, -9.81};
    vrut::Simulation<vrut::Linear, Space> sim(set, table, settings, {0.0}, space);
    const auto wall = vrut::linear_params(kn, ks, friction);
    sim.add_wall(vrut::Wall{{0.0, 0.0}, {width, 0.0}, {}}, wall);
    sim.add_wall(vrut::Wall{{0.0, height}, {0.0, 0.0}, {}}, wall);
    sim.add_wall(vrut::Wall{{width, 0.0}, {width, height}, {}}, wall);
    sim.run(1, dt);  // the first contact list
    Kokkos::fence();
    const auto begin = std::chrono::steady_clock::now();
    sim.run(steps, dt);
    Kokkos::fence();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    std::printf("threads %d\nsteps %ld\nseconds %.6g\nparticle_steps_per_second %.6g\n", vrut::concurrency(space), steps,
                seconds, set.size() * static_cast<double>(steps) / seconds);
    return 0;
  });
}
