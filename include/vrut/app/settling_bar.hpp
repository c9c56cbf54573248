#pragma once
// The settling's progress (the settling callback of run_rutting_ensemble and
// run_rutting_ensemble3): a bar of steps, and one line when Ctrl-C or
// SIGTERM comes while it settles. The run only stops at the loading's first
// sample, where its checkpoint keeps the settled specimens, so the line says
// so rather than leave a long settling silent.
#include "seeds.hpp"
#include "stop_signal.hpp"

#include <vrut/io/progress.hpp>

#include <csignal>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>

namespace vrut::app {

class SettlingBar {
 public:
  // The settling of `specimens` (more than one: an ensemble's); out ==
  // nullptr: silent (the other ranks of an MPI run).
  explicit SettlingBar(std::size_t specimens, std::FILE* out = stderr)
      : label_(specimens > 1 ? "settling " + cli::specimens_text(specimens) : "settling"), out_(out) {}

  void operator()(long done, long steps) {
    if (out_ == nullptr) return;
    if (!bar_) bar_ = std::make_unique<vrut::ProgressBar>(label_, steps, "steps", out_);
    if (stop_signal != 0 && !told_) {
      std::fprintf(out_, "\n%s while settling (%ld of %ld steps): the run stops at the loading's first sample, "
                   "with a checkpoint of the settled specimens\n",
                   stop_signal == SIGTERM ? "SIGTERM" : "Ctrl-C", done, steps);
      told_ = true;
    }
    if (done >= steps) bar_->finish();
    else bar_->update(done);
  }

 private:
  std::string label_;
  std::FILE* out_;
  std::unique_ptr<vrut::ProgressBar> bar_;
  bool told_ = false;
};

}  // namespace vrut::app
