#pragma once
// The time scales of a simulation's springs, from which the step is chosen
// (core/simulation.hpp, critical_timestep): each pair of material groups'
// stiffness from the law table, the walls' stiffest spring, and each group's
// lightest mass a contact moves (core/body_set.hpp).
#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace vrut {

// The lightest particle's mass.
template <class Space, class Masses>
double lightest_mass(const Space& space, const Masses& m) {
  double mmin = 0.0;
  Kokkos::parallel_reduce("vrut::min_mass", Kokkos::RangePolicy<Space>(space, 0, m.extent(0)),
      KOKKOS_LAMBDA(const int i, double& a) { if (m(i) < a) a = m(i); }, Kokkos::Min<double>(mmin));
  return mmin;
}

// One spring's own sqrt(m / k): between groups a <= b, or a wall's (a = b = -1).
struct SpringStep {
  int group_a = -1, group_b = -1;
  double step = 0.0;
};

struct SpringScales {
  std::vector<double> pair_stiffness;         // groups x groups, the table's stiffness (-1: not set)
  std::vector<double> lightest_contact_mass;  // per group (0: absent)
  double wall_stiffness = 0.0;

  int groups() const { return static_cast<int>(std::lround(std::sqrt(static_cast<double>(pair_stiffness.size())))); }
  double lightest(int g) const {
    return g < static_cast<int>(lightest_contact_mass.size()) ? lightest_contact_mass[g] : 0.0;
  }

  // The smallest sqrt(m / k) over the springs that can act: for each two
  // material groups present, the table's stiffness over the lighter of the
  // two groups' lightest masses; for the walls, their stiffest spring over
  // the lightest mass of any group. A disk's mass is its own; a member's is
  // 1 / (1 / M + d^2 / I), its body's mass M as felt at its centre, d from
  // the body's (a normal force acts through the member's centre).
  double contact_timestep() const {
    const int n = groups();
    double worst = 0.0;  // largest k / m
    double mall = 0.0;
    for (int a = 0; a < n; ++a) {
      if (!(lightest(a) > 0.0)) continue;
      mall = mall > 0.0 ? std::min(mall, lightest(a)) : lightest(a);
      for (int b = 0; b < n; ++b) {
        const double k = pair_stiffness[static_cast<std::size_t>(a) * n + b];
        if (lightest(b) > 0.0 && k > 0.0) worst = std::max(worst, k / std::min(lightest(a), lightest(b)));
      }
    }
    if (wall_stiffness > 0.0) worst = std::max(worst, wall_stiffness / mall);
    if (!(worst > 0.0)) throw std::logic_error("vrut::Simulation: no positive contact stiffness");
    return 1.0 / std::sqrt(worst);
  }

  // contact_timestep's terms, each spring's own sqrt(m / k): for each two
  // groups present (a <= b) and for the walls. The step is the smallest; the
  // others say how far each trails it.
  std::vector<SpringStep> spring_steps() const {
    std::vector<SpringStep> out;
    const int n = groups();
    double mall = 0.0;
    for (int a = 0; a < n; ++a) {
      if (!(lightest(a) > 0.0)) continue;
      mall = mall > 0.0 ? std::min(mall, lightest(a)) : lightest(a);
      for (int b = a; b < n; ++b) {
        const double k = pair_stiffness[static_cast<std::size_t>(a) * n + b];
        if (lightest(b) > 0.0 && k > 0.0) out.push_back({a, b, 1.0 / std::sqrt(k / std::min(lightest(a), lightest(b)))});
      }
    }
    if (wall_stiffness > 0.0 && mall > 0.0) out.push_back({-1, -1, 1.0 / std::sqrt(wall_stiffness / mall)});
    return out;
  }
};

}  // namespace vrut
