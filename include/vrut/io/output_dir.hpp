#pragma once
// An output folder that appears whole or not at all: files are written into
// a staging folder beside it, which replaces the target on commit(). An
// existing, non-empty target is refused unless overwrite is set. Host-only.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace vrut {

class OutputDir {
 public:
  OutputDir(std::filesystem::path target, bool overwrite) : target_(std::move(target)) {
    namespace fs = std::filesystem;
    if (target_.empty()) throw std::invalid_argument("the output folder name is empty");
    if (fs::exists(target_) && !fs::is_directory(target_))
      throw std::invalid_argument("output path '" + target_.string() + "' exists and is not a folder");
    if (fs::exists(target_) && !fs::is_empty(target_) && !overwrite)
      throw std::invalid_argument("output folder '" + target_.string() +
                                  "' exists and is not empty (use --force to overwrite)");
    const fs::path parent = fs::absolute(target_).parent_path();
    staging_ = parent / ("." + target_.filename().string() + ".partial");
    // An unwritable place is found now, before any work, not after the run.
    try {
      fs::create_directories(parent);
      fs::remove_all(staging_);
      fs::create_directories(staging_);
      std::ofstream probe(staging_ / ".probe");
      probe << "vrut";
      probe.close();
      if (!probe) throw fs::filesystem_error("cannot write a file", staging_, std::make_error_code(std::errc::io_error));
      fs::remove(staging_ / ".probe");
    } catch (const fs::filesystem_error& e) {
      throw std::runtime_error("cannot write the output folder '" + target_.string() + "' (in " + parent.string() +
                               "): " + e.code().message());
    }
  }
  // Refuses to start a run whose results (about `bytes`) would not fit on
  // the disk: better now than a full disk after hours of work.
  void require_space(std::uintmax_t bytes) const {
    const std::uintmax_t free = std::filesystem::space(staging_).available;
    if (free < bytes)
      throw std::runtime_error("the disk of '" + target_.string() + "' has " + std::to_string(free >> 20) +
                               " MB free, and this run needs about " + std::to_string((bytes >> 20) + 1) +
                               " MB: free some space or choose another --out");
  }
  // Writes a whole text file, or throws saying why it could not (a full disk).
  void write_text(const std::string& name, const std::string& text) const {
    std::ofstream out(file(name), std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("could not write " + file(name).string() + " (disk full?)");
  }
  ~OutputDir() {
    std::error_code ignored;
    if (!committed_) std::filesystem::remove_all(staging_, ignored);
  }
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;

  // Where to write a file now.
  std::filesystem::path file(const std::string& name) const { return staging_ / name; }
  const std::filesystem::path& target() const { return target_; }

  void commit() {
    namespace fs = std::filesystem;
    fs::remove_all(target_);
    fs::rename(staging_, target_);
    committed_ = true;
  }

 private:
  std::filesystem::path target_, staging_;
  bool committed_ = false;
};

}  // namespace vrut
