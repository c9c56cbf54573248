#pragma once
// Seed lists for ensembles: "1-16", "1,4,9", "1-4,10-12".
#include <cstddef>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrut::app::cli {

// "1 specimen", "3 specimens": an ensemble may be of one seed (--seeds 4).
inline std::string specimens_text(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " specimen" : " specimens");
}

inline std::vector<std::uint64_t> parse_seed_list(const std::string& text) {
  auto bad = [&](const std::string& why) {
    return std::invalid_argument("--seeds '" + text + "': " + why + " (write a range or a list, e.g. 1-16 or 1,4,9)");
  };
  auto number = [&](const std::string& s) -> std::uint64_t {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos) throw bad("'" + s + "' is not a seed");
    try {
      return std::stoull(s);
    } catch (const std::out_of_range&) {
      throw bad("'" + s + "' is too large");
    }
  };
  std::vector<std::uint64_t> seeds;
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    const std::string item = text.substr(from, comma - from);
    const std::size_t dash = item.find('-');
    if (dash == std::string::npos) {
      seeds.push_back(number(item));
    } else {
      const std::uint64_t a = number(item.substr(0, dash)), b = number(item.substr(dash + 1));
      if (b < a) throw bad("the range " + item + " runs backwards");
      if (b - a >= 100000) throw bad("the range " + item + " is too long");
      for (std::uint64_t s = a; s <= b; ++s) seeds.push_back(s);
    }
    from = comma + 1;
  }
  std::set<std::uint64_t> seen;
  for (std::uint64_t s : seeds)
    if (!seen.insert(s).second) throw bad("seed " + std::to_string(s) + " appears twice");
  return seeds;
}

}  // namespace vrut::app::cli
