#pragma once
// Paths of the GNSS reference data (data/gnss, found through the data search path) and
// the first usable record of a PRN, for the gnss tests.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "visors/core/files/data_path.hpp"

namespace visors::test {

inline std::filesystem::path gnss_data(const std::string& relative) {
  const auto path = core::files::find_data_file("gnss/" + relative);
  return path.value_or(std::filesystem::path("gnss") / relative);
}

inline bool have_gnss_data(const std::string& relative) { return core::files::find_data_file("gnss/" + relative).has_value(); }

/// Skips the current test when a GNSS data file is not in the data search path (data/SOURCES.md).
#define VISORS_REQUIRE_GNSS_DATA(relative)                                                              \
  if (!visors::test::have_gnss_data(relative))                                                            \
  GTEST_FAIL() << "gnss/" << (relative) << " not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)"

inline constexpr const char* kBrdc20100701 = "igs-2010-07-01/brdc1820.10n";
inline constexpr const char* kSp320100701 = "igs-2010-07-01/igs15904.sp3";
inline constexpr const char* kBrdc20100702 = "igs-2010-07-02/brdc1830.10n";
inline constexpr const char* kSp320100702 = "igs-2010-07-02/igs15905.sp3";
inline constexpr const char* kHert2024 = "HERT00GBR_R_20240920000_01D_GN.rnx";
inline constexpr const char* kNya2024 = "NYA100NOR_S_20241280000_01D_GN.rnx";
inline constexpr const char* kGsi0759Obs = "gsi-2005-04-02/07590920.05o";
inline constexpr const char* kGsi3040Obs = "gsi-2005-04-02/30400920.05o";
inline constexpr const char* kGsi0759Nav = "gsi-2005-04-02/07590920.05n";
inline constexpr const char* kGsi3040Nav = "gsi-2005-04-02/30400920.05n";
/// Station 3040's position as RTKLIB's own rnx2rtkp tests give it for this data (option -r,
/// tomojitakasu/RTKLIB app/rnx2rtkp/gcc/makefile; the RINEX header's is ~2 m off) [m].
inline constexpr double kGsi3040Ecef[3] = {-3978241.958, 3382840.234, 3649900.853};

/// The whole text of a file.
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// `text` with its line `number` (1-based) replaced, for malformed-input tests.
inline std::string with_line(const std::string& text, std::size_t number, const std::string& replacement) {
  std::istringstream in(text);
  std::string line, out;
  for (std::size_t k = 1; std::getline(in, line); ++k) out += (k == number ? replacement : line) + "\n";
  return out;
}

/// The first `count` lines of `text`.
inline std::string first_lines(const std::string& text, std::size_t count) {
  std::istringstream in(text);
  std::string line, out;
  for (std::size_t k = 1; k <= count && std::getline(in, line); ++k) out += line + "\n";
  return out;
}

/// Fixture for malformed-input tests: the text of the GNSS data file `Name` (skipped without it),
/// to be broken one line at a time.
template <const char* const& Name>
class MalformedCopy : public ::testing::Test {
 protected:
  void SetUp() override {
    VISORS_REQUIRE_GNSS_DATA(Name);
    text_ = file_text(gnss_data(Name));
  }
  [[nodiscard]] std::string with_line(std::size_t number, const std::string& replacement) const {
    return test::with_line(text_, number, replacement);
  }
  std::string text_;
};

}  // namespace visors::test
