#include "visors/core/files/data_path.hpp"

#include <cstdlib>
#include <sstream>

#ifndef VISORS_REPOSITORY_DATA_DIR
#define VISORS_REPOSITORY_DATA_DIR ""
#endif
#ifndef VISORS_INSTALLED_DATA_DIR
#define VISORS_INSTALLED_DATA_DIR ""
#endif

namespace visors::core::files {

std::vector<std::filesystem::path> data_search_path() {
  std::vector<std::filesystem::path> folders;
  if (const char* env = std::getenv("VISORS_DATA_PATH"); env != nullptr) {
    std::stringstream entries(env);
    std::string entry;
    while (std::getline(entries, entry, ':')) {
      if (!entry.empty()) folders.emplace_back(entry);
    }
  }
  if (const std::string repo = VISORS_REPOSITORY_DATA_DIR; !repo.empty()) folders.emplace_back(repo);
  if (const std::string installed = VISORS_INSTALLED_DATA_DIR; !installed.empty()) {
    folders.emplace_back(installed);
  }
  return folders;
}

std::optional<std::filesystem::path> find_data_file(const std::string& relative) {
  std::error_code ec;
  const std::filesystem::path given(relative);
  if (given.is_absolute() || std::filesystem::is_regular_file(given, ec)) {
    if (std::filesystem::is_regular_file(given, ec)) return given;
    return std::nullopt;
  }
  for (const auto& folder : data_search_path()) {
    const auto candidate = folder / given;
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

}  // namespace visors::core::files
