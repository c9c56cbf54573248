#pragma once
/// \file
/// The laboratory wheel-tracking test itself (docs/method.md section 1): the
/// wheel, its pressure and travel, the duration and the window of the
/// dynamic stability, in SI units, and what follows from them.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace vrut {

/// The laboratory test (docs/method.md section 1); SI units.
struct WheelTracking {
  double wheel_mass = 78.0;          // kg
  double gravity = 9.81;             // m/s^2
  double pressure = 0.7e6;           // Pa
  double wheel_width = 0.05;         // m, = the disk thickness t
  double travel = 0.230;             // m, back and forth
  double passes_per_minute = 42.0;
  double minutes = 60.0;
  double ds_from_minute = 45.0;      // DS between this minute and the end
  /// The 2D section: along the wheel's travel (the method's: the plate is the
  /// tyre's contact length l) or across it (the plate is the wheel's width d,
  /// so the mix can flow out sideways from under the wheel). A point under
  /// the wheel is loaded for the same time either way. The disks keep the
  /// thickness t = d in both: every force, stiffness and mass of the section
  /// scales with t, so t does not enter the answer.
  bool transverse = false;
  /// The 3D plate: a strip across the box's periodic depth (the model's: an
  /// endless wheel, the mix under it held in plane strain), or the tyre's
  /// patch, l along the travel and d across it at mid-depth, so the mix can
  /// flow out sideways past the wheel's edges, as in the laboratory's 300 mm
  /// slab (an experiment of docs/validation.md, round four). The patch
  /// carries the wheel's own weight, p l d; the strip p l times the depth.
  bool patch = false;

  double contact_length() const { return wheel_mass * gravity / (pressure * wheel_width); }
  double loading_time() const { return minutes * 60.0 * contact_length() / travel; }  // s, cumulative under the wheel
  /// The passes of the DS window, (t2 - t1) N C1 C2 with C1 = C2 = 1.
  double ds_window_passes() const { return (minutes - ds_from_minute) * passes_per_minute; }
  double plate_force() const { return pressure * contact_length() * wheel_width; }
  /// The plate's length in the section: l along the travel, d across it.
  double plate_length() const { return transverse ? wheel_width : contact_length(); }

  void validate(double section_width_m) const {
    auto positive = [](double v, const char* what) {
      if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(what) + " must be positive");
    };
    positive(wheel_mass, "wheel mass");
    positive(gravity, "gravity");
    positive(pressure, "contact pressure");
    positive(wheel_width, "wheel width");
    positive(travel, "wheel travel");
    positive(passes_per_minute, "passes per minute");
    positive(minutes, "test duration");
    if (!(ds_from_minute > 0.0 && ds_from_minute < minutes))
    {
      char text[160];
      std::snprintf(text, sizeof text, "the test (%g min) must last longer than minute %g, where the window of the "
                    "dynamic stability starts", minutes, ds_from_minute);
      throw std::invalid_argument(text);
    }
    if (!(plate_length() < section_width_m))
      throw std::invalid_argument("the loading plate (" + std::to_string(plate_length() * 1e3) +
                                  " mm) is longer than the specimen (" + std::to_string(section_width_m * 1e3) + " mm)");
  }
};

}  // namespace vrut
