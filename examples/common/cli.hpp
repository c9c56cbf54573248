#pragma once
// What every vrut example does with its command line and its errors.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <stdexcept>

namespace cli {

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

}  // namespace cli
