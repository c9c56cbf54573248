#pragma once
// Particle-particle contact list: for each disk (2D) or sphere (3D) i the
// partners j > i within r_i + r_j + skin, found with a cell list (O(N)) and
// the 9- or 27-cell stencil, plus the per-contact law
// state, which survives rebuilds (matched by partner), and a reverse list so
// every disk can sum its contact forces without atomics, in a fixed order.
// That fixed order makes runs bitwise identical across backends and thread counts.
// The disks of an ensemble's specimens share the grid's geometry, but each
// specimen has its own layer of cells, so pairs never cross specimens.
// In 3D an axis of the box (neighbor/periodic_box3.hpp) may be periodic:
// its cells wrap around, and pairs are seen through the face by the nearest
// image. Positions are not wrapped: a particle keeps its continuous path,
// and only its cell is taken modulo the box.
#include <vrut/contact/concept.hpp>
#include <vrut/core/cell_grid.hpp>
#include <vrut/core/contact_load.hpp>
#include <vrut/data/dimension.hpp>
#include <vrut/data/particles.hpp>
#include <vrut/neighbor/periodic_box3.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vrut {

template <class Law, class ExecutionSpace, class D = Dim2>
class ContactList {
 public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using state_type = typename Law::state_type;
  using vector = typename D::vector;
  using particles_type = Particles<memory_space, D>;
  using box_type = PeriodicBox<D>;
  using grid_type = CellGrid<D, ExecutionSpace>;
  static constexpr int dims = D::value;

  Kokkos::View<int**, memory_space> partner;  // (disk, slot) -> partner j > disk
  Kokkos::View<int*, memory_space> count;
  Kokkos::View<state_type**, memory_space> state;
  Kokkos::View<ContactLoadIn<D>**, memory_space> load;
  Kokkos::View<int**, memory_space> reverse;  // (disk, slot) -> contact id i*capacity+k with disk as j
  Kokkos::View<int*, memory_space> reverse_count;
  Kokkos::View<vector*, memory_space> position_at_build;
  box_type box;  // the periodic axes (3D); set before the first build
  int capacity = 0, reverse_capacity = 0;
  int most_partners = 0, most_reverse = 0;  // the longest rows at the last build
  int specimens = 1;  // layers of cells, one per specimen (Particles::specimen)
  long builds = 0;
  grid_type grid;  // public only because device lambdas cannot live in private members

  // Rebuilds from the current positions. Pairs that are bonded in the old
  // list are kept whatever their distance, with their state.
  void rebuild(const execution_space& space, const particles_type& ps, double skin) {
    const int n = static_cast<int>(ps.size());
    // Rows as long as the last build's longest plus one: the rows are
    // contiguous, so slack in them is memory traffic on every step (a 64k-disk
    // block ran 45 % faster with one slot of slack than with four).
    capacity = capacity == 0 ? 8 : most_partners + 1;
    reverse_capacity = reverse_capacity == 0 ? 8 : most_reverse + 1;
    if (count.extent(0) != static_cast<std::size_t>(n)) {  // first build
      partner = decltype(partner)("partner", n, capacity);
      count = decltype(count)("count", n);
      state = decltype(state)("contact_state", n, capacity);
    }
    grid.build(space, ps, skin, box, specimens);
    // Fill again (once or twice) where the rows came out too short or too long.
    for (;;) {
      most_partners = fill(space, ps, skin);
      if (most_partners <= capacity && capacity <= most_partners + 1) break;
      capacity = most_partners + 1;
    }
    for (;;) {
      most_reverse = fill_reverse(space, n);
      if (most_reverse <= reverse_capacity && reverse_capacity <= most_reverse + 1) break;
      reverse_capacity = most_reverse + 1;
    }
    if (position_at_build.extent(0) != static_cast<std::size_t>(n))
      position_at_build = Kokkos::View<vector*, memory_space>("position_at_build", n);
    Kokkos::deep_copy(space, position_at_build, ps.position);
    ++builds;
  }

  // Largest displacement since the last build; a rebuild is due past skin / 2.
  // A position that is not finite counts as a displacement of 1e300 m, so
  // this check, made every step anyway, also finds a run that has blown up.
  double max_displacement(const execution_space& space, const particles_type& ps) const {
    auto x = ps.position;
    auto x0 = position_at_build;
    double m = 0.0;
    Kokkos::parallel_reduce(
        "vrut::max_displacement", Kokkos::RangePolicy<execution_space>(space, 0, ps.size()),
        KOKKOS_LAMBDA(const int i, double& acc) {
          double d = norm(x(i) - x0(i));
          if (!(d < 1e300)) d = 1e300;  // NaN or infinite
          if (d > acc) acc = d;
        },
        Kokkos::Max<double>(m));
    return m;
  }

  // The list's part of a checkpoint (core/simulation.hpp, visit_state); the
  // cell grid is rebuilt with the list.
  template <class Archive>
  void visit(Archive& a) {
    a.view("contact_partner", partner);
    a.view("contact_count", count);
    a.view("contact_state", state);
    a.view("contact_load", load);
    a.view("contact_reverse", reverse);
    a.view("contact_reverse_count", reverse_count);
    a.view("position_at_build", position_at_build);
    a.value("contact_capacity", capacity);
    a.value("contact_reverse_capacity", reverse_capacity);
    a.value("contact_most_partners", most_partners);
    a.value("contact_most_reverse", most_reverse);
    a.value("contact_builds", builds);
  }

  // Fills a new partner list; returns the largest count (> capacity: redo larger).
  int fill(const execution_space& space, const particles_type& ps, double skin) {
    const int n = static_cast<int>(ps.size());
    const int cap = capacity;
    // The rows are written into the last build's Views where they have this
    // shape (a slot past a row's count is never read), else into new ones.
    auto new_partner = reuse_or_new(spare_partner_, "partner", n, cap);
    auto new_count = reuse_or_new(spare_count_, "count", n);
    auto new_state = reuse_or_new(spare_state_, "contact_state", n, cap);
    auto old_partner = partner;
    auto old_count = count;
    auto old_state = state;
    auto x = ps.position;
    auto r = ps.radius;
    auto body = ps.body;
    auto cof = grid.cell_of;
    auto start = grid.cell_start;
    auto members = grid.cell_particles;
    const int cx = grid.cells[0], cy = grid.cells[1], cz = grid.cells[2];
    const bool px = box.periodic[0], py = box.periodic[1], pz = dims == 3 && box.periodic[dims - 1];
    const box_type space_box = box;
    int needed = 0;
    Kokkos::parallel_reduce("vrut::contact_fill", Kokkos::RangePolicy<execution_space>(space, 0, n),
        KOKKOS_LAMBDA(const int i, int& most) {
          int k = 0;
          const int ix = cof(i) % cx, iy = (cof(i) / cx) % cy, iz = (cof(i) / (cx * cy)) % cz;
          const int layer = cof(i) / (cx * cy * cz);
          const int reach_z = dims == 3 ? 1 : 0;
          for (int dz = -reach_z; dz <= reach_z; ++dz) {
            const int zz = grid_type::wrap_or_skip(iz + dz, cz, pz);
            if (zz < 0) continue;
            for (int dy = -1; dy <= 1; ++dy) {
              const int yy = grid_type::wrap_or_skip(iy + dy, cy, py);
              if (yy < 0) continue;
              for (int dx = -1; dx <= 1; ++dx) {
                const int xx = grid_type::wrap_or_skip(ix + dx, cx, px);
                if (xx < 0) continue;
                const int c = ((layer * cz + zz) * cy + yy) * cx + xx;
                for (int m = start(c); m < start(c + 1); ++m) {
                  const int j = members(m);
                  if (j <= i) continue;
                  if (body(i) >= 0 && body(j) == body(i)) continue;  // two members of one rigid body never touch
                  const double reach = r(i) + r(j) + skin;
                  const vector d = space_box.separation(x(i), x(j));
                  if (dot(d, d) < reach * reach) {
                    if (k < cap) new_partner(i, k) = j;
                    ++k;
                  }
                }
              }
            }
          }
          // Bonded pairs stay, however far apart.
          for (int m = 0; m < old_count(i); ++m) {
            if (!is_bonded<Law>(old_state(i, m))) continue;
            const int j = old_partner(i, m);
            bool found = false;
            for (int q = 0; q < k && q < cap; ++q) found = found || new_partner(i, q) == j;
            if (!found) {
              if (k < cap) new_partner(i, k) = j;
              ++k;
            }
          }
          if (k > most) most = k;
          if (k > cap) return;
          // Sorted partners give a fixed summation order on every backend.
          for (int a = 1; a < k; ++a) {
            const int v = new_partner(i, a);
            int b = a - 1;
            while (b >= 0 && new_partner(i, b) > v) {
              new_partner(i, b + 1) = new_partner(i, b);
              --b;
            }
            new_partner(i, b + 1) = v;
          }
          new_count(i) = k;
          for (int a = 0; a < k; ++a) {
            const int j = new_partner(i, a);
            state_type s{};
            for (int m = 0; m < old_count(i); ++m)
              if (old_partner(i, m) == j) s = old_state(i, m);
            new_state(i, a) = s;
          }
        },
        Kokkos::Max<int>(needed));
    if (needed > cap) return needed;
    spare_partner_ = partner;
    spare_count_ = count;
    spare_state_ = state;
    partner = new_partner;
    count = new_count;
    state = new_state;
    // The loads start at zero after every build, as the force pass has not
    // yet been over the new rows.
    if (load.extent(0) == static_cast<std::size_t>(n) && load.extent(1) == static_cast<std::size_t>(cap))
      Kokkos::deep_copy(space, load, ContactLoadIn<D>{});
    else
      load = Kokkos::View<ContactLoadIn<D>**, memory_space>("contact_load", n, cap);
    return needed;
  }

  int fill_reverse(const execution_space& space, int n) {
    const int cap = capacity, rcap = reverse_capacity;
    if (reverse.extent(0) != static_cast<std::size_t>(n) || reverse.extent(1) != static_cast<std::size_t>(rcap))
      reverse = Kokkos::View<int**, memory_space>("reverse", n, rcap);
    if (reverse_count.extent(0) != static_cast<std::size_t>(n))
      reverse_count = Kokkos::View<int*, memory_space>("reverse_count", n);
    else
      Kokkos::deep_copy(space, reverse_count, 0);
    auto rev = reverse;
    auto rcount = reverse_count;
    auto p = partner;
    auto cnt = count;
    Kokkos::parallel_for("vrut::reverse_fill", Kokkos::RangePolicy<execution_space>(space, 0, n),
        KOKKOS_LAMBDA(const int i) {
          for (int k = 0; k < cnt(i); ++k) {
            const int j = p(i, k);
            const int slot = Kokkos::atomic_fetch_add(&rcount(j), 1);
            if (slot < rcap) rev(j, slot) = i * cap + k;
          }
        });
    int needed = 0;
    Kokkos::parallel_reduce("vrut::reverse_sort", Kokkos::RangePolicy<execution_space>(space, 0, n),
        KOKKOS_LAMBDA(const int j, int& most) {
          const int c = rcount(j);
          if (c > most) most = c;
          if (c > rcap) return;
          for (int a = 1; a < c; ++a) {
            const int v = rev(j, a);
            int b = a - 1;
            while (b >= 0 && rev(j, b) > v) {
              rev(j, b + 1) = rev(j, b);
              --b;
            }
            rev(j, b + 1) = v;
          }
        },
        Kokkos::Max<int>(needed));
    return needed;
  }

 private:
  // The Views of the build before last, which a build writes its rows into
  // when their shape fits (a new View costs its allocation and first touch).
  Kokkos::View<int**, memory_space> spare_partner_;
  Kokkos::View<int*, memory_space> spare_count_;
  Kokkos::View<state_type**, memory_space> spare_state_;

  template <class View, class... Extents>
  static View reuse_or_new(const View& spare, const char* label, Extents... extents) {
    const std::size_t want[] = {static_cast<std::size_t>(extents)...};
    bool fits = spare.data() != nullptr;
    for (std::size_t a = 0; a < sizeof...(Extents); ++a) fits = fits && spare.extent(a) == want[a];
    return fits ? spare : View(std::string(label), static_cast<std::size_t>(extents)...);
  }
};

}  // namespace vrut
