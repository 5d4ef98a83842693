#pragma once
// A file with the given text in the system's temporary folder, removed when it goes out of scope
// (for reader tests on malformed input).

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace visors::test {

class TempFile {
 public:
  TempFile(const std::string& text, const std::string& extension)
      : path_(std::filesystem::temp_directory_path() /
              ("visors_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++) + extension)) {
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  static inline std::atomic<int> counter_{0};
  std::filesystem::path path_;
};

/// An empty folder in the system's temporary folder, removed with its content when it goes out
/// of scope (for commands that write an output directory).
class TempDir {
 public:
  TempDir()
      : path_(std::filesystem::temp_directory_path() /
              ("visors_test_dir_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++))) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  static inline std::atomic<int> counter_{0};
  std::filesystem::path path_;
};

}  // namespace visors::test
