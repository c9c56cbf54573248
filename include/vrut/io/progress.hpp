#pragma once
// A terminal progress bar for long runs: percent, rate, ETA. On a terminal it
// redraws one line; otherwise (logs, CI) it prints a line every 10 %.
// Host-only.
#include <chrono>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace vrut {

class ProgressBar {
 public:
  // out == nullptr: a silent bar (the other ranks of an MPI run, say).
  ProgressBar(std::string label, long total, std::string unit = "steps", std::FILE* out = stderr)
      : label_(std::move(label)), unit_(std::move(unit)), total_(total > 0 ? total : 1), out_(out),
        tty_(out != nullptr && isatty(fileno(out)) != 0), start_(clock::now()), last_draw_(start_) {}

  void update(long done) {
    if (out_ == nullptr) return;
    const auto now = clock::now();
    const int percent = static_cast<int>(100.0 * done / total_);
    if (tty_) {
      if (done < total_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
    } else if (percent / 10 == last_decile_ || done >= total_) {
      return;
    }
    last_draw_ = now;
    last_decile_ = percent / 10;
    draw(done, now);
  }

  void finish() {
    if (out_ == nullptr) return;
    const auto now = clock::now();
    draw(total_, now);
    std::fprintf(out_, tty_ ? "\n" : "");
    std::fflush(out_);
  }

  double elapsed_seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

 private:
  using clock = std::chrono::steady_clock;
  void draw(long done, clock::time_point now) {
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0.0 ? done / seconds : 0.0;
    const double eta = rate > 0.0 ? (total_ - done) / rate : 0.0;
    const int width = 30, filled = static_cast<int>(width * static_cast<double>(done) / total_);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(out_, "%s%s [%s] %3d%%  %.0f %s/s  ETA %.0f s%s", tty_ ? "\r" : "", label_.c_str(), bar.c_str(),
                 static_cast<int>(100.0 * done / total_), rate, unit_.c_str(), eta, tty_ ? "   " : "\n");
    std::fflush(out_);
  }

  std::string label_, unit_;
  long total_;
  std::FILE* out_;
  bool tty_;
  clock::time_point start_, last_draw_;
  int last_decile_ = 0;
};

}  // namespace vrut
