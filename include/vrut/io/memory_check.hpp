#pragma once
// Work that cannot fit in memory is refused before it starts, with the
// estimate, as a full disk is (OutputDir::require_space). Host-only.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace vrut {

// The memory this machine can still give, in bytes (Linux: MemAvailable of
// /proc/meminfo); 0 where it is not known.
inline double available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  double kib = 0.0;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024.0;
  return 0.0;
}

// The disks a section of width x height (mm) holds on the hexagonal packing
// of radius r (mm): one per 2 sqrt(3) r^2 of area.
inline double hex_disks_in(double width_mm, double height_mm, double radius_mm) {
  return width_mm * height_mm / (2.0 * std::sqrt(3.0) * radius_mm * radius_mm);
}

// Throws std::invalid_argument (bad input: the sizes asked for) when `disks`
// of `bytes_per_disk` each, beside a fixed `base_bytes`, need more memory
// than is available. `what` says what would have been run.
inline void require_memory(double disks, double bytes_per_disk, double base_bytes, const std::string& what,
                           double available = available_memory_bytes()) {
  const double need = base_bytes + disks * bytes_per_disk;
  if (!(available > 0.0) || need <= available) return;
  std::ostringstream text;
  text.precision(3);
  text << what << " needs about " << need / (1u << 30) << " GiB of memory (" << disks << " disks at about "
       << bytes_per_disk / 1024.0 << " kB each), and this machine has " << available / (1u << 30)
       << " GiB available: use larger disks, a smaller section or fewer seeds";
  throw std::invalid_argument(text.str());
}

}  // namespace vrut
