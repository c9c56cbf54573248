#pragma once
// The engine's default wall controller: it leaves every wall at the
// velocity it was given (velocity control). Controllers that act on the
// load, a servo and a dead load, are servo/servo.hpp's.
#include <Kokkos_Core.hpp>

namespace vrut {

struct VelocityControl {
  struct params_type {};
  struct state_type {};
  template <class W, class Load>
  KOKKOS_INLINE_FUNCTION static void control(const params_type&, state_type&, W&, const Load&, double) {}
};

}  // namespace vrut
