#pragma once
// What a rutting run records of its skeleton (protocol/rutting/skeleton.hpp measures
// it): the load path across a cut under the plate by class of contact, and
// the stones' film census, when the loading starts, early and at the end.
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace vrut {

// The vertical force (N, up on the part above) that crosses the cut, by class.
struct LoadPath {
  double minutes = std::numeric_limits<double>::quiet_NaN();  // of the test, when measured
  double stone_spring = 0.0, stone_film = 0.0, mastic = 0.0;
  double total() const { return stone_spring + stone_film + mastic; }
  double share(double part) const { return total() != 0.0 ? part / total() : std::numeric_limits<double>::quiet_NaN(); }
  bool measured() const { return !std::isnan(minutes); }
};

// The films between stones are sized in steps of 0.2 diameters (bins of
// film_reach_classes); a contact's film goes in the bin nearest its
// thickness, 0 to 1 diameter.
inline constexpr int film_census_bins = 6;                 // film_reach_classes + 1 (skeleton.hpp checks)
inline constexpr double film_census_step = 0.2;  // diameters

// The contacts between two stones' particles (overlapping), by the film
// between them, and how many of each bear on the stones' spring.
struct FilmCensus {
  std::array<int, film_census_bins> contacts{}, bearing{};
  static double thickness(int bin) { return bin * film_census_step; }  // diameters
  int total_contacts() const {
    int n = 0;
    for (int c : contacts) n += c;
    return n;
  }
  int total_bearing() const {
    int n = 0;
    for (int c : bearing) n += c;
    return n;
  }
};

// What a run records of its skeleton: the films when the loading starts and
// at its end, the load path at `early_minute` and at the end.
struct SkeletonRecord {
  static constexpr double early_minute = 5.0;
  FilmCensus films_start, films_end;
  LoadPath load_early, load_end;

  template <class Archive>
  void visit(Archive& archive, const std::string& id) {
    archive.value(id + "films_start", films_start);
    archive.value(id + "load_early", load_early);
  }
};

}  // namespace vrut
