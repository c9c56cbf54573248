#pragma once
// A mix's gradation below 2.36 mm, where the source stops. The fines' own
// sieves are used where a table gives them; below a table's smallest sieve
// the gradation follows the 0.45-power maximum-density line through that
// sieve's point, P(d) = P(smallest) (d / smallest)^0.45 (the FHWA 0.45-power
// chart): an assumption, since the source gives no fine gradation.
// Host-only; mm, percent passing by mass.
#include <vrut/specimen/gradation.hpp>

#include <cmath>
#include <stdexcept>

namespace vrut {

inline double fine_passing_percent(const Gradation& g, double d_mm) {
  const double smallest = g.sieve_mm.back(), at_smallest = g.passing.back();
  if (smallest > 2.36)
    throw std::invalid_argument("the fines need the gradation " + g.name + " down to 2.36 mm at least");
  return d_mm >= smallest ? g.passing_at(d_mm) : at_smallest * std::pow(d_mm / smallest, 0.45);
}

}  // namespace vrut
