// vrut-demo: a bonded hex-packed block compressed by a servo plate, with the
// library's linear contact law and contact bonds.
#include "compression.hpp"

int main(int argc, char** argv) {
  demo::Options opts;
  if (int code = demo::parse(argc, argv, opts, "vrut demo: bonded block under a servo-controlled plate"); code >= 0)
    return code;
  demo::Material mat;
  const double t = opts.thickness_mm * 1e-3;
  mat.kn = 2.0 * t * 55.5e9 * 1e-3;  // a stiff but affordable block: 2 t E with E = 55.5 MPa
  mat.ks = mat.kn / (2.0 * (1.0 + 0.35));
  return demo::run<vrut::LinearBonded>(opts, mat, [&] {
    vrut::AssignmentTable<vrut::LinearBonded> table;
    table.set_all(vrut::linear_bonded_params(mat.kn, mat.ks, 0.5, 1e30, 1e30));
    return table;
  }, "linear + contact bond");
}
