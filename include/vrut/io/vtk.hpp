#pragma once
// Legacy-format VTK files of disks or spheres (POLYDATA vertices with point
// data), which ParaView opens directly (Glyph by "radius" to see them). Every double is
// written with 17 significant digits, so it reads back as it was. Host-only.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

struct VtkPointData {
  std::vector<std::pair<std::string, std::vector<double>>> scalars;
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> vectors;  // in-plane
};

// Spheres in 3D (z given) or disks in the plane z = 0 (z empty).
inline void write_vtk_points(const std::string& path, const std::string& title, const std::vector<double>& x,
                             const std::vector<double>& y, const std::vector<double>& z, const VtkPointData& data) {
  const std::size_t n = x.size();
  if (y.size() != n || !(z.empty() || z.size() == n)) throw std::invalid_argument("vtk points: coordinates of unequal lengths");
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET POLYDATA\nPOINTS %zu double\n", title.c_str(), n);
  for (std::size_t i = 0; i < n; ++i) std::fprintf(f, "%.17g %.17g %.17g\n", x[i], y[i], z.empty() ? 0.0 : z[i]);
  std::fprintf(f, "VERTICES %zu %zu\n", n, 2 * n);
  for (std::size_t i = 0; i < n; ++i) std::fprintf(f, "1 %zu\n", i);
  std::fprintf(f, "POINT_DATA %zu\n", n);
  for (const auto& [name, values] : data.scalars) {
    if (values.size() != n) throw std::invalid_argument("vtk scalar " + name + " has the wrong length");
    std::fprintf(f, "SCALARS %s double 1\nLOOKUP_TABLE default\n", name.c_str());
    for (double v : values) std::fprintf(f, "%.17g\n", v);
  }
  for (const auto& [name, values] : data.vectors) {
    if (values.size() != n) throw std::invalid_argument("vtk vector " + name + " has the wrong length");
    std::fprintf(f, "VECTORS %s double\n", name.c_str());
    for (const auto& v : values) std::fprintf(f, "%.17g %.17g 0\n", v.first, v.second);
  }
  const bool failed = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || failed) throw std::runtime_error("error writing " + path + " (disk full?)");
}

inline void write_vtk_disks(const std::string& path, const std::string& title, const std::vector<double>& x,
                            const std::vector<double>& y, const VtkPointData& data) {
  write_vtk_points(path, title, x, y, {}, data);
}

}  // namespace vrut
