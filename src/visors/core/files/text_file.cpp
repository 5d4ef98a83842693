#include "visors/core/files/text_file.hpp"

#include <fstream>
#include <sstream>

namespace visors::core::files {

std::optional<std::string> read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

}  // namespace visors::core::files
