#pragma once
// The mass properties of a 3D rigid body made of spheres (a clump, as a
// stone of the 3D specimen is made of the lattice spheres whose centres lie
// inside it), in the form the rotation step wants (integrate/
// rigid_rotation.hpp): the mass, the centre of mass, the principal moments,
// the orientation that takes the principal frame to the world, and each
// member's centre in that frame. Host-only (Eigen).
//
// The members' masses add, so they must not overlap (a lattice's spheres
// touch at most); each contributes its own 2/5 m r^2 and, by the parallel
// axis theorem, m (|d|^2 1 - d d^T) for its offset d from the centre.
#include <vrut/data/quaternion.hpp>
#include <vrut/data/vec3.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace vrut {

struct ClumpProperties3 {
  double mass = 0.0;
  Vec3 centre;                  // of mass, world frame
  Vec3 principal_moments;       // ascending, about the centre
  Quaternion orientation;       // principal frame to world
  std::vector<Vec3> offsets;    // each member's centre from `centre`, in the principal frame
};

// The inertia tensor about `about` of spheres of the given centres, radii
// and masses (world frame).
inline Eigen::Matrix3d sphere_inertia_tensor_of_masses(const std::vector<Vec3>& centres,
                                                       const std::vector<double>& radii,
                                                       const std::vector<double>& masses, Vec3 about) {
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const double r = radii[i], m = masses[i];
    const Vec3 d = centres[i] - about;
    const Eigen::Vector3d e(d.x, d.y, d.z);
    tensor += (0.4 * m * r * r + m * e.squaredNorm()) * Eigen::Matrix3d::Identity() - m * e * e.transpose();
  }
  return tensor;
}

// Each sphere's mass at the given density.
inline std::vector<double> sphere_masses(const std::vector<double>& radii, double density) {
  std::vector<double> masses;
  for (double r : radii) masses.push_back(density * 4.0 / 3.0 * M_PI * r * r * r);
  return masses;
}

// The same with one density for all.
inline Eigen::Matrix3d sphere_inertia_tensor(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                                             double density, Vec3 about) {
  return sphere_inertia_tensor_of_masses(centres, radii, sphere_masses(radii, density), about);
}

// A clump of spheres of the given masses (a simulation's own, which may
// differ between members).
inline ClumpProperties3 clump_properties_of_masses(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                                                   const std::vector<double>& masses) {
  if (centres.empty() || centres.size() != radii.size() || masses.size() != radii.size())
    throw std::invalid_argument("a clump needs one radius and one mass per member, and at least one member");
  ClumpProperties3 c;
  Vec3 moment{};
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!(radii[i] > 0.0)) throw std::invalid_argument("a clump member's radius must be positive");
    if (!(masses[i] > 0.0)) throw std::invalid_argument("a clump member's mass must be positive");
    c.mass += masses[i];
    moment += masses[i] * centres[i];
  }
  c.centre = (1.0 / c.mass) * moment;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
      sphere_inertia_tensor_of_masses(centres, radii, masses, c.centre));
  Eigen::Matrix3d axes = solver.eigenvectors();  // columns: the principal axes, moments ascending
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);  // a rotation, not a reflection
  const Eigen::Vector3d moments = solver.eigenvalues();
  c.principal_moments = {moments(0), moments(1), moments(2)};
  const Eigen::Quaterniond q(axes);
  c.orientation = normalized(Quaternion{q.w(), q.x(), q.y(), q.z()});
  for (const Vec3& x : centres) c.offsets.push_back(rotate_back(c.orientation, x - c.centre));
  return c;
}

inline ClumpProperties3 clump_properties(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                                         double density) {
  if (!(density > 0.0)) throw std::invalid_argument("a clump's density must be positive");
  return clump_properties_of_masses(centres, radii, sphere_masses(radii, density));
}

}  // namespace vrut
