#pragma once
// The pairs of spheres closer than r_i + r_j + skin, in 3D, with a cell list
// (O(N)) and the 27-cell stencil, wrapping around the periodic axes of the
// box (neighbor/periodic_box3.hpp). Each pair is listed once, under its
// lower index, partners ascending: a fixed order on every backend.
//
// Along a periodic axis the box must hold at least 3 cells (a length of 3
// times the largest reach): with fewer, one neighbour cell would be visited
// twice through the two faces. Along the others the cells span the spheres'
// extent, those outside the box included.
#include <vrut/data/vec3.hpp>
#include <vrut/neighbor/periodic_box3.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vrut {

template <class Space>
struct PairList3 {
  using memory_space = typename Space::memory_space;
  Kokkos::View<int*, memory_space> start;    // i's partners: partner(start(i)) .. partner(start(i + 1) - 1)
  Kokkos::View<int*, memory_space> partner;  // all of them > i, ascending
};

// The 27 neighbour cells of a sphere's, wrapped along the periodic axes:
// calls visit(j) for every sphere j > i within reach. (A functor, not a
// generic lambda: nvcc refuses generic extended lambdas.)
template <class MemorySpace>
struct CellStencil3 {
  Kokkos::View<Vec3*, MemorySpace> x;
  Kokkos::View<double*, MemorySpace> r;
  Kokkos::View<int*, MemorySpace> cell_of, cell_start, members;
  PeriodicBox3 box;
  double skin;
  int nx, ny, nz;
  bool px, py, pz;

  template <class Visit>
  KOKKOS_INLINE_FUNCTION void operator()(const int i, Visit&& visit) const {
    const int c = cell_of(i), ix = c % nx, iy = (c / nx) % ny, iz = c / (nx * ny);
    for (int dz = -1; dz <= 1; ++dz) {
      int zz = iz + dz;
      if (pz) zz = (zz + nz) % nz;
      else if (zz < 0 || zz >= nz) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        int yy = iy + dy;
        if (py) yy = (yy + ny) % ny;
        else if (yy < 0 || yy >= ny) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          int xx = ix + dx;
          if (px) xx = (xx + nx) % nx;
          else if (xx < 0 || xx >= nx) continue;
          const int cc = (zz * ny + yy) * nx + xx;
          for (int m = cell_start(cc); m < cell_start(cc + 1); ++m) {
            const int j = members(m);
            if (j <= i) continue;
            const double reach = r(i) + r(j) + skin;
            const Vec3 d = box.separation(x(i), x(j));
            if (dot(d, d) < reach * reach) visit(j);
          }
        }
      }
    }
  }
};

// The half list of the spheres at x (radii r) within r_i + r_j + skin.
template <class Space>
PairList3<Space> find_pairs(const Space& space, const Kokkos::View<Vec3*, typename Space::memory_space>& x,
                            const Kokkos::View<double*, typename Space::memory_space>& r, const PeriodicBox3& box,
                            double skin) {
  using memory_space = typename Space::memory_space;
  using policy = Kokkos::RangePolicy<Space>;
  const int n = static_cast<int>(x.extent(0));
  // The extent of the spheres along each axis, and the largest radius.
  double lo[3], hi[3], rmax = 0.0;
  for (int k = 0; k < 3; ++k) {
    double a = 0.0, b = 0.0;
    Kokkos::parallel_reduce("vrut::bounds3_min", policy(space, 0, n),
        KOKKOS_LAMBDA(const int i, double& m) { if (component(x(i), k) < m) m = component(x(i), k); }, Kokkos::Min<double>(a));
    Kokkos::parallel_reduce("vrut::bounds3_max", policy(space, 0, n),
        KOKKOS_LAMBDA(const int i, double& m) { if (component(x(i), k) > m) m = component(x(i), k); }, Kokkos::Max<double>(b));
    lo[k] = box.periodic[k] ? component(box.low, k) : a;
    hi[k] = box.periodic[k] ? component(box.high, k) : b;
  }
  Kokkos::parallel_reduce("vrut::bounds3_rmax", policy(space, 0, n),
      KOKKOS_LAMBDA(const int i, double& m) { if (r(i) > m) m = r(i); }, Kokkos::Max<double>(rmax));
  if (!std::isfinite(lo[0] + lo[1] + lo[2] + hi[0] + hi[1] + hi[2]))
    throw std::runtime_error("vrut: a sphere position is not finite (time step too large?)");
  const double size = 2.0 * rmax + skin;
  int cells[3];
  double cell[3];
  for (int k = 0; k < 3; ++k) {
    if (box.periodic[k]) {
      cells[k] = static_cast<int>(std::floor((hi[k] - lo[k]) / size));
      if (cells[k] < 3)
        throw std::invalid_argument("a periodic axis must be at least 3 reaches long (" + std::to_string(3 * size) +
                                    " m), so that no neighbour is met twice through its two faces");
      cell[k] = (hi[k] - lo[k]) / cells[k];  // at least `size`: cells tile the period exactly
    } else {
      cells[k] = static_cast<int>((hi[k] - lo[k]) / size) + 1;
      cell[k] = size;
    }
  }
  const int nx = cells[0], ny = cells[1], nz = cells[2], ncells = nx * ny * nz;
  const double ox = lo[0], oy = lo[1], oz = lo[2], sx = cell[0], sy = cell[1], sz = cell[2];
  const bool px = box.periodic[0], py = box.periodic[1], pz = box.periodic[2];

  // Counting sort of the spheres into cells.
  Kokkos::View<int*, memory_space> cell_of("cell3_of", n), cell_start("cell3_start", ncells + 1),
      members("cell3_members", n), fill("cell3_fill", ncells);
  Kokkos::parallel_for("vrut::cell3_count", policy(space, 0, n), KOKKOS_LAMBDA(const int i) {
    const Vec3 p = box.wrapped(x(i));
    int ix = static_cast<int>(floor((p.x - ox) / sx)), iy = static_cast<int>(floor((p.y - oy) / sy)),
        iz = static_cast<int>(floor((p.z - oz) / sz));
    ix = ix < 0 ? 0 : (ix >= nx ? nx - 1 : ix);
    iy = iy < 0 ? 0 : (iy >= ny ? ny - 1 : iy);
    iz = iz < 0 ? 0 : (iz >= nz ? nz - 1 : iz);
    cell_of(i) = (iz * ny + iy) * nx + ix;
    Kokkos::atomic_add(&cell_start(cell_of(i) + 1), 1);
  });
  Kokkos::parallel_scan("vrut::cell3_scan", policy(space, 1, ncells + 1),
      KOKKOS_LAMBDA(const int c, int& partial, const bool final) {
        partial += cell_start(c);
        if (final) cell_start(c) = partial;
      });
  Kokkos::parallel_for("vrut::cell3_fill", policy(space, 0, n), KOKKOS_LAMBDA(const int i) {
    const int c = cell_of(i);
    members(cell_start(c) + Kokkos::atomic_fetch_add(&fill(c), 1)) = i;
  });

  const CellStencil3<memory_space> each_partner{x, r, cell_of, cell_start, members, box, skin, nx, ny, nz, px, py, pz};
  PairList3<Space> list;
  list.start = Kokkos::View<int*, memory_space>("pairs3_start", n + 1);
  auto start = list.start;
  Kokkos::parallel_for("vrut::pairs3_count", policy(space, 0, n), KOKKOS_LAMBDA(const int i) {
    int k = 0;
    each_partner(i, [&](int) { ++k; });
    start(i + 1) = k;
  });
  int total = 0;
  Kokkos::parallel_scan("vrut::pairs3_scan", policy(space, 1, n + 1),
      KOKKOS_LAMBDA(const int i, int& partial, const bool final) {
        partial += start(i);
        if (final) start(i) = partial;
      }, total);
  list.partner = Kokkos::View<int*, memory_space>("pairs3_partner", total);
  auto partner = list.partner;
  Kokkos::parallel_for("vrut::pairs3_fill", policy(space, 0, n), KOKKOS_LAMBDA(const int i) {
    int k = start(i);
    each_partner(i, [&](int j) { partner(k++) = j; });
    // Ascending: the cells come in stencil order, not index order.
    for (int a = start(i) + 1; a < start(i + 1); ++a) {
      const int v = partner(a);
      int b = a - 1;
      while (b >= start(i) && partner(b) > v) {
        partner(b + 1) = partner(b);
        --b;
      }
      partner(b + 1) = v;
    }
  });
  return list;
}

}  // namespace vrut
