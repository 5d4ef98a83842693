#pragma once
// Test helpers for the run directories' CSV files and the scenario texts the system tests edit:
// a CSV file as its header and its rows' fields (comma-separated, no quoting: the files the
// tools write), read and written back; one replacement in a text that must contain it.

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace visors::test {

/// The fields of one CSV line; a trailing comma is a last empty field.
inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream fields(line);
  for (std::string f; std::getline(fields, f, ',');) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

/// A CSV file: its header's columns and its rows' fields.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  /// The index of column `name` (a test failure, and 0, when there is none).
  [[nodiscard]] std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  [[nodiscard]] const std::string& text(std::size_t row, const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return rows.at(row).at(i);
    }
    throw std::runtime_error("no column " + name);
  }
  [[nodiscard]] double number(std::size_t row, const std::string& name) const { return std::stod(text(row, name)); }
  /// The three columns prefix + x|y|z + suffix of a row.
  [[nodiscard]] Eigen::Vector3d vector(std::size_t row, const std::string& prefix, const std::string& suffix) const {
    return {number(row, prefix + "x" + suffix), number(row, prefix + "y" + suffix), number(row, prefix + "z" + suffix)};
  }
};

inline CsvTable read_csv_table(const std::filesystem::path& path) {
  CsvTable t;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  t.header = split_csv_line(line);
  while (std::getline(in, line)) t.rows.push_back(split_csv_line(line));
  return t;
}

inline void write_csv_table(const std::filesystem::path& path, const CsvTable& t) {
  std::ofstream out(path);
  const auto line = [&out](const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
    out << '\n';
  };
  line(t.header);
  for (const auto& row : t.rows) line(row);
}

/// Replaces the first `from` in `text` by `to`; a test failure when `text` has no `from`.
inline void replace_once(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

}  // namespace visors::test
