// libFuzzer target: the gradation CSV reader, then the stereology it feeds.
// Bad input must end in std::invalid_argument with a message, never in a
// crash, a hang or undefined behaviour. See docs/fuzzing.md.
#include <vrut/specimen/stereology.hpp>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const vrut::Gradation g = vrut::parse_gradation_csv(in, "fuzz.csv");
    (void)vrut::stereology(g, vrut::MixVolumetrics{});
  } catch (const std::invalid_argument&) {
    // a clear refusal: what bad input should get
  }
  return 0;
}
