#include "gnss/files/text_file.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

namespace visors::gnss::files {

namespace {

// "'<text>' is not <what>", built by appending (GCC 12 reports a false -Wrestrict on
// "'" + std::string(...)).
std::string not_a(std::string_view text, const char* what) {
  std::string message(1, '\'');
  message.append(text);
  message.append("' is not ");
  message.append(what);
  return message;
}

}  // namespace

core::Result<TextFile> TextFile::open(const std::filesystem::path& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return core::Error{path.string(), what + " not found or not a regular file"};
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return core::Error{path.string(), "cannot open the " + what + " for reading"};
  return TextFile(path, std::move(in));
}

bool TextFile::next(std::string& line) {
  if (!std::getline(in_, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  ++line_number_;
  return true;
}

core::Error TextFile::error(const std::string& problem) const {
  return core::Error{path_.string() + ":" + std::to_string(line_number_), problem};
}

core::Error TextFile::file_error(const std::string& problem) const { return core::Error{path_.string(), problem}; }

std::string_view column(std::string_view line, std::size_t first, std::size_t width) {
  if (first >= line.size()) return {};
  return line.substr(first, width);
}

std::string_view trim(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

core::Result<std::optional<double>> parse_number(std::string_view field, std::string_view name) {
  const std::string_view text = trim(field);
  if (text.empty()) return std::optional<double>{};
  std::string normal(text);
  for (char& c : normal) {
    if (c == 'D' || c == 'd') c = 'E';
  }
  const char* begin = normal.data();
  if (*begin == '+') ++begin;  // from_chars rejects a leading '+'
  double value = 0.0;
  const auto [end, ec] = std::from_chars(begin, normal.data() + normal.size(), value);
  if (ec != std::errc() || end != normal.data() + normal.size() || !std::isfinite(value)) {
    return core::Error{std::string(name), not_a(text, "a number")};
  }
  return std::optional<double>(value);
}

core::Result<std::optional<long long>> parse_integer(std::string_view field, std::string_view name) {
  const std::string_view text = trim(field);
  if (text.empty()) return std::optional<long long>{};
  const char* begin = text.data();
  if (*begin == '+') ++begin;
  long long value = 0;
  const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) {
    return core::Error{std::string(name), not_a(text, "an integer")};
  }
  return std::optional<long long>(value);
}

}  // namespace visors::gnss::files
