#pragma once
// A rutting run's stop: Ctrl-C (SIGINT) or SIGTERM sets stop_signal, and the
// run stops at its next sample and writes what it has, with a checkpoint.
#include <csignal>

namespace vrut::app {

inline volatile std::sig_atomic_t stop_signal = 0;
extern "C" inline void on_stop_signal(int signal) { stop_signal = signal; }

// Catches both signals while it lives, then gives them back to whoever had
// them (the shell's default, or Python's own handler in the module).
class CatchStopSignals {
 public:
  CatchStopSignals() {
    stop_signal = 0;
    previous_int_ = std::signal(SIGINT, on_stop_signal);
    previous_term_ = std::signal(SIGTERM, on_stop_signal);
  }
  ~CatchStopSignals() {
    std::signal(SIGINT, previous_int_ == SIG_ERR ? SIG_DFL : previous_int_);
    std::signal(SIGTERM, previous_term_ == SIG_ERR ? SIG_DFL : previous_term_);
  }
  CatchStopSignals(const CatchStopSignals&) = delete;
  CatchStopSignals& operator=(const CatchStopSignals&) = delete;

 private:
  void (*previous_int_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
};

}  // namespace vrut::app
