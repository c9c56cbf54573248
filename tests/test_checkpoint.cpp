// Checkpoints: a rutting run stopped and resumed from its checkpoint ends
// exactly where the run never stopped ends; a checkpoint that is damaged, from
// another version or of another run is refused, saying which.
#include "pile3.hpp"
#include "rutting_checks.hpp"
#include "scratch.hpp"
#include "spaces.hpp"

#include <vrut/io/checkpoint.hpp>
#include <vrut/protocol/rutting.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>

#include <sys/resource.h>

namespace {

vrut::Specimen small_specimen(double width = 60.0) {
  vrut::SpecimenSettings s;
  s.placement.width = width;
  s.placement.height = 30.0;
  s.disk_radius = 1.0;
  s.seed = 3;
  return vrut::generate_specimen(s);
}

vrut::WheelTracking short_test() {
  vrut::WheelTracking wt;
  wt.minutes = 6.0;
  wt.ds_from_minute = 4.0;
  return wt;
}

// Few steps (the sanitizer build runs these too), and still a curve of 30 samples.
vrut::RuttingNumerics short_numerics() {
  vrut::RuttingNumerics n;
  n.shift = 1e5;
  n.settle_steps = 1000;
  n.samples = 30;
  return n;
}

// The short test on the small section, in Space, stopped when stop() says so
// and checkpointing to `checkpoints`.
template <class Space>
vrut::RuttingResult run_short(const std::function<bool()>& stop, vrut::CheckpointFile* checkpoints,
                              const vrut::RuttingMaterials& materials = {}) {
  return vrut::run_rutting<Space>(small_specimen(), short_test(), materials, short_numerics(), {}, {}, stop,
                                  checkpoints);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("a run stopped with a checkpoint and resumed ends bit for bit as the run never stopped",
                        "[checkpoint]", vrut_test::ExecutionSpaces) {
  // The run asks whether to stop once at each sample: counted, they tell a
  // resume (the samples after the checkpoint's) from a run started over.
  int asked_whole = 0;
  const auto whole = run_short<TestType>([&] { return ++asked_whole < 0; }, nullptr);

  const vrut_test::ScratchDir scratch("vrut-test-checkpoint");
  const auto path = scratch / "stopped.vrut";
  vrut::CheckpointFile first(path, 0.0, {{"run", "stopped at sample 7"}});
  int asked = 0;
  const auto part = run_short<TestType>([&] { return ++asked == 7; }, &first);
  REQUIRE(part.interrupted);
  REQUIRE(first.written() == 1);

  auto again = vrut::CheckpointFile::resume(path, 0.0);
  CHECK(again.header().at("run") == "stopped at sample 7");
  int asked_resumed = 0;
  const auto resumed = run_short<TestType>([&] { return ++asked_resumed < 0; }, &again);
  CHECK_FALSE(resumed.interrupted);
  CHECK(asked_whole > 7);
  CHECK(asked_resumed == asked_whole - 7);
  vrut_test::require_same(resumed, whole);
}

// The method's exact stones (no bodies) checkpoint what they did before
// rigid stones: stopped and resumed on the other backend, the run ends as
// the one never stopped.
TEST_CASE("a run with the method's exact stones resumes bit for bit", "[checkpoint]") {
  vrut::RuttingMaterials exact;
  exact.rigid_stones = false;
  const auto whole = run_short<Kokkos::DefaultHostExecutionSpace>({}, nullptr, exact);
  const vrut_test::ScratchDir scratch("vrut-test-checkpoint");
  const auto path = scratch / "exact.vrut";
  vrut::CheckpointFile first(path, 0.0, {});
  int asked = 0;
  const auto part = run_short<Kokkos::DefaultHostExecutionSpace>([&] { return ++asked == 11; }, &first, exact);
  REQUIRE(part.interrupted);
  auto again = vrut::CheckpointFile::resume(path, 0.0);
  const auto resumed = run_short<Kokkos::Serial>({}, &again, exact);
  vrut_test::require_same(resumed, whole);
  CHECK(whole.deformation_final > 0.1e-3);
}

TEST_CASE("checkpoints written by the clock resume, on another backend too", "[checkpoint]") {
  const vrut_test::ScratchDir scratch("vrut-test-checkpoint");
  const auto path = scratch / "clock.vrut";
  // Due at every sample but the last, or every one where the last falls a
  // step before the end: the file left holds the last sample before the end.
  vrut::CheckpointFile clock(path, 1e-9, {});
  const auto whole = run_short<Kokkos::DefaultHostExecutionSpace>({}, &clock);
  CHECK(clock.written() >= short_numerics().samples - 1);
  CHECK(clock.written() <= short_numerics().samples);
  CHECK_FALSE(std::filesystem::exists(path.string() + ".writing"));
  auto again = vrut::CheckpointFile::resume(path, 0.0);
  // Every sum runs in a fixed order, so the backends agree bit for bit.
  const auto resumed = run_short<Kokkos::Serial>({}, &again);
  vrut_test::require_same(resumed, whole);
}

TEST_CASE("a checkpoint that is damaged, from another version, of another run or time step is refused", "[checkpoint]") {
  const vrut_test::ScratchDir scratch("vrut-test-checkpoint");
  const auto path = scratch / "good.vrut";
  {
    vrut::CheckpointFile file(path, 0.0, {});
    int asked = 0;
    run_short<Kokkos::DefaultHostExecutionSpace>([&] { return ++asked == 3; }, &file);
  }
  std::ifstream in(path, std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto write = [](const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
  };

  const auto truncated = (scratch / "truncated.vrut");
  write(truncated, good.substr(0, good.size() / 2));
  CHECK_THROWS_WITH(vrut::read_checkpoint(truncated), Catch::Contains("is damaged"));

  const auto flipped = (scratch / "flipped.vrut");
  std::string bad = good;
  bad[bad.size() - 100] ^= 0x10;
  write(flipped, bad);
  CHECK_THROWS_WITH(vrut::read_checkpoint(flipped), Catch::Contains("checksum"));

  const auto other = (scratch / "other.txt");
  write(other, "gradation=2\n");
  CHECK_THROWS_WITH(vrut::read_checkpoint(other), Catch::Contains("not a vrut checkpoint"));
  CHECK_THROWS_WITH(vrut::read_checkpoint((scratch / "missing.vrut")), Catch::Contains("cannot open"));

  const auto old = (scratch / "old.vrut");
  const vrut::Checkpoint c = vrut::read_checkpoint(path);
  vrut::write_checkpoint(old, c.header, c.state, "0.0.9");
  CHECK_THROWS_WITH(vrut::read_checkpoint(old), Catch::Contains("written by vrut 0.0.9"));

  // Nor at another time step (as a build whose engine computes another one
  // would take it): the same steps would be another run.
  auto faster = vrut::CheckpointFile::resume(path, 0.0);
  vrut::RuttingNumerics other_step = short_numerics();
  other_step.timestep_safety *= 1.25;
  CHECK_THROWS_WITH(vrut::run_rutting<Kokkos::DefaultHostExecutionSpace>(small_specimen(), short_test(), {},
                                                                         other_step, {}, {}, {}, &faster),
                    Catch::Contains("written at a time step of"));

  // The checkpoint of a 60 mm section cannot go on as a 70 mm one.
  auto wrong = vrut::CheckpointFile::resume(path, 0.0);
  CHECK_THROWS_WITH(vrut::run_rutting<Kokkos::DefaultHostExecutionSpace>(small_specimen(70.0), short_test(), {},
                                                                         short_numerics(), {}, {}, {}, &wrong),
                    Catch::Contains("another run"));
}

// A disk that is full past `bytes` into a file, while it lives: this
// process's file-size limit (RLIMIT_FSIZE) lowered, with SIGXFSZ ignored, so
// that a write past it fails (EFBIG) as on a full disk instead of ending the
// process. Works where /dev/full does not exist. Nothing else may write a
// file meanwhile (Catch's own output to a log file included: no CHECK inside).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) : previous_signal_(std::signal(SIGXFSZ, SIG_IGN)) {
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit low = previous_;
    low.rlim_cur = previous_.rlim_max == RLIM_INFINITY ? bytes : std::min(bytes, previous_.rlim_max);
    lowered_ = setrlimit(RLIMIT_FSIZE, &low) == 0;
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_signal_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  bool lowered() const { return lowered_; }

 private:
  rlimit previous_{};
  void (*previous_signal_)(int);
  bool lowered_ = false;
};

// The write that fails goes aside to path.writing; the previous checkpoint
// stays, and nothing is left aside. A full disk stands in two ways: /dev/full
// (where there is one: a WARN says so where not) and a file-size limit
// (always), so that the test never passes without having filled a disk.
TEST_CASE("a checkpoint that cannot be written whole leaves the previous one", "[checkpoint]") {
  const vrut_test::ScratchDir scratch("vrut-test-checkpoint");
  const auto path = scratch / "full.vrut";
  const std::filesystem::path aside = path.string() + ".writing";
  const nlohmann::json state = {{"item", 1}};
  vrut::write_checkpoint(path, {{"which", "previous"}}, state);
  const auto refused_and_kept = [&](const std::string& message) {
    CHECK_THAT(message, Catch::Contains("could not write the checkpoint") && Catch::Contains("previous checkpoint"));
    CHECK(vrut::read_checkpoint(path).header.at("which") == "previous");
    CHECK_FALSE(std::filesystem::exists(std::filesystem::symlink_status(aside)));
  };
  SECTION("a disk full past 4 kB (a file-size limit)") {
    std::string message = "no error";
    {
      const FileSizeLimit full(4096);
      REQUIRE(full.lowered());
      try {
        vrut::write_checkpoint(path, {{"which", "next"}}, std::string(1 << 16, 'x'));
      } catch (const std::exception& e) {
        message = e.what();
      }
    }
    refused_and_kept(message);
  }
  SECTION("/dev/full") {
    if (!std::filesystem::exists("/dev/full")) {
      WARN("no /dev/full here: only the file-size limit stood for a full disk");
      return;
    }
    std::filesystem::remove(aside);
    std::filesystem::create_symlink("/dev/full", aside);
    std::string message = "no error";
    try {
      vrut::write_checkpoint(path, {{"which", "next"}}, std::string(1 << 16, 'x'));
    } catch (const std::exception& e) {
      message = e.what();
    }
    refused_and_kept(message);
  }
}

// The 3D engine's state goes through the same visit: a pile with a clump,
// stopped halfway, written, read into a new simulation built the same way
// and run on, ends bit for bit where the run never stopped ends (the
// clump's quaternion and angular momentum and the contacts' vector shear
// included).
TEMPLATE_LIST_TEST_CASE("a 3D run written and read back goes on bit for bit", "[checkpoint][engine3]",
                        vrut_test::ExecutionSpaces) {
  auto whole = vrut_test::make_pile<TestType>();
  const double dt = 0.2 * whole.critical_timestep();
  whole.run(1200, dt);
  auto first = vrut_test::make_pile<TestType>();
  first.run(600, dt);
  vrut::StateWriter writer;
  first.visit_state(writer);
  auto second = vrut_test::make_pile<TestType>();
  vrut::StateReader reader(writer.state(), "the first half");
  second.visit_state(reader);
  second.run(600, dt);
  CHECK(vrut_test::pile_motion(second) == vrut_test::pile_motion(whole));
  CHECK(vrut_test::pile_motion(second) != vrut_test::pile_motion(first));  // it did go on
}
