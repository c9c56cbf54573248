// vrut-demo-custom: the demonstration job with a user-written contact law.
#include "../compression.hpp"
#include "soft_contact.hpp"

int main(int argc, char** argv) {
  demo::Options opts;
  opts.out = "out/demo-custom";
  if (int code = demo::parse(argc, argv, opts, "vrut demo with a user-written contact law"); code >= 0) return code;
  demo::Material mat;
  mat.kn = 2.0 * opts.thickness_mm * 1e-3 * 55.5e6;
  return demo::run<StiffeningContact>(opts, mat, [&] {
    vrut::AssignmentTable<StiffeningContact> table;
    table.set_all({mat.kn, opts.radius_mm * 1e-3, mat.kn / 2.7, 0.5});
    return table;
  }, "user-written StiffeningContact");
}
