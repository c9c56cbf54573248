#pragma once
// What one contact between two particles leaves for the sums: the force on
// its second particle (the first takes the reaction) and the moments on both.
#include <vrut/data/dimension.hpp>

namespace vrut {

template <class D>
struct ContactLoadIn {
  typename D::vector force;
  typename D::spin moment_first{}, moment_second{};
};
using ContactLoad = ContactLoadIn<Dim2>;

}  // namespace vrut
