#pragma once
// An ensemble's 3D specimens, several at a time on host threads. Each
// specimen is placed by one thread from its own seed's streams, so it is the
// specimen generate_specimen3 makes for that seed, whatever the number of
// threads. A compacted 3# specimen takes about 18 minutes on one thread:
// five of them on two threads take three rounds instead of five. Threads
// left over (more workers than seeds) go to each specimen's compaction,
// which gives the same packing on any count. Host-only.
#include <vrut/specimen/specimen3.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace vrut {

// A specimen that could not be made (its stones' volume fraction not
// reached), and the seed whose it was.
class SpecimenSeedError : public std::runtime_error {
 public:
  SpecimenSeedError(std::uint64_t seed, const std::string& why)
      : std::runtime_error("seed " + std::to_string(seed) + ": " + why), seed_(seed) {}
  std::uint64_t seed() const { return seed_; }

 private:
  std::uint64_t seed_;
};

// The specimens of settings s with each of seeds, `workers` at a time (at
// least one). started(i) and done(i) are called as the specimen of seeds[i]
// begins and ends, and compacting(i) where its random addition jammed and a
// compaction follows; one call at a time, from the worker threads. Once a
// specimen fails no other starts; when the running ones have ended, the
// failure of the first such seed in the list is thrown, a SpecimenSeedError
// for a runtime_error, any other exception as it was.
inline std::vector<Specimen3> generate_specimens3(SpecimenSettings3 s, const std::vector<std::uint64_t>& seeds,
                                                  int workers, const std::function<void(std::size_t)>& started = {},
                                                  const std::function<void(std::size_t)>& done = {},
                                                  const std::function<void(std::size_t)>& compacting = {}) {
  std::vector<Specimen3> out(seeds.size());
  std::vector<std::exception_ptr> failures(seeds.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex calls;
  auto call = [&](const std::function<void(std::size_t)>& f, std::size_t i) {
    if (!f) return;
    std::lock_guard<std::mutex> lock(calls);
    f(i);
  };
  const int threads = std::max(1, std::min<int>(workers, static_cast<int>(seeds.size())));
  auto work = [&] {
    for (std::size_t i = next++; i < seeds.size() && !failed; i = next++) {
      SpecimenSettings3 mine = s;
      mine.seed = seeds[i];
      mine.compaction.threads = std::max(1, workers / threads);  // the threads left over, where there are
      call(started, i);
      std::size_t last_placed = 0;
      bool placing = false;
      try {
        out[i] = generate_specimen3(mine, [&](std::size_t placed, std::size_t) {
          if (placing && placed <= last_placed) call(compacting, i);  // a second placement: the loose one
          placing = true;
          last_placed = placed;
        });
      } catch (const std::runtime_error& e) {
        failures[i] = std::make_exception_ptr(SpecimenSeedError(seeds[i], e.what()));
        failed = true;
        continue;
      } catch (...) {
        failures[i] = std::current_exception();
        failed = true;
        continue;
      }
      call(done, i);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  for (const auto& f : failures)
    if (f) std::rethrow_exception(f);
  return out;
}

}  // namespace vrut
