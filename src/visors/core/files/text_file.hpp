#pragma once
// A whole text file read into a string (scenario and settings files). Ground side
// (visors_core_files).

#include <filesystem>
#include <optional>
#include <string>

namespace visors::core::files {

/// The file's contents; nullopt when it cannot be opened (the caller names the error).
std::optional<std::string> read_text_file(const std::filesystem::path& path);

}  // namespace visors::core::files
