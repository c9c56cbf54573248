#pragma once
/// \file
/// Host-side description of disks (2D) or spheres (3D), the input from which
/// a Simulation is built.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

struct ParticleSet {
  std::vector<double> x, y, radius, density;
  std::vector<double> z;  // 3D only: empty for disks, one per sphere
  std::vector<int> group;
  /// Which specimen of an ensemble each disk belongs to (0 for a single run).
  /// Disks of different specimens never touch, whatever their positions, and
  /// each specimen's disks are contiguous and in increasing specimen order.
  std::vector<int> specimen;
  /// The rigid body (clump) each disk is a member of, -1 for a free disk.
  /// Members move as one (data/bodies.hpp) and never touch each other; a
  /// body's members lie in one specimen. Bodies are numbered from 0.
  std::vector<int> body;

  std::size_t size() const { return x.size(); }
  int specimens() const { return specimen.empty() ? 0 : specimen.back() + 1; }
  int bodies() const {
    int n = 0;
    for (int b : body) n = b + 1 > n ? b + 1 : n;
    return n;
  }

  void add(double px, double py, double r, double rho, int g = 0, int member_of = -1) {
    if (!(r > 0.0)) throw std::invalid_argument("vrut: a disk radius must be positive");
    if (!(rho > 0.0)) throw std::invalid_argument("vrut: a disk density must be positive");
    if (g < 0) throw std::invalid_argument("vrut: a material group must be >= 0");
    if (member_of < -1) throw std::invalid_argument("vrut: a body index must be >= 0 (-1: no body)");
    x.push_back(px);
    y.push_back(py);
    radius.push_back(r);
    density.push_back(rho);
    group.push_back(g);
    specimen.push_back(specimens() > 0 ? specimen.back() : 0);
    body.push_back(member_of);
  }

  /// A sphere, for a 3D simulation: as add, with the third coordinate.
  void add_sphere(double px, double py, double pz, double r, double rho, int g = 0, int member_of = -1) {
    if (z.size() != x.size()) throw std::invalid_argument("vrut: a set of disks cannot take a sphere");
    add(px, py, r, rho, g, member_of);
    z.push_back(pz);
  }

  /// Appends every disk of `other` as a new specimen, its bodies numbered
  /// after the ones already here; returns its index.
  int append_specimen(const ParticleSet& other) {
    const int s = size() == 0 ? 0 : specimens();
    const int first_body = bodies();
    const bool spheres = !z.empty() || (size() == 0 && !other.z.empty());
    if (spheres ? (z.size() != size() || other.z.size() != other.size()) : !other.z.empty())
      throw std::invalid_argument("vrut: an ensemble's specimens must all be disks or all spheres");
    x.insert(x.end(), other.x.begin(), other.x.end());
    y.insert(y.end(), other.y.begin(), other.y.end());
    z.insert(z.end(), other.z.begin(), other.z.end());
    radius.insert(radius.end(), other.radius.begin(), other.radius.end());
    density.insert(density.end(), other.density.begin(), other.density.end());
    group.insert(group.end(), other.group.begin(), other.group.end());
    specimen.insert(specimen.end(), other.size(), s);
    for (std::size_t i = 0; i < other.size(); ++i)
      body.push_back(i < other.body.size() && other.body[i] >= 0 ? other.body[i] + first_body : -1);
    return s;
  }
};

/// Disks on a hexagonal close packing: rows along x, each row shifted by
/// half a diameter, rows 2r*sqrt(3)/2 apart. Every inner disk touches six.
inline ParticleSet hex_packing(int columns, int rows, double radius, double density,
                               double x0 = 0.0, double y0 = 0.0, int group = 0) {
  if (columns < 1 || rows < 1) throw std::invalid_argument("vrut: hex_packing needs at least one row and column");
  ParticleSet set;
  const double dy = radius * 1.7320508075688772;  // 2r * sqrt(3)/2
  for (int row = 0; row < rows; ++row) {
    const double shift = (row % 2) ? radius : 0.0;
    for (int col = 0; col < columns; ++col)
      set.add(x0 + radius + shift + 2.0 * radius * col, y0 + radius + dy * row, radius, density, group);
  }
  return set;
}

}  // namespace vrut
