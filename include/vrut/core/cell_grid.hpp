#pragma once
// The engine's cell grid: particles binned in cubes (squares in 2D) at least
// one contact reach wide, one layer of cells per specimen of an ensemble, so
// that a particle's partners lie in its own and the 9 (2D) or 27 (3D) cells
// around it (core/contact_list.hpp walks that stencil). Along a periodic axis
// the cells tile the box and wrap around; along the others they span the
// particles, and a coordinate outside is clamped to the edge cells. The grid
// is rebuilt with the list, from the particles as they are.
//
// The specimen generators bin their stones in grids of their own
// (specimen/placement.hpp's AggregateGrid, specimen/placement3.hpp's
// StoneGrid3): those hold polygons and polyhedra by their bounding boxes
// while a specimen is being placed, on the host, one at a time as each is
// accepted; this one holds particles on the device, rebuilt in bulk.
// The docs (docs/core.md, "Three grids") say why they stay apart.
#include <vrut/data/dimension.hpp>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace vrut {

template <class D, class ExecutionSpace>
struct CellGrid {
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  static constexpr int dims = D::value;

  Kokkos::View<int*, memory_space> cell_of, cell_start, cell_particles;
  int cells[3] = {1, 1, 1};  // per axis, per specimen layer (the third is 1 in 2D)
  double cell_width[3] = {0.0, 0.0, 0.0}, origin[3] = {0.0, 0.0, 0.0};

  // Bins the particles for pairs within their radii and skin; box: the
  // periodic axes; specimens: the layers.
  template <class Particles, class Box>
  void build(const execution_space& space, const Particles& ps, double skin, const Box& box, int specimens) {
    const int n = static_cast<int>(ps.size());
    auto x = ps.position;
    auto r = ps.radius;
    auto specimen = ps.specimen;
    double low[3] = {0.0, 0.0, 0.0}, high[3] = {0.0, 0.0, 0.0}, rmax = 0.0;
    for (int k = 0; k < dims; ++k) {
      Kokkos::parallel_reduce("vrut::bounds_min", Kokkos::RangePolicy<execution_space>(space, 0, n),
          KOKKOS_LAMBDA(const int i, double& a) { if (component(x(i), k) < a) a = component(x(i), k); },
          Kokkos::Min<double>(low[k]));
      Kokkos::parallel_reduce("vrut::bounds_max", Kokkos::RangePolicy<execution_space>(space, 0, n),
          KOKKOS_LAMBDA(const int i, double& a) { if (component(x(i), k) > a) a = component(x(i), k); },
          Kokkos::Max<double>(high[k]));
      if (!std::isfinite(low[k] + high[k]))
        throw std::runtime_error("vrut: a particle position is not finite (time step too large?)");
    }
    Kokkos::parallel_reduce("vrut::bounds_rmax", Kokkos::RangePolicy<execution_space>(space, 0, n),
        KOKKOS_LAMBDA(const int i, double& a) { if (r(i) > a) a = r(i); }, Kokkos::Max<double>(rmax));
    const double reach = 2.0 * rmax + skin;
    // Along a periodic axis the cells tile the box; along the others they
    // span the particles.
    auto span = [&](int k) { return box.periodic[k] ? box.length(k) : high[k] - low[k]; };
    auto count_along = [&](int k, double size) {
      return box.periodic[k] ? static_cast<int>(span(k) / size) : static_cast<int>(span(k) / size) + 1;
    };
    double size = reach;
    // Keep the grid at most ~4 cells per particle, whatever the spread.
    const double per_layer = static_cast<double>(n) / (specimens > 0 ? specimens : 1);
    for (;;) {
      double total = 1.0;
      bool periodic_would_fall_short = false;  // below 3 cells, had the cells doubled
      for (int k = 0; k < dims; ++k) {
        total *= box.periodic[k] ? span(k) / size : span(k) / size + 1.0;
        periodic_would_fall_short = periodic_would_fall_short || (box.periodic[k] && count_along(k, 2.0 * size) < 3);
      }
      if (total <= 4.0 * per_layer + 16.0 || periodic_would_fall_short) break;
      size *= 2.0;
    }
    for (int k = 0; k < dims; ++k) {
      cells[k] = count_along(k, size);
      if (box.periodic[k] && cells[k] < 3)
        throw std::invalid_argument("vrut: a periodic axis must be at least 3 contact reaches long (" +
                                    std::to_string(3.0 * reach) + " m here; the box has " +
                                    std::to_string(span(k)) + " m)");
      cell_width[k] = box.periodic[k] ? span(k) / cells[k] : size;
      origin[k] = box.periodic[k] ? component(box.low, k) : low[k];
    }
    const int ncells = cells[0] * cells[1] * cells[2] * (specimens > 0 ? specimens : 1);

    cell_of = Kokkos::View<int*, memory_space>("cell_of", n);
    cell_start = Kokkos::View<int*, memory_space>("cell_start", ncells + 1);
    cell_particles = Kokkos::View<int*, memory_space>("cell_particles", n);
    Kokkos::View<int*, memory_space> fill("cell_fill", ncells);
    auto cof = cell_of;
    auto start = cell_start;
    auto members = cell_particles;
    const int cx = cells[0], cy = cells[1], cz = cells[2];
    const double ox = origin[0], oy = origin[1], oz = origin[2];
    const double wx = cell_width[0], wy = cell_width[1], wz = cell_width[2];
    const bool px = box.periodic[0], py = box.periodic[1], pz = dims == 3 && box.periodic[dims - 1];
    Kokkos::parallel_for("vrut::cell_count", Kokkos::RangePolicy<execution_space>(space, 0, n),
        KOKKOS_LAMBDA(const int i) {
          const int ix = cell_index(component(x(i), 0), ox, wx, cx, px);
          const int iy = cell_index(component(x(i), 1), oy, wy, cy, py);
          const int iz = dims == 3 ? cell_index(component(x(i), 2), oz, wz, cz, pz) : 0;
          cof(i) = ((specimen(i) * cz + iz) * cy + iy) * cx + ix;
          Kokkos::atomic_add(&start(cof(i) + 1), 1);  // atomic_increment is deprecated in Kokkos 4
        });
    Kokkos::parallel_scan("vrut::cell_scan", Kokkos::RangePolicy<execution_space>(space, 1, ncells + 1),
        KOKKOS_LAMBDA(const int c, int& partial, const bool final) {
          partial += start(c);
          if (final) start(c) = partial;
        });
    Kokkos::parallel_for("vrut::cell_fill", Kokkos::RangePolicy<execution_space>(space, 0, n),
        KOKKOS_LAMBDA(const int i) {
          const int c = cof(i);
          members(start(c) + Kokkos::atomic_fetch_add(&fill(c), 1)) = i;
        });
  }

  // The cell of coordinate c along an axis: wrapped around a periodic one,
  // clamped to the grid along the others.
  KOKKOS_INLINE_FUNCTION static int cell_index(double c, double origin, double width, int cells, bool periodic) {
    if (periodic) {
      int k = static_cast<int>(floor((c - origin) / width)) % cells;
      return k < 0 ? k + cells : k;
    }
    const int k = static_cast<int>((c - origin) / width);
    return k < 0 ? 0 : (k >= cells ? cells - 1 : k);
  }

  // A neighbour cell's index along an axis: wrapped on a periodic one, -1
  // past the grid's edge on the others.
  KOKKOS_INLINE_FUNCTION static int wrap_or_skip(int k, int cells, bool periodic) {
    if (periodic) return k < 0 ? k + cells : (k >= cells ? k - cells : k);
    return k < 0 || k >= cells ? -1 : k;
  }

};

}  // namespace vrut
