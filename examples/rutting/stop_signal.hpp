#pragma once
// vrut-rutting's stop: Ctrl-C (SIGINT) or SIGTERM sets stop_signal, and the
// run stops at its next sample and writes what it has, with a checkpoint.
#include <csignal>

namespace {

volatile std::sig_atomic_t stop_signal = 0;
extern "C" void on_stop_signal(int signal) { stop_signal = signal; }

// Catches both signals while it lives.
struct CatchStopSignals {
  CatchStopSignals() {
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
  }
  ~CatchStopSignals() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
  CatchStopSignals(const CatchStopSignals&) = delete;
  CatchStopSignals& operator=(const CatchStopSignals&) = delete;
};

}  // namespace
