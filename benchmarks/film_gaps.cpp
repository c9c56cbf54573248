// The mastic that 1 mm disks cannot show (docs/studies/2026-11-23-gradation-sensitivity.md, the film
// between stones). A disk belongs to a stone when its centre lies inside the
// stone's outline, so where two disks are neighbours the true outlines lie
// somewhere on the segment between their centres. Along that segment this
// measures, for the three built-in mixes:
//   - between disks of two stones: the gap between the two outlines, the
//     mastic film the stones meet through (RuttingMaterials::film_gap);
//   - between a mastic disk and a stone disk: the mastic's length from the
//     mastic disk's centre to the outline (the mastic-aggregate factor is one
//     diameter over it).
// Both as fractions of the disk diameter, over the seeds asked for.
//   vrut-film-gaps [seeds, default 3] [disk radius in mm, default 1 as vrut-rutting]
#include <vrut/specimen/specimen.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

struct Tally {
  double sum = 0.0, squares = 0.0;
  long count = 0;
  void add(double v) { sum += v, squares += v * v, ++count; }
  double mean() const { return sum / count; }
  double sd() const { return std::sqrt(squares / count - mean() * mean()); }
};

// The fraction of the segment a-b outside every given outline, sampled at
// 1,000 midpoints (a resolution of 2 micrometres for 2 mm disks).
double outside_fraction(const vrut::Point& a, const vrut::Point& b, const vrut::Polygon& p, const vrut::Polygon& q) {
  const int samples = 1000;
  int outside = 0;
  for (int k = 0; k < samples; ++k) {
    const vrut::Point x = a + (b - a) * ((k + 0.5) / samples);
    outside += !vrut::point_in_polygon(p, x) && !vrut::point_in_polygon(q, x);
  }
  return static_cast<double>(outside) / samples;
}

}  // namespace

int main(int argc, char** argv) {
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 3;
  const double radius = argc > 2 ? std::atof(argv[2]) : 1.0;
  if (seeds < 1 || !(radius > 0.0)) {
    std::fprintf(stderr, "usage: vrut-film-gaps [seeds >= 1] [disk radius mm > 0]\n");
    return 2;
  }
  std::printf("mix | stone-stone neighbours | film gap (mean, sd) | mastic-stone neighbours | mastic length (mean, sd)\n");
  for (int mix = 1; mix <= 3; ++mix) {
    Tally film, mastic;
    for (int seed = 1; seed <= seeds; ++seed) {
      vrut::SpecimenSettings settings;
      settings.gradation = vrut::builtin_gradation(mix);
      settings.seed = static_cast<std::uint64_t>(seed);
      settings.disk_radius = radius;
      const vrut::Specimen sp = vrut::generate_specimen(settings);
      const auto& centre = sp.disks.centers;
      const auto& owner = sp.disks.aggregate;
      const double d = 2.0 * sp.disks.radius;
      // Neighbours on the hexagonal lattice lie one diameter apart.
      for (std::size_t i = 0; i < centre.size(); ++i)
        for (std::size_t j = i + 1; j < centre.size(); ++j) {
          if (std::abs(centre[j].y() - centre[i].y()) > 1.01 * d) {
            if (centre[j].y() > centre[i].y()) break;  // rows go up with the index
            continue;
          }
          if ((centre[i] - centre[j]).norm() > 1.001 * d) continue;
          const int a = owner[i], b = owner[j];
          if (a < 0 && b < 0) continue;
          if (a >= 0 && b >= 0) {
            if (a != b)
              film.add(outside_fraction(centre[i], centre[j], sp.placement.aggregates[a].polygon,
                                        sp.placement.aggregates[b].polygon));
          } else {
            const vrut::Polygon& stone = sp.placement.aggregates[a >= 0 ? a : b].polygon;
            mastic.add(outside_fraction(centre[i], centre[j], stone, stone));
          }
        }
    }
    std::printf("%d# | %ld | %.3f, %.3f | %ld | %.3f, %.3f\n", mix, film.count, film.mean(), film.sd(), mastic.count,
                mastic.mean(), mastic.sd());
  }
}
