#pragma once
// What every vrut example does with its command line and its errors.
#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <iostream>
#include <stdexcept>

namespace vrut::app::cli {

// CLI11's PositiveNumber and Range let NaN through (every comparison with it
// is false), and PositiveNumber infinity too: these refuse both. CLI11 puts
// the option's name before the message, and the command exits 2.
inline CLI::Validator finite_positive() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v)) return "not a number: '" + text + "'";
        if (!std::isfinite(v) || !(v > 0.0)) return "must be a finite positive number, got " + text;
        return {};
      },
      "POSITIVE");
}

// A finite number in [lo, hi], or in [lo, hi) where `open_above`.
inline CLI::Validator finite_range(double lo, double hi, bool open_above = false) {
  const std::string range = "[" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + (open_above ? ")" : "]");
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v)) return "not a number: '" + text + "'";
        if (!std::isfinite(v) || v < lo || v > hi || (open_above && v == hi))
          return "must be a finite number in " + range + ", got " + text;
        return {};
      },
      "FLOAT in " + range);
}

// finite_range(lo, hi), or exactly `sentinel` (an option's "left to the
// program", as -1).
inline CLI::Validator finite_range_or(double sentinel, double lo, double hi) {
  const CLI::Validator in_range = finite_range(lo, hi);
  const std::string range = "[" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]";
  const std::string either = CLI::detail::to_string(sentinel) + " or " + range;
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0.0;
        if (CLI::detail::lexical_cast(text, v) && v == sentinel) return {};
        std::string copy = text;
        return in_range(copy).empty() ? std::string{} : "must be " + either + ", got " + text;
      },
      "FLOAT: " + either);
}

// Parses; returns -1 to go on, else the exit code: 0 after --help, 2 for a
// malformed command line (CLI11's own codes are not 1 or 2).
inline int parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  return -1;
}

// Runs body() and turns an escaping exception into a message and an exit
// code: 2 for bad input (std::invalid_argument), 1 for anything else.
template <class Body>
int guarded(Body&& body) {
  try {
    return body();
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace vrut::app::cli
