// Must NOT compile: the law has no state_type.
#include <vrut/vrut.hpp>

struct LawWithoutState {
  struct params_type { double k; };
  static double stiffness(const params_type& p) { return p.k; }
};

static_assert(vrut::check_contact_law<LawWithoutState>(), "");
int main() { return 0; }
