#pragma once
// The walls of a simulation: where they are (on the host and the device),
// their laws and controllers, each particle's contact state with each wall
// of its specimen, and the loads. Each wall belongs to one specimen of an
// ensemble and touches only its particles; a specimen's walls take slots 0,
// 1, ... in the order they were added, and (particle, slot) indexes the
// contact state and load. The particles' side of a wall contact is summed
// with their other forces (core/sum_and_advance.hpp); here the loads are
// summed per wall and the walls move (move).
#include <vrut/core/geometry.hpp>
#include <vrut/data/walls.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

template <class Dim, class WallLaw, class Controller, class ExecutionSpace>
struct WallSet {
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using vector = typename Dim::vector;
  using wall_type = typename Geometry<Dim>::wall_type;
  using wall_load_type = WallLoadIn<Dim>;
  using params_type = typename WallLaw::params_type;
  using state_type = typename WallLaw::state_type;
  using controller_params = typename Controller::params_type;
  using controller_state = typename Controller::state_type;
  using WallMask = unsigned long long;
  static constexpr int max_walls_per_specimen = 64;
  // Wall loads are summed in fixed blocks of the wall's specimen, then the
  // blocks in order, so the sum depends neither on the backend nor on the
  // other specimens.
  static constexpr int reduce_block = 512;

  // The host's copies: the walls (where they were last pulled), laws, controls, owners.
  std::vector<wall_type> host;
  std::vector<params_type> params_host;
  std::vector<controller_params> control_host;
  std::vector<int> specimen_host;
  double stiffness = 0.0;  // the stiffest wall spring, for the time step
  int blocks = 0;          // reduce blocks of the largest specimen

  Kokkos::View<int*, memory_space> specimen, slot, specimen_wall_count;
  Kokkos::View<int**, memory_space> specimen_walls;
  Kokkos::View<wall_type*, memory_space> walls;
  Kokkos::View<vector*, memory_space> normal;  // inward, unit
  Kokkos::View<params_type*, memory_space> params;
  Kokkos::View<controller_params*, memory_space> control;
  Kokkos::View<controller_state*, memory_space> control_state;
  Kokkos::View<state_type**, memory_space> state;
  Kokkos::View<wall_load_type**, memory_space> load, block_load;
  Kokkos::View<WallMask*, memory_space> touch;  // per particle: bit q set where slot q holds state or load
  Kokkos::View<wall_load_type*, memory_space> total;
  Kokkos::View<vector*, memory_space> impulse;

  int size() const { return static_cast<int>(host.size()); }

  // Adds a wall of specimen s (of `specimens`) on n particles; returns its index.
  int add(const execution_space& space, const wall_type& wall, const params_type& p, const controller_params& c,
          int s, int specimens, int n) {
    Geometry<Dim>::check(wall);
    if (s < 0 || s >= specimens)
      throw std::invalid_argument("vrut::Simulation: wall for specimen " + std::to_string(s) + ", but there are " +
                                  std::to_string(specimens));
    pull();  // the device holds where the existing walls have moved to
    const int w = size();
    host.push_back(wall);
    params_host.push_back(p);
    control_host.push_back(c);
    specimen_host.push_back(s);
    stiffness = std::max(stiffness, static_cast<double>(WallLaw::stiffness(p)));
    rebuild(space, n, specimens);
    return w;
  }

  // The device's views for the walls there are, on n particles of `nspec`
  // specimens; the existing walls keep their slots and contact states.
  void rebuild(const execution_space& space, int n, int nspec) {
    const int nwalls = size();
    std::vector<int> slots_used(nspec, 0), slot_of(nwalls);
    for (int w = 0; w < nwalls; ++w) slot_of[w] = slots_used[specimen_host[w]]++;
    const int slots = nspec > 0 ? *std::max_element(slots_used.begin(), slots_used.end()) : 0;
    if (slots > max_walls_per_specimen)
      throw std::invalid_argument("vrut::Simulation: more than " + std::to_string(max_walls_per_specimen) +
                                  " walls for one specimen");
    if (touch.extent(0) != static_cast<std::size_t>(n)) touch = Kokkos::View<WallMask*, memory_space>("wall_touch", n);
    specimen = Kokkos::View<int*, memory_space>("wall_specimen", nwalls);
    slot = Kokkos::View<int*, memory_space>("wall_slot", nwalls);
    specimen_walls = Kokkos::View<int**, memory_space>("specimen_walls", nspec, slots);
    specimen_wall_count = Kokkos::View<int*, memory_space>("specimen_wall_count", nspec);
    {
      auto hs = Kokkos::create_mirror_view(specimen);
      auto hq = Kokkos::create_mirror_view(slot);
      auto hw = Kokkos::create_mirror_view(specimen_walls);
      auto hc = Kokkos::create_mirror_view(specimen_wall_count);
      for (int w = 0; w < nwalls; ++w) {
        hs(w) = specimen_host[w];
        hq(w) = slot_of[w];
        hw(hs(w), hq(w)) = w;
      }
      for (int s = 0; s < nspec; ++s) hc(s) = slots_used[s];
      Kokkos::deep_copy(specimen, hs);
      Kokkos::deep_copy(slot, hq);
      Kokkos::deep_copy(specimen_walls, hw);
      Kokkos::deep_copy(specimen_wall_count, hc);
    }
    walls = Kokkos::View<wall_type*, memory_space>("walls", nwalls);
    normal = Kokkos::View<vector*, memory_space>("wall_normal", nwalls);
    params = Kokkos::View<params_type*, memory_space>("wall_params", nwalls);
    control = Kokkos::View<controller_params*, memory_space>("wall_control", nwalls);
    Kokkos::View<controller_state*, memory_space> new_control_state("wall_control_state", nwalls);
    if (control_state.extent(0) > 0)
      Kokkos::deep_copy(Kokkos::subview(new_control_state, std::make_pair(std::size_t(0), control_state.extent(0))),
                        control_state);
    control_state = new_control_state;
    total = Kokkos::View<wall_load_type*, memory_space>("wall_total", nwalls);
    impulse = Kokkos::View<vector*, memory_space>("wall_impulse", nwalls);
    // A new wall takes a new slot of its specimen, so the existing slots keep their walls.
    Kokkos::View<state_type**, memory_space> new_state("wall_state", n, slots);
    if (state.extent(1) > 0) {
      auto old = state;
      const int kept = static_cast<int>(old.extent(1));
      Kokkos::parallel_for("vrut::keep_wall_state", Kokkos::RangePolicy<execution_space>(space, 0, n),
          KOKKOS_LAMBDA(const int i) { for (int w = 0; w < kept; ++w) new_state(i, w) = old(i, w); });
    }
    state = new_state;
    load = Kokkos::View<wall_load_type**, memory_space>("wall_load", n, slots);
    block_load = {};
    push();
  }

  // The host's walls, laws and controls to the device. A wall's normal:
  // walls translate (move) but never turn, so it stays as computed here.
  void push() {
    const int nwalls = size();
    auto hn = Kokkos::create_mirror_view(normal);
    for (int w = 0; w < nwalls; ++w) hn(w) = inward_normal(host[w]);
    Kokkos::deep_copy(normal, hn);
    auto hw = Kokkos::create_mirror_view(walls);
    auto hp = Kokkos::create_mirror_view(params);
    auto hc = Kokkos::create_mirror_view(control);
    for (int w = 0; w < nwalls; ++w) {
      hw(w) = host[w];
      hp(w) = params_host[w];
      hc(w) = control_host[w];
    }
    Kokkos::deep_copy(walls, hw);
    Kokkos::deep_copy(params, hp);
    Kokkos::deep_copy(control, hc);
  }
  // Where the walls have moved to, to the host.
  void pull() {
    if (host.empty()) return;
    auto hw = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), walls);
    for (int w = 0; w < size(); ++w) host[w] = hw(w);
  }

  void set_control(int w, const controller_params& c) {
    pull();
    control_host.at(w) = c;
    push();
  }
  void set_velocity(int w, vector v) {
    pull();
    host.at(w).velocity = v;
    push();
  }
  wall_type at(int w) {
    pull();
    return host.at(w);
  }
  const std::vector<wall_type>& all() {
    pull();
    return host;
  }
  wall_load_type load_of(int w) const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), total);
    return h(w);
  }
  std::vector<vector> impulses() const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), impulse);
    return std::vector<vector>(h.data(), h.data() + h.extent(0));
  }

  // Each wall's load summed in fixed blocks of its specimen (specimen s's
  // particles are begin(s) .. begin(s + 1) - 1), then the blocks in order;
  // then the controllers and the motion.
  void move(const execution_space& space, const Kokkos::View<int*, memory_space>& begin, double dt) {
    const int nwalls = size();
    if (nwalls == 0) return;
    const int nblocks = blocks;
    if (block_load.extent(0) != static_cast<std::size_t>(nblocks) || block_load.extent(1) != static_cast<std::size_t>(nwalls))
      block_load = Kokkos::View<wall_load_type**, memory_space>("wall_block_load", nblocks, nwalls);
    auto bl = block_load;
    auto wload = load;
    auto wtouch = touch;
    auto owner = specimen;
    auto wslot = slot;
    Kokkos::parallel_for("vrut::wall_blocks",
        Kokkos::RangePolicy<execution_space>(space, 0, nblocks * nwalls), KOKKOS_LAMBDA(const int bw) {
          const int b = bw / nwalls, w = bw % nwalls;
          const int first = begin(owner(w)), last = begin(owner(w) + 1), q = wslot(w);
          wall_load_type sum;
          const int end = first + (b + 1) * reduce_block < last ? first + (b + 1) * reduce_block : last;
          // Clear bits stand for zero loads: skipping them leaves the sum bit for bit the same.
          for (int i = first + b * reduce_block; i < end; ++i)
            if ((wtouch(i) >> q) & 1u) sum += wload(i, q);
          bl(b, w) = sum;
        });
    auto wall_view = walls;
    auto wtotal = total;
    auto wimpulse = impulse;
    auto wcontrol = control;
    auto wcontrol_state = control_state;
    Kokkos::parallel_for("vrut::move_walls", Kokkos::RangePolicy<execution_space>(space, 0, nwalls),
        KOKKOS_LAMBDA(const int w) {
          wall_load_type sum;
          const int own_blocks = (begin(owner(w) + 1) - begin(owner(w)) + reduce_block - 1) / reduce_block;
          for (int b = 0; b < own_blocks; ++b) sum += bl(b, w);
          wtotal(w) = sum;
          wimpulse(w) += dt * sum.force;
          wall_type wall = wall_view(w);
          Controller::control(wcontrol(w), wcontrol_state(w), wall, sum, dt);
          translate(wall, dt * wall.velocity);
          wall_view(w) = wall;
        });
  }

  // The walls' part of a checkpoint (core/simulation.hpp, visit_state).
  template <class Archive>
  void visit(Archive& a) {
    pull();
    const std::size_t nwalls = host.size();
    a.vector("walls", host);
    a.vector("wall_control", control_host);
    if (host.size() != nwalls || control_host.size() != nwalls)
      throw std::invalid_argument("vrut::Simulation: the checkpoint has " + std::to_string(host.size()) +
                                  " walls, this simulation " + std::to_string(nwalls));
    a.view("wall_control_state", control_state);
    a.view("wall_state", state);
    a.view("wall_load", load);
    a.view("wall_touch", touch);
    a.view("wall_total", total);
    a.view("wall_impulse", impulse);
    push();
  }
};

}  // namespace vrut
