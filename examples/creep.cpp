// vrut-creep: virtual uniaxial creep test of an all-mastic, bonded, hex-packed
// block under a constant plate stress, against the macro Burger's model. The
// test, its options and outputs: include/vrut/app/creep_run.hpp (the Python
// module's vrut.creep runs the same).
#include <vrut/app/cli.hpp>
#include <vrut/app/creep_run.hpp>

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  vrut::app::CreepOptions o;
  CLI::App app("vrut-creep: virtual uniaxial creep test of a bonded all-mastic block (Burger's contacts)");
  vrut::app::add_creep_options(app, o);
  if (const int code = vrut::app::cli::parse(app, argc, argv); code >= 0) return code;
  return vrut::app::cli::guarded([&] {
    if (o.out.empty()) throw std::invalid_argument("--out: the output folder, not empty");
    vrut::app::run_creep_app(o);
    return 0;
  });
}
