// Must NOT compile: the law has no stiffness(). The test that builds this
// file passes only if the compiler names the missing member.
#include <vrut/vrut.hpp>

struct LawWithoutStiffness {
  struct params_type { double k; };
  struct state_type {};
  KOKKOS_INLINE_FUNCTION static vrut::ContactForce force(const params_type& p, state_type&,
                                                         const vrut::ContactGeometry& g) {
    return {p.k * g.overlap, 0.0};
  }
};

int main() {
  vrut::AssignmentTable<LawWithoutStiffness> table;
  vrut::Simulation<LawWithoutStiffness, Kokkos::DefaultHostExecutionSpace> sim(vrut::ParticleSet{}, table);
  return 0;
}
