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

#include <algorithm>
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

// The clump's mass as felt at a member's centre (its offset d in the
// principal frame) by a force through that centre, in the direction that
// moves the centre most: 1 / (1/M + max over unit n of (d x n)^T I^-1 (d x n)).
// d x n lies in the plane normal to d and is at most |d| long, so the
// maximum is |d|^2 times the larger eigenvalue of I^-1 on that plane, not
// |d|^2 / I_min: a thin clump is light about its long axis, but a force
// through a member on that axis cannot turn it about it. This sets the time
// step of contacts on rigid stones (core/simulation.hpp, contact_timestep).
inline double mass_felt_at_member(const ClumpProperties3& c, Vec3 offset) {
  const double dd = dot(offset, offset);
  if (!(dd > 0.0)) return c.mass;
  const Vec3 inverse{1.0 / c.principal_moments.x, 1.0 / c.principal_moments.y, 1.0 / c.principal_moments.z};
  // Two unit vectors spanning the plane normal to the offset (the first
  // normal to the offset's smallest component's axis as well), then I^-1
  // on them as a 2 x 2 matrix and its larger eigenvalue, in a form without
  // cancellation (a symmetric clump's two moments can be equal).
  const Vec3 e = (1.0 / std::sqrt(dd)) * offset;
  const Vec3 ax = std::abs(e.x) <= std::abs(e.y) && std::abs(e.x) <= std::abs(e.z) ? Vec3{1.0, 0.0, 0.0}
                  : std::abs(e.y) <= std::abs(e.z)                               ? Vec3{0.0, 1.0, 0.0}
                                                                                  : Vec3{0.0, 0.0, 1.0};
  Vec3 p = cross(e, ax);
  p = (1.0 / norm(p)) * p;
  const Vec3 q = cross(e, p);
  const double pp = dot(p, times_each(inverse, p)), qq = dot(q, times_each(inverse, q)),
               pq = dot(p, times_each(inverse, q));
  const double larger = 0.5 * (pp + qq) + std::hypot(0.5 * (pp - qq), pq);
  return 1.0 / (1.0 / c.mass + dd * larger);
}

inline ClumpProperties3 clump_properties(const std::vector<Vec3>& centres, const std::vector<double>& radii,
                                         double density) {
  if (!(density > 0.0)) throw std::invalid_argument("a clump's density must be positive");
  return clump_properties_of_masses(centres, radii, sphere_masses(radii, density));
}

}  // namespace vrut
