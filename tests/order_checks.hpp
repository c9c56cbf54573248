#pragma once
// A second-order scheme's errors at a step and at half of it: the half step
// quarters the error (3.5 to 4.5 allows for the next order), and the finer
// error lies within `bound`.
#include <catch2/catch.hpp>

namespace vrut_test {

inline void check_second_order(double coarse, double fine, double bound) {
  INFO("error at the step " << coarse << ", at half of it " << fine << ", ratio " << coarse / fine);
  CHECK(fine < bound);
  CHECK(coarse / fine > 3.5);
  CHECK(coarse / fine < 4.5);
}

}  // namespace vrut_test
