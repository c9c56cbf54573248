#pragma once
// A run that blew up: some particle jumped more than a diameter in one step,
// or its position is no longer finite. The engine checks it every step
// (core/simulation.hpp, step) and throws SimulationUnstable with a message
// that says where, and how the step compares with the critical one.
#include <vrut/core/geometry.hpp>

#include <Kokkos_Core.hpp>

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace vrut {

class SimulationUnstable : public std::runtime_error {
 public:
  SimulationUnstable(const std::string& what, long step) : std::runtime_error(what), step_(step) {}
  long step() const { return step_; }  // the step (counted from 1) that made it so

 private:
  long step_;
};

// Names the first particle that moved more than `limit` from where it was at
// the list's build (x0), and how many more did; step and t: the steps and
// time done; critical: sqrt(m_min / k_max).
template <class Dim, class Particles, class Positions>
[[noreturn]] void throw_instability(const Particles& ps, const Positions& at_build, double limit, long step, double t,
                                    double dt, double critical) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.position);
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), at_build);
  auto s = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), ps.specimen);
  std::size_t bad = 0, count = 0;
  for (std::size_t i = x.extent(0); i-- > 0;)
    if (!(norm(x(i) - x0(i)) <= limit)) bad = i, ++count;
  char text[512];
  char where[96];
  Geometry<Dim>::describe(where, sizeof where, bad, s(bad), x(bad));
  std::snprintf(text, sizeof text,
                "vrut: the simulation became unstable at step %ld (t = %.4g s): %s, and %zu more jumped more than "
                "a diameter in one step or are not finite. The time step %.4g s is %.3g of sqrt(m_min / k_max) = "
                "%.4g s; dense packings need 0.1 to 0.3 of it.",
                step, t, where, count - 1, dt, dt / critical, critical);
  throw SimulationUnstable(text, step);
}

}  // namespace vrut
