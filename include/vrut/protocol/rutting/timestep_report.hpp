#pragma once
// Which class of contact sets a rutting run's time step, and how far the
// next one trails it: each class's stiffest spring on the lightest mass it
// can meet (Simulation::spring_steps, the terms of contact_timestep). The
// classes: mastic-mastic, mastic-stone, stone-stone (bare stones, or two
// disks of one stone colour in 2D, which never meet with rigid stones but
// count in the step), film (two stones through a film), particle-wall (the
// mould and the plate). Host-only.
#include <vrut/protocol/rutting/materials.hpp>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace vrut {

struct TimestepReport {
  std::string set_by, next;            // classes; empty where not known (no rigid bodies) or no second class
  double step = 0.0, next_step = 0.0;  // s (reduced): sqrt(m / k) of the class's stiffest spring on its lightest mass
  bool known() const { return !set_by.empty(); }
};

inline std::string contact_pair_class(const RuttingLaw::params_type& p, int group_a, int group_b) {
  if (group_a < 0) return "particle-wall";
  if (group_a == mastic_group && group_b == mastic_group) return "mastic-mastic";
  if (group_a == mastic_group || group_b == mastic_group) return "mastic-stone";
  return p.use_second ? "stone-stone" : "film";
}

template <class Sim>
TimestepReport timestep_report(const Sim& sim, const AssignmentTable<RuttingLaw>& table) {
  std::vector<std::pair<double, std::string>> least;  // each class's smallest step
  for (const auto& s : sim.spring_steps()) {
    const std::string c =
        s.group_a < 0 ? "particle-wall" : contact_pair_class(table(s.group_a, s.group_b), s.group_a, s.group_b);
    auto at = std::find_if(least.begin(), least.end(), [&](const auto& l) { return l.second == c; });
    if (at == least.end())
      least.emplace_back(s.step, c);
    else
      at->first = std::min(at->first, s.step);
  }
  std::sort(least.begin(), least.end());
  TimestepReport r;
  if (!least.empty()) r.set_by = least[0].second, r.step = least[0].first;
  if (least.size() > 1) r.next = least[1].second, r.next_step = least[1].first;
  return r;
}

}  // namespace vrut
