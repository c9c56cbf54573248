#pragma once
// An ensemble shared among MPI ranks (mpirun -np K): each rank runs a block
// of the seeds side by side, and rank 0 gathers every specimen's result to
// write one summary. Each specimen's result does not depend on which others
// run beside it, so K ranks give the results of one process, bit for bit.
// Built without MPI (VRUT_WITH_MPI unset) there is one rank and nothing to share.
#include <vrut/io/output_dir.hpp>
#include <vrut/protocol/rutting.hpp>

#include <nlohmann/json.hpp>

#ifdef VRUT_WITH_MPI
#include <mpi.h>
#endif

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vrut::app::ranks {

// Whether an MPI launcher started this process: mpirun and mpiexec of Open
// MPI, of MPICH and its kin (Intel MPI, MVAPICH), and srun under PMI or PMIx
// each set one of these. Without one, MPI_Init would start a singleton
// runtime (Open MPI forks its daemon) that costs about 0.4 s for one rank and
// nothing to share: long enough to slow every `--help` and refused input.
// VRUT_MPI=1 says "launched" for a launcher that sets none of them.
template <class Lookup = char* (*)(const char*)>
bool launched_by_mpi(Lookup environment = &std::getenv) {
  if (const char* forced = environment("VRUT_MPI"); forced != nullptr && std::strcmp(forced, "1") == 0) return true;
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MV2_COMM_WORLD_SIZE"})
    if (const char* value = environment(name); value != nullptr && *value != '\0') return true;
  return false;
}

// MPI for the life of main(), started only under an MPI launcher; one rank
// when vrut was built without MPI or run without a launcher.
class Session {
 public:
  Session(int& argc, char**& argv) {
#ifdef VRUT_WITH_MPI
    if (launched_by_mpi()) {
      MPI_Init(&argc, &argv);
      mpi_ = true;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
      MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
#else
    (void)argc, (void)argv;
#endif
  }
  ~Session() {
#ifdef VRUT_WITH_MPI
    if (mpi_) MPI_Finalize();
#endif
  }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  // A rank that fails takes the others down with it, rather than leave them
  // waiting for its results.
  [[noreturn]] void abort(int code) const {
#ifdef VRUT_WITH_MPI
    if (mpi_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::exit(code);
  }
  // True on every rank when it is true on any (all must call it together).
  bool any(bool mine) const {
#ifdef VRUT_WITH_MPI
    if (size_ > 1) {
      int local = mine ? 1 : 0, global = 0;
      MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
      return global != 0;
    }
#endif
    return mine;
  }
  // Rank 0 gets every rank's bytes, in rank order; the others get nothing.
  std::vector<std::vector<std::uint8_t>> gather(const std::vector<std::uint8_t>& mine) const {
    if (size_ == 1) return {mine};
#ifdef VRUT_WITH_MPI
    int count = static_cast<int>(mine.size());
    std::vector<int> counts(size_), offsets(size_);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size_; ++r) offsets[r] = total, total += counts[r];
    std::vector<std::uint8_t> all(root() ? total : 0);
    MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
    std::vector<std::vector<std::uint8_t>> parts;
    if (root())
      for (int r = 0; r < size_; ++r) parts.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
    return parts;
#else
    return {mine};
#endif
  }

 private:
  int rank_ = 0, size_ = 1;
#ifdef VRUT_WITH_MPI
  bool mpi_ = false;  // MPI_Init was called
#endif
};

// This rank's block of n items: [first, second). Blocks keep the seeds in
// order, so gathering in rank order gives the seeds' order back.
inline std::pair<std::size_t, std::size_t> block(std::size_t n, int rank, int size) {
  const std::size_t base = n / size, extra = n % size, r = static_cast<std::size_t>(rank);
  const std::size_t first = r * base + (r < extra ? r : extra);
  return {first, first + base + (r < extra ? 1 : 0)};
}

// This rank's seeds, its block of the ensemble's; refused where there are
// fewer seeds than ranks (a rank would have nothing to run).
inline std::vector<std::uint64_t> seeds_of_rank(const std::vector<std::uint64_t>& seeds, const Session& session) {
  if (seeds.size() < static_cast<std::size_t>(session.size()))
    throw std::invalid_argument(std::to_string(session.size()) + " MPI ranks for " + std::to_string(seeds.size()) +
                                " seed(s): give at least one seed per rank (--seeds)");
  const auto [first, last] = block(seeds.size(), session.rank(), session.size());
  return {seeds.begin() + static_cast<std::ptrdiff_t>(first), seeds.begin() + static_cast<std::ptrdiff_t>(last)};
}

// Each rank checkpoints its own specimens, and resumes them with as many ranks.
inline std::string checkpoint_name(int rank, int size) {
  return size == 1 ? "checkpoint.vrut"
                   : "checkpoint-rank-" + std::to_string(rank) + "-of-" + std::to_string(size) + ".vrut";
}

// How many ranks wrote the checkpoints in `folder`: 1 for checkpoint.vrut,
// K for checkpoint-rank-0-of-K.vrut; 0 where it holds neither.
inline int checkpoint_ranks_in(const std::filesystem::path& folder) {
  std::error_code ignored;
  if (std::filesystem::exists(folder / checkpoint_name(0, 1), ignored)) return 1;
  const std::string prefix = "checkpoint-rank-0-of-", suffix = ".vrut";
  for (const auto& entry : std::filesystem::directory_iterator(folder, ignored)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > prefix.size() + suffix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
      if (digits.find_first_not_of("0123456789") == std::string::npos && digits.size() < 6) return std::stoi(digits);
    }
  }
  return 0;
}

// A stopped run's checkpoints, every rank's, go into its output folder's
// staging copy beside the partial results (rank 0 calls this once every rank
// has written its own: the gather that precedes it waits for them all), so
// that the folder which replaces the old one holds what a resume needs.
inline void keep_checkpoints(const std::filesystem::path& out, const vrut::OutputDir& output, int size) {
  for (int r = 0; r < size; ++r) {
    const std::string name = checkpoint_name(r, size);
    std::filesystem::rename(out / name, output.file(name));
  }
}

// How to go on with a stopped run: the command, with the launcher that ran
// its ranks (a resume needs as many).
inline std::string resume_command(int size, const std::string& out) {
  return (size > 1 ? "mpirun -np " + std::to_string(size) + " " : std::string()) + "vrut-rutting --resume " + out;
}

// What rank 0 needs of a specimen run elsewhere: its result less the
// per-disk fields (pictures are of the first specimen, which rank 0 runs),
// two facts of the specimen for seeds.csv, and the rank that ran it.
struct SpecimenFacts {
  std::size_t aggregates = 0;
  double aggregate_area_fraction = 0.0;
  int rank = 0;
};

inline nlohmann::json to_json(const vrut::RuttingResult& r, const SpecimenFacts& f) {
  std::vector<std::uint8_t> samples(r.samples.size() * sizeof(vrut::RuttingSample));
  if (!samples.empty()) std::memcpy(samples.data(), r.samples.data(), samples.size());
  // The skeleton record is plain numbers (protocol/rutting/skeleton_record.hpp): its bytes travel as they are.
  static_assert(std::is_trivially_copyable_v<vrut::SkeletonRecord>);
  std::vector<std::uint8_t> skeleton(sizeof(vrut::SkeletonRecord));
  std::memcpy(skeleton.data(), &r.skeleton, skeleton.size());
  return {{"samples", nlohmann::json::binary(std::move(samples))},
          {"skeleton", nlohmann::json::binary(std::move(skeleton))},
          {"deformation_at_ds_start", r.deformation_at_ds_start},
          {"deformation_final", r.deformation_final},
          {"dynamic_stability", r.dynamic_stability},  // CBOR keeps infinity and NaN
          {"dynamic_stability_is_lower_bound", r.dynamic_stability_is_lower_bound},
          {"deformation_resolution", r.deformation_resolution},
          {"plate", {r.plate_x0, r.plate_x1, r.plate_y_final}}, {"plate_mass", r.plate_mass},
          {"particles", r.particles}, {"contacts", r.contacts}, {"bonds", r.bonds},
          {"stones", r.stones}, {"stone_pairs_touching", r.stone_pairs_touching},
          {"interrupted", r.interrupted}, {"steps", r.steps}, {"dt", r.dt}, {"wall_seconds", r.wall_seconds},
          {"aggregates", f.aggregates}, {"aggregate_area_fraction", f.aggregate_area_fraction}, {"rank", f.rank}};
}

inline std::pair<vrut::RuttingResult, SpecimenFacts> from_json(const nlohmann::json& j) {
  vrut::RuttingResult r;
  const auto& bytes = j.at("samples").get_binary();
  r.samples.resize(bytes.size() / sizeof(vrut::RuttingSample));
  if (!bytes.empty()) std::memcpy(static_cast<void*>(r.samples.data()), bytes.data(), bytes.size());
  const auto& skeleton = j.at("skeleton").get_binary();
  if (skeleton.size() != sizeof(vrut::SkeletonRecord)) throw std::runtime_error("a rank sent a skeleton record of another size");
  std::memcpy(static_cast<void*>(&r.skeleton), skeleton.data(), skeleton.size());
  r.deformation_at_ds_start = j.at("deformation_at_ds_start");
  r.deformation_final = j.at("deformation_final");
  r.dynamic_stability = j.at("dynamic_stability");
  r.dynamic_stability_is_lower_bound = j.at("dynamic_stability_is_lower_bound");
  r.deformation_resolution = j.at("deformation_resolution");
  r.plate_x0 = j.at("plate")[0], r.plate_x1 = j.at("plate")[1], r.plate_y_final = j.at("plate")[2];
  r.plate_mass = j.at("plate_mass");
  r.particles = j.at("particles"), r.contacts = j.at("contacts"), r.bonds = j.at("bonds");
  r.stones = j.at("stones"), r.stone_pairs_touching = j.at("stone_pairs_touching");
  r.interrupted = j.at("interrupted"), r.steps = j.at("steps"), r.dt = j.at("dt"), r.wall_seconds = j.at("wall_seconds");
  return {r, {j.at("aggregates"), j.at("aggregate_area_fraction"), j.at("rank")}};
}

// Rank 0 gathers every rank's results and facts into runs and facts, in the
// seeds' order (each rank holds a block of them); every rank must call it.
// Returns false on the other ranks, which have nothing more to write.
inline bool gather_on_root(const Session& session, std::vector<vrut::RuttingResult>& runs,
                           std::vector<SpecimenFacts>& facts) {
  if (session.size() == 1) return true;
  nlohmann::json mine = nlohmann::json::array();
  for (std::size_t e = 0; e < runs.size(); ++e) mine.push_back(to_json(runs[e], facts[e]));
  const auto parts = session.gather(nlohmann::json::to_cbor(mine));
  if (!session.root()) return false;
  std::vector<vrut::RuttingResult> all;
  facts.clear();
  for (const auto& part : parts)
    for (const auto& j : nlohmann::json::from_cbor(part)) {
      auto [r, f] = from_json(j);
      all.push_back(std::move(r));
      facts.push_back(f);
    }
  all.front() = std::move(runs.front());  // with what only rank 0 has: the snapshots and velocities, for the pictures
  runs = std::move(all);
  return true;
}

}  // namespace vrut::app::ranks
