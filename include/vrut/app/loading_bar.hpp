#pragma once
// The loading's progress on the screen, 2D and 3D alike: a bar in minutes of
// the test, and for a resumed run the minute at which it took the test up
// again (its first sample after the checkpoint), so that a person, or a
// test, can tell a resume from a run started over.
#include "seeds.hpp"

#include <vrut/io/progress.hpp>

#include <cstddef>
#include <cstdio>

namespace vrut::app {

class LoadingBar {
 public:
  // out == nullptr: a silent bar (the other ranks of an MPI run).
  LoadingBar(bool ensemble, std::size_t specimens, double test_minutes, bool resuming, std::FILE* out)
      : bar_(ensemble ? "loading " + cli::specimens_text(specimens) : "loading", 1000,
             {"test min", test_minutes / 1000.0}, out),
        test_minutes_(test_minutes), out_(out), resuming_(resuming) {}

  // At every sample: the fraction of the test done.
  void update(double fraction) {
    if (resuming_ && out_ != nullptr)
      std::fprintf(out_, "resumed: minute %.3f of %.0f is the first sample after the checkpoint\n",
                   fraction * test_minutes_, test_minutes_);
    resuming_ = false;
    bar_.update(static_cast<long>(1000 * fraction));
  }
  void finish() { bar_.finish(); }

 private:
  vrut::ProgressBar bar_;
  double test_minutes_;
  std::FILE* out_;
  bool resuming_;
};

}  // namespace vrut::app
