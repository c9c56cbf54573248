#pragma once
// The kinematics of a 3D contact, and the contact frame's bookkeeping: the
// conventions of geometry.hpp, with the shear a vector in the contact's
// tangent plane.
//   - The normal points from the first body to the second; a positive
//     normal force pushes them apart.
//   - The shear displacement and force are the second body's, relative to
//     the first, in the plane normal to the contact.
//   - A shear spring's stored force must turn with the contact: as the pair
//     rolls or spins, the force that was tangent yesterday has a normal part
//     today. ContactTurn carries it: the least rotation that takes the old
//     normal to the new one, then the pair's mean spin about the normal, as
//     YADE's ScGeom and PFC do; a last projection into the plane (keeping
//     the magnitude, as LAMMPS' gran/hooke/history does) takes out what
//     rounding leaves.
#include <vrut/contact/geometry.hpp>
#include <vrut/data/vec3.hpp>

#include <Kokkos_Core.hpp>

namespace vrut {

using ContactGeometry3 = ContactGeometryIn<Dim3>;

// The kinematics of a contact: `normal` and `overlap` as above, each body's
// branch vector (its centre to the contact point), velocity and angular
// velocity. The relative velocity of the second body's material point at
// the contact against the first's, over dt, split into normal and shear.
KOKKOS_INLINE_FUNCTION ContactGeometry3 contact_kinematics(Vec3 normal, double overlap, Vec3 branch_1, Vec3 v_1,
                                                           Vec3 w_1, Vec3 branch_2, Vec3 v_2, Vec3 w_2, double dt) {
  const Vec3 relative = (v_2 + cross(w_2, branch_2)) - (v_1 + cross(w_1, branch_1));
  const double along = dot(relative, normal);
  ContactGeometry3 g;
  g.normal = normal;
  g.overlap = overlap;
  g.normal_increment = -along * dt;  // approaching (along < 0) deepens the overlap
  g.shear_increment = dt * (relative - along * normal);
  g.dt = dt;
  return g;
}

// Two spheres: centres x, radii r. The contact point lies in the middle of
// the overlap.
KOKKOS_INLINE_FUNCTION ContactGeometry3 sphere_sphere(Vec3 x_1, Vec3 v_1, Vec3 w_1, double r_1, Vec3 x_2, Vec3 v_2,
                                                      Vec3 w_2, double r_2, double dt) {
  const Vec3 d = x_2 - x_1;
  const double distance = norm(d);
  const Vec3 n = (1.0 / distance) * d;
  const double overlap = r_1 + r_2 - distance;
  return contact_kinematics(n, overlap, (r_1 - 0.5 * overlap) * n, v_1, w_1, -(r_2 - 0.5 * overlap) * n, v_2, w_2,
                            dt);
}

// A sphere (second body) on a fixed plane through `point` with unit normal
// `plane_normal` towards the sphere's side (first body, at rest). The
// contact point lies on the plane.
KOKKOS_INLINE_FUNCTION ContactGeometry3 plane_sphere(Vec3 point, Vec3 plane_normal, Vec3 x, Vec3 v, Vec3 w, double r,
                                                     double dt) {
  const double height = dot(x - point, plane_normal);
  return contact_kinematics(plane_normal, r - height, Vec3{}, Vec3{}, Vec3{}, -height * plane_normal, v, w, dt);
}

// A contact frame's turn over one step, from the unit normal `old_normal`
// to `new_normal` with `twist` radians about the normal (dt times the
// pair's mean angular velocity along the mean of the two normals). Applied
// to a shear vector of the old frame (normal to old_normal):
//   - the least rotation taking old_normal to new_normal, exactly, as
//     v - (v . n') / (1 + n . n') (n + n') (for v normal to n; the
//     component along the rotation's axis stays, the rest turns with n);
//   - the twist to second order, v + twist n' x v: the step's direction
//     error is of order twist^3, and the length is restored below;
//   - a projection into the new tangent plane, taking out what rounding
//     leaves, and the vector's old length restored, as LAMMPS'
//     gran/hooke/history keeps it.
// No trigonometry, one division and one square root a vector: the turn is
// done for every contact at every step. What depends only on the normals
// is worked out once in the constructor, for all of a law's vectors.
struct ContactTurn {
  Vec3 new_normal, normal_sum;  // n', n + n'
  double inverse_one_plus_cosine = 0.0, twist = 0.0;
  KOKKOS_FORCEINLINE_FUNCTION ContactTurn(Vec3 old_normal, Vec3 normal, double turn_about_normal)
      : new_normal(normal), normal_sum(old_normal + normal), twist(turn_about_normal) {
    const double one_plus_cosine = 1.0 + dot(old_normal, normal);
    // Normals half a turn apart have no least rotation: a contact never turns so far in a step.
    inverse_one_plus_cosine = one_plus_cosine > 1e-12 ? 1.0 / one_plus_cosine : 0.0;
  }
  KOKKOS_FORCEINLINE_FUNCTION Vec3 operator()(Vec3 shear) const {
    const double length2 = dot(shear, shear);
    if (!(length2 > 0.0)) return Vec3{};
    Vec3 v = shear - (dot(shear, new_normal) * inverse_one_plus_cosine) * normal_sum;
    v += twist * cross(new_normal, v);
    v -= dot(v, new_normal) * new_normal;
    const double after2 = dot(v, v);
    return after2 > 0.0 ? sqrt(length2 / after2) * v : v;
  }
};

// A shear vector of the old contact frame carried into the new one (ContactTurn).
KOKKOS_INLINE_FUNCTION Vec3 turn_with_contact(Vec3 shear, Vec3 old_normal, Vec3 new_normal, double twist) {
  return ContactTurn(old_normal, new_normal, twist)(shear);
}

}  // namespace vrut
