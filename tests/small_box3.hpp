#pragma once
// The small 3D box of the specimen and film tests: a built-in mix, 50 mm
// high and 40 mm deep (twice the 19 mm sieve), `width` mm wide.
#include <vrut/specimen/gradation.hpp>
#include <vrut/specimen/specimen3.hpp>

#include <cstdint>

namespace vrut_test {

inline vrut::SpecimenSettings3 small_box3(int mix, std::uint64_t seed, double width = 60.0) {
  vrut::SpecimenSettings3 s;
  s.gradation = vrut::builtin_gradation(mix);
  s.placement.width = width;
  s.placement.height = 50.0;
  s.placement.depth = 40.0;
  s.seed = seed;
  return s;
}

}  // namespace vrut_test
