// What a 3D specimen's sphere size changes in its stones
// (docs/studies/2026-12-07-fidelity-round-five.md): the same stones, placed
// once, filled with spheres of each radius asked for. A stone exists in the
// DEM only where it holds the centre of a lattice site; a stone that holds
// none is mastic. Per size class: the stones placed, those that hold a
// sphere, their share of the class's volume, and the spheres per stone that
// holds one; over all stone pairs whose spheres are lattice neighbours: how
// many, and their film (one diameter less the two reaches,
// specimen/stone_reach3.hpp) in mm.
//   vrut-stones-held3 MIX SEED WIDTH_MM DEPTH_MM RADIUS_MM...
//   e.g. vrut-stones-held3 2 1 100 42.4264 1.5 1 0.75 0.5
#include <vrut/specimen/specimen3.hpp>
#include <vrut/specimen/stone_reach3.hpp>

#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: %s MIX SEED WIDTH_MM DEPTH_MM RADIUS_MM...\n", argv[0]);
    return 2;
  }
  vrut::SpecimenSettings3 s;
  s.gradation = vrut::builtin_gradation(std::atoi(argv[1]));
  s.seed = std::strtoull(argv[2], nullptr, 10);
  s.placement.width = std::atof(argv[3]);
  s.placement.height = 50.0;
  s.placement.depth = std::atof(argv[4]);
  s.sphere_radius = std::atof(argv[5]);
  const vrut::Specimen3 first = vrut::generate_specimen3(s);
  const auto& stones = first.placement.stones;
  const auto& classes = first.stereology.classes;
  std::printf("| mix | sphere radius mm | spheres | class mm | stones placed | holding a sphere | their share of "
              "the class's volume | spheres per such stone |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  std::vector<std::string> films;
  for (int a = 5; a < argc; ++a) {
    s.sphere_radius = std::atof(argv[a]);
    const vrut::Specimen3 sp = a == 5 ? first : vrut::specimen3_on_stones(s, first.placement);
    std::vector<int> spheres_of(stones.size(), 0);
    for (const int stone : sp.spheres.stone)
      if (stone >= 0) ++spheres_of[stone];
    for (std::size_t c = 0; c < classes.size(); ++c) {
      int placed = 0, held = 0, spheres = 0;
      double volume = 0.0, held_volume = 0.0;
      for (std::size_t i = 0; i < stones.size(); ++i) {
        if (stones[i].size_class != static_cast<int>(c)) continue;
        ++placed, volume += stones[i].shape.volume;
        if (spheres_of[i] > 0) ++held, held_volume += stones[i].shape.volume, spheres += spheres_of[i];
      }
      std::printf("| %s# | %g | %zu | %g-%g | %d | %d | %.2f | %.1f |\n", argv[1], s.sphere_radius,
                  sp.spheres.centers.size(), classes[c].lower_mm, classes[c].upper_mm, placed, held,
                  volume > 0.0 ? held_volume / volume : 0.0, held > 0 ? double(spheres) / held : 0.0);
    }
    const std::vector<double> reach = vrut::stone_reach3(sp);
    double sum = 0.0;
    std::set<std::pair<int, int>> stone_pairs;
    for (const auto& [i, j] : sp.spheres.stone_pairs) {
      sum += std::max(0.0, 1.0 - reach[i] - reach[j]) * 2.0 * sp.spheres.radius;
      const int p = sp.spheres.stone[i], q = sp.spheres.stone[j];
      stone_pairs.insert({std::min(p, q), std::max(p, q)});
    }
    const std::size_t n = sp.spheres.stone_pairs.size();
    char line[240];
    std::snprintf(line, sizeof line, "| %s# | %g | %zu | %zu | %.3f | %.2f |", argv[1], s.sphere_radius, n,
                  stone_pairs.size(), n > 0 ? sum / n : 0.0, stone_pairs.empty() ? 0.0 : double(n) / stone_pairs.size());
    films.push_back(line);
  }
  std::printf("\n| mix | sphere radius mm | sphere pairs between stones | stone pairs they join | mean film mm | "
              "sphere pairs per stone pair |\n| --- | --- | --- | --- | --- | --- |\n");
  for (const auto& line : films) std::printf("%s\n", line.c_str());
}
