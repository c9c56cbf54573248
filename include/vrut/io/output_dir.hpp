#pragma once
// An output folder that appears whole or not at all: files are written into
// a staging folder beside it, which replaces the target on commit(). An
// existing, non-empty target is refused unless overwrite is set. Host-only.
#include <filesystem>
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
    fs::create_directories(parent);
    staging_ = parent / ("." + target_.filename().string() + ".partial");
    fs::remove_all(staging_);
    fs::create_directories(staging_);
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
