#pragma once
// Checkpoint files: a run's whole state, written aside and renamed into place,
// so that a checkpoint is always whole, and read back to go on bit for bit.
// Host-only; needs nlohmann_json.
//
// The file: one line "vrut checkpoint", then the byte count and the CRC-32 of
// the rest (8 and 4 bytes, little-endian), then one CBOR document:
//   {"format": 1, "vrut": version, "header": {...the caller's...}, "state": {item: ...}}.
// Each item is a value, a vector or a Kokkos view (extents and the elements in
// index order, so a GPU's layout reads back on a CPU). A state is written and
// read by one visit function that names its items in order (see
// Simulation::visit_state), called with a StateWriter or a StateReader.
#include <vrut/version.hpp>

#include <Kokkos_Core.hpp>
#include <boost/crc.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace vrut {

// The format's versions, each refusing the older files whose bytes it reads
// differently:
// 2: the loading's time step kept, and checked on resume.
// 3: each specimen's skeleton record (the films at the start,
// the early load path: protocol/rutting/skeleton_record.hpp).
// 4: a Choice's contact slot holds the state of the law that
// acts there only (contact/choice.hpp), so the contact state's bytes changed;
// a checkpoint of format 3 is refused by its format, not by its item sizes.
// 5: each sample holds the plate's speed (protocol/rutting/result.hpp).
inline constexpr int checkpoint_format = 5;
inline constexpr const char* checkpoint_magic = "vrut checkpoint\n";

// A checkpoint that cannot be used: not one, damaged, from another version,
// or of another run. Bad input, as a wrong option is.
class CheckpointError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace detail {
template <class T>
std::vector<std::uint8_t> bytes_of(const T* data, std::size_t count) {
  static_assert(std::is_trivially_copyable_v<T>, "checkpoint items must be trivially copyable");
  std::vector<std::uint8_t> b(sizeof(T) * count);
  if (count > 0) std::memcpy(b.data(), data, b.size());
  return b;
}
}  // namespace detail

class StateWriter {
 public:
  template <class T>
  void value(const std::string& name, const T& x) {
    state_[name] = item(detail::bytes_of(&x, 1), sizeof(T), {});
  }
  template <class T>
  void vector(const std::string& name, const std::vector<T>& v) {
    state_[name] = item(detail::bytes_of(v.data(), v.size()), sizeof(T), {v.size()});
  }
  template <class View>
  void view(const std::string& name, const View& v) {
    using T = typename View::non_const_value_type;
    static_assert(View::rank == 1 || View::rank == 2, "checkpoints hold views of rank 1 or 2");
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
    std::vector<T> flat;
    flat.reserve(v.size());
    std::vector<std::size_t> extents{v.extent(0)};
    if constexpr (View::rank == 1) {
      for (std::size_t i = 0; i < v.extent(0); ++i) flat.push_back(h(i));
    } else {
      extents.push_back(v.extent(1));
      for (std::size_t i = 0; i < v.extent(0); ++i)
        for (std::size_t k = 0; k < v.extent(1); ++k) flat.push_back(h(i, k));
    }
    state_[name] = item(detail::bytes_of(flat.data(), flat.size()), sizeof(T), extents);
  }
  const nlohmann::json& state() const { return state_; }

 private:
  static nlohmann::json item(std::vector<std::uint8_t> bytes, std::size_t size, std::vector<std::size_t> extents) {
    return {{"size", size}, {"extents", extents}, {"bytes", nlohmann::json::binary(std::move(bytes))}};
  }
  nlohmann::json state_ = nlohmann::json::object();
};

class StateReader {
 public:
  StateReader(nlohmann::json state, std::string source) : state_(std::move(state)), source_(std::move(source)) {}

  template <class T>
  void value(const std::string& name, T& x) {
    const auto& b = bytes(name, sizeof(T), 1);
    std::memcpy(&x, b.data(), sizeof(T));
  }
  template <class T>
  void vector(const std::string& name, std::vector<T>& v) {
    const std::size_t n = extents(name).at(0);
    const auto& b = bytes(name, sizeof(T), n);
    v.resize(n);
    if (n > 0) std::memcpy(static_cast<void*>(v.data()), b.data(), b.size());
  }
  // A view keeps its rows (disks, say): a checkpoint with other rows is of
  // another run. Its columns (contact slots) take the checkpoint's count.
  template <class View>
  void view(const std::string& name, View& v) {
    using T = typename View::non_const_value_type;
    static_assert(View::rank == 1 || View::rank == 2, "checkpoints hold views of rank 1 or 2");
    const std::vector<std::size_t> e = extents(name);
    if (e.size() != View::rank) fail("item '" + name + "' has the wrong rank");
    if (v.extent(0) > 0 && v.extent(0) != e[0])
      fail("item '" + name + "' has " + std::to_string(e[0]) + " rows where this run has " +
           std::to_string(v.extent(0)) + ": the checkpoint is of another run");
    const std::size_t columns = View::rank == 2 ? e[1] : 1;
    const auto& b = bytes(name, sizeof(T), e[0] * columns);
    std::vector<T> flat(e[0] * columns);
    if (!flat.empty()) std::memcpy(static_cast<void*>(flat.data()), b.data(), b.size());
    if constexpr (View::rank == 1) {
      if (v.extent(0) != e[0]) v = View(v.label(), e[0]);
      auto h = Kokkos::create_mirror_view(v);
      for (std::size_t i = 0; i < e[0]; ++i) h(i) = flat[i];
      Kokkos::deep_copy(v, h);
    } else {
      if (v.extent(0) != e[0] || v.extent(1) != e[1]) v = View(v.label(), e[0], e[1]);
      auto h = Kokkos::create_mirror_view(v);
      for (std::size_t i = 0; i < e[0]; ++i)
        for (std::size_t k = 0; k < e[1]; ++k) h(i, k) = flat[i * e[1] + k];
      Kokkos::deep_copy(v, h);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw CheckpointError(source_ + ": " + why); }
  const nlohmann::json& entry(const std::string& name) const {
    const auto it = state_.find(name);
    if (it == state_.end()) fail("no item '" + name + "' (written by another kind of run?)");
    return *it;
  }
  std::vector<std::size_t> extents(const std::string& name) const {
    return entry(name).at("extents").get<std::vector<std::size_t>>();
  }
  const std::vector<std::uint8_t>& bytes(const std::string& name, std::size_t size, std::size_t count) const {
    const auto& e = entry(name);
    if (e.at("size").get<std::size_t>() != size)
      fail("item '" + name + "' has elements of " + std::to_string(e.at("size").get<std::size_t>()) +
           " bytes where this build has " + std::to_string(size));
    const auto& b = e.at("bytes").get_binary();
    if (b.size() != size * count) fail("item '" + name + "' has the wrong length");
    return b;
  }
  nlohmann::json state_;
  std::string source_;
};

// Writes header and state to path: aside first, then renamed over the old
// file, so a crash or a full disk leaves the previous checkpoint whole.
// (written_by: the version it claims, another only in tests of the refusal.)
inline void write_checkpoint(const std::filesystem::path& path, const nlohmann::json& header,
                             const nlohmann::json& state, const std::string& written_by = version) {
  const nlohmann::json doc = {{"format", checkpoint_format}, {"vrut", written_by}, {"header", header}, {"state", state}};
  const std::vector<std::uint8_t> body = nlohmann::json::to_cbor(doc);
  boost::crc_32_type crc;
  crc.process_bytes(body.data(), body.size());
  std::uint8_t frame[12];
  const std::uint64_t n = body.size();
  const std::uint32_t sum = crc.checksum();
  for (int b = 0; b < 8; ++b) frame[b] = static_cast<std::uint8_t>(n >> (8 * b));
  for (int b = 0; b < 4; ++b) frame[8 + b] = static_cast<std::uint8_t>(sum >> (8 * b));
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path aside = path.string() + ".writing";
  {
    std::ofstream out(aside, std::ios::binary | std::ios::trunc);
    out.write(checkpoint_magic, static_cast<std::streamsize>(std::strlen(checkpoint_magic)));
    out.write(reinterpret_cast<const char*>(frame), sizeof frame);
    out.write(reinterpret_cast<const char*>(body.data()), static_cast<std::streamsize>(body.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(aside, ignored);
      throw std::runtime_error("could not write the checkpoint " + aside.string() +
                               " (disk full or not writable?); the previous checkpoint, if any, is kept");
    }
  }
  std::filesystem::rename(aside, path);
}

struct Checkpoint {
  nlohmann::json header, state;
};

// Reads a checkpoint; a file that is not one, is damaged, or comes from
// another version of vrut is refused with a CheckpointError that says which.
inline Checkpoint read_checkpoint(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError("cannot open the checkpoint " + name);
  const std::size_t magic = std::strlen(checkpoint_magic);
  std::string head(magic, '\0');
  std::uint8_t frame[12] = {};
  if (!in.read(head.data(), static_cast<std::streamsize>(magic)) || head != checkpoint_magic)
    throw CheckpointError(name + " is not a vrut checkpoint");
  if (!in.read(reinterpret_cast<char*>(frame), sizeof frame))
    throw CheckpointError(name + " is damaged: it ends early");
  std::uint64_t n = 0;
  std::uint32_t sum = 0;
  for (int b = 0; b < 8; ++b) n |= static_cast<std::uint64_t>(frame[b]) << (8 * b);
  for (int b = 0; b < 4; ++b) sum |= static_cast<std::uint32_t>(frame[8 + b]) << (8 * b);
  const std::uintmax_t file_size = std::filesystem::file_size(path);
  if (n != file_size - magic - sizeof frame)
    throw CheckpointError(name + " is damaged: it is " + std::to_string(file_size) + " bytes long, not " +
                          std::to_string(n + magic + sizeof frame));
  std::vector<std::uint8_t> body(n);
  in.read(reinterpret_cast<char*>(body.data()), static_cast<std::streamsize>(n));
  boost::crc_32_type crc;
  crc.process_bytes(body.data(), body.size());
  if (!in || crc.checksum() != sum) throw CheckpointError(name + " is damaged: its checksum does not match");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::from_cbor(body);
  } catch (const nlohmann::json::exception& e) {
    throw CheckpointError(name + " is damaged: " + e.what());
  }
  const std::string written_by = doc.value("vrut", std::string("?"));
  const int format = doc.value("format", 0);
  if (format != checkpoint_format || written_by != version)
    throw CheckpointError(name + " was written by vrut " + written_by + " in checkpoint format " +
                          std::to_string(format) + "; this is vrut " + version + ", format " +
                          std::to_string(checkpoint_format) +
                          ", which resumes only its own checkpoints (run the test again from the start)");
  return {doc.at("header"), doc.at("state")};
}

// A protocol's checkpoints in one file: due() every `every_seconds` of wall
// time (0: never by the clock), save() writes, load() reads the file given
// to resume().
class CheckpointFile {
 public:
  CheckpointFile(std::filesystem::path path, double every_seconds, nlohmann::json header)
      : path_(std::move(path)), every_(every_seconds), header_(std::move(header)), last_(clock::now()) {}
  static CheckpointFile resume(const std::filesystem::path& path, double every_seconds) {
    Checkpoint c = read_checkpoint(path);
    CheckpointFile f(path, every_seconds, c.header);
    f.resume_state_ = std::move(c.state);
    f.resuming_ = true;
    return f;
  }

  void set_interval(double every_seconds) { every_ = every_seconds; }
  bool resuming() const { return resuming_; }
  const nlohmann::json& header() const { return header_; }
  // A part of the header known only once the run has begun (a 3D run's
  // stones, placed after the file was named); every later save carries it.
  void add_to_header(const std::string& key, nlohmann::json value) { header_[key] = std::move(value); }
  const std::filesystem::path& path() const { return path_; }
  int written() const { return written_; }
  bool due() const {
    return every_ > 0.0 && std::chrono::duration<double>(clock::now() - last_).count() >= every_;
  }
  template <class Visit>
  void save(Visit&& visit) {
    StateWriter w;
    visit(w);
    write_checkpoint(path_, header_, w.state());
    last_ = clock::now();
    ++written_;
  }
  template <class Visit>
  void load(Visit&& visit) {
    StateReader r(std::move(resume_state_), path_.string());
    visit(r);
    resuming_ = false;
  }

 private:
  using clock = std::chrono::steady_clock;
  std::filesystem::path path_;
  double every_ = 0.0;
  nlohmann::json header_, resume_state_;
  clock::time_point last_;
  bool resuming_ = false;
  int written_ = 0;
};

}  // namespace vrut
