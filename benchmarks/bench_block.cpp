// vrut-bench-block: a block of particles settling under gravity in a box
// (linear contacts with Coulomb friction, no damping), the job
// benchmarks/lammps_side_by_side.sh runs in both vrut and LAMMPS. In 2D a
// hex-packed block of disks in a box of three walls; with --dim 3 a simple
// cubic block of touching spheres in a box of five plates (a floor and four
// sides). Prints the set-up and the throughput in particle-steps per second,
// and can write the same block as a LAMMPS data file.
#include <vrut/backend.hpp>
#include <vrut/vrut.hpp>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace {

struct Block {
  int columns = 180, rows = 90, layers = 1, dim = 2;
  double radius = 0.5e-3, density = 2700.0, thickness = 0.05, kn = 1e7, friction = 0.5;
};

// Runs the settling block for `steps` after one step that builds the
// contact list; prints the throughput.
template <class Sim>
int time_steps(Sim& sim, std::size_t particles, long steps, double dt, int threads) {
  sim.run(1, dt);  // the first contact list
  Kokkos::fence();
  const auto begin = std::chrono::steady_clock::now();
  sim.run(steps, dt);
  Kokkos::fence();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::printf("threads %d\nsteps %ld\nseconds %.6g\nparticle_steps_per_second %.6g\n", threads, steps, seconds,
              particles * static_cast<double>(steps) / seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Block b;
  int threads = 0;
  long steps = 2000;
  std::string backend = "openmp", lammps_data;
  CLI::App app("vrut-bench-block: throughput of a settling block (the LAMMPS side-by-side job)");
  app.add_option("--dim", b.dim, "2: disks, 3: spheres")->check(CLI::IsMember({2, 3}))->capture_default_str();
  app.add_option("--columns", b.columns)->check(CLI::Range(2, 100000))->capture_default_str();
  app.add_option("--rows", b.rows)->check(CLI::Range(2, 100000))->capture_default_str();
  app.add_option("--layers", b.layers, "3D: layers along z")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--steps", steps)->check(CLI::Range(1L, 100000000L))->capture_default_str();
  app.add_option("--backend", backend)->check(CLI::IsMember(vrut::available_backends()))->capture_default_str();
  app.add_option("--threads", threads)->capture_default_str();
  app.add_option("--write-lammps", lammps_data, "write the block as a LAMMPS data file (atom_style sphere) and stop");
  CLI11_PARSE(app, argc, argv);

  const double r = b.radius;
  vrut::ParticleSet set;
  double width, depth, height, mass;
  if (b.dim == 2) {
    set = vrut::hex_packing(b.columns, b.rows, r, b.density);
    width = 2.0 * r * b.columns + r, depth = 1.0, height = 4.0 * r * b.rows;
    mass = b.density * M_PI * r * r * b.thickness;
  } else {
    for (int k = 0; k < b.layers; ++k)
      for (int j = 0; j < b.rows; ++j)
        for (int i = 0; i < b.columns; ++i)
          set.add_sphere(r * (1 + 2 * i), r * (1 + 2 * j), r * (1 + 2 * k), r, b.density);
    width = 2.0 * r * b.columns, depth = 2.0 * r * b.rows, height = 4.0 * r * b.layers;
    mass = b.density * 4.0 / 3.0 * M_PI * r * r * r;
  }
  const double ks = b.kn * 2.0 / 7.0;
  const double dt = 0.2 * std::sqrt(mass / b.kn);
  std::printf("particles %zu\nwidth %.10g\ndepth %.10g\nheight %.10g\nmass %.10g\nkn %.10g\nks %.10g\nfriction "
              "%.10g\ndt %.10g\n",
              set.size(), width, depth, height, mass, b.kn, ks, b.friction, dt);
  if (!lammps_data.empty()) {
    std::ofstream f(lammps_data);
    const double z_low = b.dim == 2 ? -0.5 : 0.0, z_high = b.dim == 2 ? 0.5 : height;
    const double y_high = b.dim == 2 ? height : depth;
    f << "vrut block (SI)\n\n" << set.size() << " atoms\n1 atom types\n\n0 " << width << " xlo xhi\n0 " << y_high
      << " ylo yhi\n" << z_low << ' ' << z_high << " zlo zhi\n\nAtoms # sphere\n\n";
    f.precision(17);
    for (std::size_t i = 0; i < set.size(); ++i)
      f << i + 1 << " 1 " << 2.0 * set.radius[i] << " 1.0 " << set.x[i] << ' ' << set.y[i] << ' '
        << (b.dim == 2 ? 0.0 : set.z[i]) << "\n";
    return f ? 0 : 1;
  }

  vrut::KokkosSession kokkos(threads);
  return vrut::dispatch_backend(backend, [&](auto space) {
    using Space = decltype(space);
    vrut::AssignmentTable<vrut::Linear> table;
    table.set_all(vrut::linear_params(b.kn, ks, b.friction));
    const auto wall = vrut::linear_params(b.kn, ks, b.friction);
    if (b.dim == 2) {
      vrut::SimulationSettings settings;
      settings.thickness = b.thickness;
      settings.gravity = {0.0, -9.81};
      vrut::Simulation<vrut::Linear, Space> sim(set, table, settings, {0.0}, space);
      sim.add_wall(vrut::Wall{{0.0, 0.0}, {width, 0.0}, {}}, wall);
      sim.add_wall(vrut::Wall{{0.0, height}, {0.0, 0.0}, {}}, wall);
      sim.add_wall(vrut::Wall{{width, 0.0}, {width, height}, {}}, wall);
      return time_steps(sim, set.size(), steps, dt, vrut::concurrency(space));
    }
    vrut::SimulationSettings3 settings;
    settings.gravity = {0.0, 0.0, -9.81};
    vrut::Simulation3<vrut::Linear, Space> sim(set, table, settings, {0.0}, space);
    using vrut::Wall3;
    const double w = width, d = depth, h = height;
    sim.add_wall(Wall3{{0.5 * w, 0.5 * d, 0.0}, {w, 0.0, 0.0}, {0.0, d, 0.0}, {}}, wall);  // floor, normal +z
    sim.add_wall(Wall3{{0.0, 0.5 * d, 0.5 * h}, {0.0, d, 0.0}, {0.0, 0.0, h}, {}}, wall);  // x = 0, normal +x
    sim.add_wall(Wall3{{w, 0.5 * d, 0.5 * h}, {0.0, 0.0, h}, {0.0, d, 0.0}, {}}, wall);    // x = w, normal -x
    sim.add_wall(Wall3{{0.5 * w, 0.0, 0.5 * h}, {0.0, 0.0, h}, {w, 0.0, 0.0}, {}}, wall);  // y = 0, normal +y
    sim.add_wall(Wall3{{0.5 * w, d, 0.5 * h}, {w, 0.0, 0.0}, {0.0, 0.0, h}, {}}, wall);    // y = d, normal -y
    return time_steps(sim, set.size(), steps, dt, vrut::concurrency(space));
  });
}
