#pragma once
// A rutting run's stop: Ctrl-C (SIGINT) or SIGTERM sets stop_signal, and the
// run stops at its next sample and writes what it has, with a checkpoint.
#include <csignal>

#include <signal.h>  // sigaction (POSIX)

namespace vrut::app {

inline volatile std::sig_atomic_t stop_signal = 0;
extern "C" inline void on_stop_signal(int signal) { stop_signal = signal; }

// Catches both signals while it lives, then gives them back to whoever had
// them, flags and all (the shell's default, or Python's own handler in the
// module). It leaves stop_signal as it finds it: a signal caught by an outer
// CatchStopSignals (the Python module's, around a whole run) still counts.
class CatchStopSignals {
 public:
  CatchStopSignals() {
    struct sigaction mine {};
    mine.sa_handler = on_stop_signal;
    sigemptyset(&mine.sa_mask);
    sigaction(SIGINT, &mine, &previous_int_);
    sigaction(SIGTERM, &mine, &previous_term_);
  }
  ~CatchStopSignals() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
  }
  CatchStopSignals(const CatchStopSignals&) = delete;
  CatchStopSignals& operator=(const CatchStopSignals&) = delete;

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
};

}  // namespace vrut::app
