// The progress bar's numbers as a person reads them (io/progress.hpp): a
// slow run's rate keeps its digits, a long wait reads in minutes and hours.
#include <vrut/io/progress.hpp>

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

TEST_CASE("the progress bar writes a slow rate with its digits and a long ETA in minutes and hours",
          "[progress][unit]") {
  using vrut::ProgressBar;
  // A five-specimen 3D run advances about a hundredth of a test minute a second.
  CHECK(ProgressBar::rate_text(0.2417) == "0.24");
  CHECK(ProgressBar::rate_text(0.0152) == "0.015");
  CHECK(ProgressBar::rate_text(0.0) == "0");
  CHECK(ProgressBar::rate_text(41.53) == "41.5");
  CHECK(ProgressBar::rate_text(8823.4) == "8823");
  CHECK(ProgressBar::duration_text(45.2) == "45 s");
  CHECK(ProgressBar::duration_text(3277.0) == "55 min");    // 54.6 min
  CHECK(ProgressBar::duration_text(7500.0) == "2 h 05 min");  // 2 h 5 min 0 s
  CHECK(ProgressBar::duration_text(9017.0) == "2 h 30 min");  // 2 h 30 min 17 s
  // Written to a file, a bar prints a line every 10 %, with both, its rate
  // in the unit a person reads (a rutting run: minutes of the test).
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  {
    ProgressBar bar("loading", 1000, {"test min", 60.0 / 1000}, f);
    bar.update(150);
  }
  std::rewind(f);
  char line[200] = {};
  REQUIRE(std::fgets(line, sizeof line, f) != nullptr);
  std::fclose(f);
  const std::string text = line;
  CHECK(text.rfind("loading [####", 0) == 0);
  CHECK(text.find(" 15%") != std::string::npos);
  CHECK(text.find(" test min/s  ETA ") != std::string::npos);
}

// A run resumed at 49 % (its first report) that then does 10 permille in
// 10 s goes at 1 permille a second, of a 60-minute test 0.06 test minutes a
// second: 500 permille left is 500 s, "8 min". A rate from the bar's start
// would count the 490 permille done before the resume as done in no time
// (the ETA of "15 s" a resumed 45-minute run showed).
TEST_CASE("a resumed run's rate and ETA count from its first report", "[progress][unit]") {
  using vrut::ProgressBar;
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  {
    ProgressBar bar("loading", 1000, {"test min", 60.0 / 1000}, f);
    const auto t0 = ProgressBar::clock::now() + std::chrono::seconds(5);
    bar.update(490, t0);  // the first report: no rate yet
    bar.update(500, t0 + std::chrono::seconds(10));
  }
  std::rewind(f);
  char first[200] = {}, second[200] = {};
  REQUIRE(std::fgets(first, sizeof first, f) != nullptr);
  REQUIRE(std::fgets(second, sizeof second, f) != nullptr);
  std::fclose(f);
  CHECK(std::string(first).find(" 49%  - test min/s  ETA -") != std::string::npos);
  CHECK(std::string(second).find(" 50%  0.06 test min/s  ETA 8 min") != std::string::npos);
}

// Steps, the default unit, count one a report.
TEST_CASE("a bar in steps gives steps a second", "[progress][unit]") {
  using vrut::ProgressBar;
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  {
    ProgressBar bar("compressing", 5000, {}, f);
    const auto t0 = ProgressBar::clock::now();
    bar.update(0, t0);
    bar.update(1000, t0 + std::chrono::seconds(4));
  }
  std::rewind(f);
  char line[200] = {};
  REQUIRE(std::fgets(line, sizeof line, f) != nullptr);
  std::fclose(f);
  CHECK(std::string(line).find(" 20%  250 steps/s  ETA 16 s") != std::string::npos);
}

// A short settling (300 steps done between two reports a microsecond apart)
// has no rate a person can use: the bar says "-", not the billions of steps
// a second that the clock's resolution gives; over a second it says 300.
TEST_CASE("a rate over less than a twentieth of a second is not shown", "[progress][unit]") {
  using vrut::ProgressBar;
  for (const auto& [span, rate] : {std::pair<std::chrono::microseconds, std::string>{std::chrono::microseconds(1), "-"},
                                   {std::chrono::microseconds(49'000), "-"},
                                   {std::chrono::microseconds(1'000'000), "300"}}) {
    std::FILE* f = std::tmpfile();
    REQUIRE(f != nullptr);
    {
      ProgressBar bar("settling", 300, "steps", f);
      const auto t0 = ProgressBar::clock::now();
      bar.update(0, t0);
      bar.finish(t0 + span);
    }
    std::rewind(f);
    char line[200] = {};
    REQUIRE(std::fgets(line, sizeof line, f) != nullptr);
    std::fclose(f);
    INFO(line);
    CHECK(std::string(line).find("100%  " + rate + " steps/s  ETA 0 s") != std::string::npos);
  }
}
