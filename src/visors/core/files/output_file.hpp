#pragma once
// A C stdio file opened for writing and closed when it goes out of scope: the simulator's and the
// file writers' large numeric outputs (fprintf formats several times faster than iostreams).
// Ground side (visors_core_files).

#include <cstdio>
#include <filesystem>
#include <memory>

namespace visors::core::files {

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f != nullptr) std::fclose(f);
  }
};

using OutputFile = std::unique_ptr<std::FILE, FileCloser>;

/// `path` opened for writing (truncated); empty when it cannot be (the caller names the error).
inline OutputFile open_output_file(const std::filesystem::path& path) { return OutputFile(std::fopen(path.c_str(), "w")); }

}  // namespace visors::core::files
