#pragma once
// A terminal progress bar for long runs: percent, rate, ETA. On a terminal it
// redraws one line; otherwise (logs, CI) it prints a line every 10 %. The
// rate counts from the first report, so a run resumed half way (or one that
// settles before its first report) shows the pace it goes at now, not half
// the run done in its first seconds. Host-only.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include <unistd.h>

namespace vrut {

// What the bar's rate counts, as a person reads it: `name` a second, each
// count reported being `per_count` of them. A rutting run reports permille
// of its test; {"test min", 60.0 / 1000} turns that into minutes of the test
// a second ("0.25 test min/s"), where "permille/s" said nothing one knows.
struct RateUnit {
  std::string name = "steps";
  double per_count = 1.0;
  RateUnit() = default;
  RateUnit(std::string unit_name, double amount_per_count = 1.0)
      : name(std::move(unit_name)), per_count(amount_per_count) {}
  RateUnit(const char* unit_name, double amount_per_count = 1.0) : RateUnit(std::string(unit_name), amount_per_count) {}
};

class ProgressBar {
 public:
  using clock = std::chrono::steady_clock;

  // out == nullptr: a silent bar (the other ranks of an MPI run, say).
  ProgressBar(std::string label, long total, RateUnit unit = {}, std::FILE* out = stderr)
      : label_(std::move(label)), unit_(std::move(unit)), total_(total > 0 ? total : 1), out_(out),
        tty_(out != nullptr && isatty(fileno(out)) != 0), start_(clock::now()), last_draw_(start_) {}

  void update(long done) { update(done, clock::now()); }
  // As update(done), at the time `now` (tests give their own).
  void update(long done, clock::time_point now) {
    if (out_ == nullptr) return;
    const int percent = static_cast<int>(100.0 * done / total_);
    if (first_done_ < 0) first_done_ = done, first_report_ = now;
    if (tty_) {
      if (done < total_ && now - last_draw_ < std::chrono::milliseconds(200)) return;
    } else if (percent / 10 == last_decile_ || done >= total_) {
      return;
    }
    last_draw_ = now;
    last_decile_ = percent / 10;
    draw(done, now);
  }

  void finish() { finish(clock::now()); }
  // As finish(), at the time `now` (tests give their own).
  void finish(clock::time_point now) {
    if (out_ == nullptr) return;
    if (first_done_ < 0) first_done_ = 0, first_report_ = start_;
    draw(total_, now);
    std::fprintf(out_, tty_ ? "\n" : "");
    std::fflush(out_);
  }

  double elapsed_seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

  // A rate with the digits it needs: 8823, 41.5, 0.24 (a long run's
  // minutes of the test a second would otherwise read 0).
  static std::string rate_text(double rate) {
    char text[40];
    std::snprintf(text, sizeof text, rate >= 100.0 ? "%.0f" : rate >= 1.0 ? "%.1f" : "%.2g", rate);
    return text;
  }
  // A time left as a person reads it: 45 s, 12 min, 2 h 05 min.
  static std::string duration_text(double seconds) {
    char text[40];
    if (seconds < 120.0)
      std::snprintf(text, sizeof text, "%.0f s", seconds);
    else if (seconds < 7200.0)
      std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
    else
      std::snprintf(text, sizeof text, "%.0f h %02.0f min", std::floor(seconds / 3600.0),
                    std::floor(std::fmod(seconds, 3600.0) / 60.0));
    return text;
  }

 private:
  void draw(long done, clock::time_point now) {
    const double seconds = std::chrono::duration<double>(now - first_report_).count();
    // Else no rate yet: "-". Over less than a twentieth of a second the clock's
    // resolution and the first report's own cost are the rate (a short
    // settling read "2777777778 steps/s").
    const bool measured = seconds >= least_seconds && done > first_done_;
    const double rate = measured ? (done - first_done_) / seconds : 0.0;  // counts a second
    const std::string eta = done >= total_ ? "0 s" : measured ? duration_text((total_ - done) / rate) : "-";
    const int width = 30, filled = static_cast<int>(width * static_cast<double>(done) / total_);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(out_, "%s%s [%s] %3d%%  %s %s/s  ETA %s%s", tty_ ? "\r" : "", label_.c_str(), bar.c_str(),
                 static_cast<int>(100.0 * done / total_), measured ? rate_text(rate * unit_.per_count).c_str() : "-",
                 unit_.name.c_str(), eta.c_str(), tty_ ? "   " : "\n");
    std::fflush(out_);
  }

  static constexpr double least_seconds = 0.05;
  std::string label_;
  RateUnit unit_;
  long total_;
  std::FILE* out_;
  bool tty_;
  clock::time_point start_, last_draw_, first_report_;
  long first_done_ = -1;  // at the first report
  int last_decile_ = 0;
};

}  // namespace vrut
