#pragma once
// What a rutting run of the application layer (run_rutting_2d, run_rutting_3d)
// hands back to its caller, the command line or the Python module: every
// specimen's result, the report's numbers, and summary.json as written.
#include "rutting_report.hpp"

#include <vrut/protocol/rutting/result.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vrut::app {

struct RuttingOutcome {
  std::vector<vrut::RuttingResult> runs;  // in the seeds' order (on rank 0, every rank's)
  std::vector<std::uint64_t> seeds;
  RuttingReport report;
  nlohmann::json summary;  // summary.json's content, also when no folder is written
  bool ensemble = false;
  bool interrupted = false;  // stopped by a signal: partial results, a checkpoint
  int exit_code = 0;         // what the command line exits with: 0, or 128 + the signal
};

// What the caller wants besides the results.
struct RuttingHooks {
  std::function<void(double)> progress;  // the loading's fraction done, at every sample
  bool print = true;                     // the result's lines on stdout, as the command line prints them
  // Starts the Kokkos runtime on these threads once the options are checked,
  // and keeps it running after the run (the Python module's); unset: the run
  // starts and ends its own (KokkosSession).
  std::function<void(int threads)> start_runtime;
};

}  // namespace vrut::app
