// libFuzzer target: the config-file reader (CLI11's INI/TOML reader, as
// `--config` uses it) with vrut's specimen options and their checks, then the
// settings and stereology they lead to. Bad input must end in a CLI11 parse
// error or std::invalid_argument, never in a crash. See docs/fuzzing.md.
#include <vrut/app/specimen_cli.hpp>

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace vrut::app;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  specimen_cli::SpecimenOptions options;
  CLI::App app("fuzz");
  app.allow_config_extras(false);
  specimen_cli::add_specimen_options(app, options);
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    app.parse_from_stream(in);
    if (options.gradation != "1" && options.gradation != "2" && options.gradation != "3") return 0;  // no file reads
    const vrut::SpecimenSettings s = specimen_cli::to_settings(options);
    (void)vrut::stereology(s.gradation, s.mix);
  } catch (const CLI::Error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
