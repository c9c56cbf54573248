#pragma once
// Which parameters a contact gets, from the material groups of its two disks.
// Host-side table; the Simulation copies it to the device once.
#include <vrut/contact/concept.hpp>

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut {

template <class Law>
class AssignmentTable {
 public:
  using params_type = typename Law::params_type;

  explicit AssignmentTable(int groups = 1)
      : groups_(groups), params_(static_cast<std::size_t>(groups) * groups), set_(params_.size(), 0) {
    if (groups < 1) throw std::invalid_argument("vrut: an assignment table needs at least one group");
  }

  int groups() const { return groups_; }

  // The pair (a, b) and (b, a) get p.
  AssignmentTable& set(int a, int b, const params_type& p) {
    check(a);
    check(b);
    params_[index(a, b)] = p;
    params_[index(b, a)] = p;
    set_[index(a, b)] = set_[index(b, a)] = 1;
    return *this;
  }
  AssignmentTable& set_all(const params_type& p) {
    for (int a = 0; a < groups_; ++a)
      for (int b = 0; b < groups_; ++b) set(a, b, p);
    return *this;
  }

  bool is_set(int a, int b) const { return set_[index(a, b)] != 0; }
  const params_type& operator()(int a, int b) const {
    if (!is_set(a, b))
      throw std::logic_error("vrut: no contact parameters for groups " + std::to_string(a) + " and " +
                             std::to_string(b));
    return params_[index(a, b)];
  }

  double max_stiffness() const {
    double k = 0.0;
    for (std::size_t i = 0; i < params_.size(); ++i)
      if (set_[i]) k = std::max(k, static_cast<double>(Law::stiffness(params_[i])));
    return k;
  }

 private:
  std::size_t index(int a, int b) const { return static_cast<std::size_t>(a) * groups_ + b; }
  void check(int g) const {
    if (g < 0 || g >= groups_)
      throw std::out_of_range("vrut: material group " + std::to_string(g) + " outside [0, " +
                              std::to_string(groups_) + ")");
  }
  int groups_;
  std::vector<params_type> params_;
  std::vector<char> set_;
};

// The table's parameters into `view` (groups x groups, on the device), for
// the law in its engine form; returns each pair's stiffness (-1: not set),
// row by row, for the time step.
template <class Law, class Spec, class View>
std::vector<double> upload_table(const AssignmentTable<Spec>& table, const View& view) {
  auto host = Kokkos::create_mirror_view(view);
  std::vector<double> stiffness(static_cast<std::size_t>(table.groups()) * table.groups(), -1.0);
  for (int a = 0; a < table.groups(); ++a)
    for (int b = 0; b < table.groups(); ++b)
      if (table.is_set(a, b)) {
        host(a, b) = table(a, b);
        stiffness[static_cast<std::size_t>(a) * table.groups() + b] = Law::stiffness(table(a, b));
      }
  Kokkos::deep_copy(view, host);
  return stiffness;
}

}  // namespace vrut
