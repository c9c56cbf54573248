#pragma once
// The homogeneity test of a placement, in 2D and 3D alike: the stones'
// fraction in five equal bands (across the height, or along the width) over
// several specimens, fraction[band][specimen]. Each interior band (those not
// touching the mould) must equal the interior's mean within four standard
// errors of the band's mean; the outer bands, lower, are the wall effect,
// printed with the label ("mix 2#, height").
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace vrut_test {

inline void check_interior_bands(const std::vector<std::vector<double>>& fraction, const std::string& label) {
  const int bands = static_cast<int>(fraction.size());
  REQUIRE(bands == 5);
  const int specimens = static_cast<int>(fraction[0].size());
  std::vector<double> mean(bands), se(bands);
  for (int b = 0; b < bands; ++b) {
    double m = 0.0, q = 0.0;
    for (double v : fraction[b]) m += v / specimens;
    for (double v : fraction[b]) q += (v - m) * (v - m);
    mean[b] = m;
    se[b] = std::sqrt(q / (specimens - 1) / specimens);
  }
  const double interior = (mean[1] + mean[2] + mean[3]) / 3.0;
  std::printf("%s bands: %.3f (mould) / %.3f / %.3f / %.3f / %.3f (mould); wall effect %.2f of the interior\n",
              label.c_str(), mean[0], mean[1], mean[2], mean[3], mean[4], 0.5 * (mean[0] + mean[4]) / interior);
  for (int b = 1; b < bands - 1; ++b) {
    INFO(label << " band " << b << ": " << mean[b] << " +- " << se[b] << " against the interior's " << interior);
    CHECK(std::abs(mean[b] - interior) <= 4.0 * se[b] + 1e-9);
  }
}

}  // namespace vrut_test
