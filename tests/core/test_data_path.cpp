#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <unistd.h>

#include "visors/core/files/data_path.hpp"

namespace {

class DataPath : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* old = std::getenv("VISORS_DATA_PATH");
    saved_ = old ? std::optional<std::string>(old) : std::nullopt;
    // One folder per process: CTest runs the cases of this fixture in parallel processes.
    root_ = std::filesystem::temp_directory_path() / ("visors_data_path_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(root_ / "first" / "eop");
    std::filesystem::create_directories(root_ / "second" / "eop");
    std::ofstream(root_ / "second" / "eop" / "x.txt") << "second";
    ::setenv("VISORS_DATA_PATH", ((root_ / "first").string() + ":" + (root_ / "second").string()).c_str(), 1);
  }
  void TearDown() override {
    if (saved_) ::setenv("VISORS_DATA_PATH", saved_->c_str(), 1);
    else ::unsetenv("VISORS_DATA_PATH");
    std::filesystem::remove_all(root_);
  }
  std::filesystem::path root_;
  std::optional<std::string> saved_;
};

TEST_F(DataPath, SearchesEveryEntryOfTheEnvironmentVariable) {
  const auto found = visors::core::files::find_data_file("eop/x.txt");
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(*found, root_ / "second" / "eop" / "x.txt");
}

TEST_F(DataPath, EarlierEntryWins) {
  std::ofstream(root_ / "first" / "eop" / "x.txt") << "first";
  EXPECT_EQ(*visors::core::files::find_data_file("eop/x.txt"), root_ / "first" / "eop" / "x.txt");
}

TEST_F(DataPath, MissingFileIsNullopt) {
  EXPECT_FALSE(visors::core::files::find_data_file("eop/none.txt").has_value());
}

// The environment's two entries, then the repository's data/ and the installed share/visors/data.
TEST_F(DataPath, RepositoryDataFolderAfterTheEnvironment) {
  const auto folders = visors::core::files::data_search_path();
  ASSERT_EQ(folders.size(), 4u);
  EXPECT_EQ(folders[2].filename(), "data");
}

TEST_F(DataPath, InstalledDataFolderIsLast) {
  const auto folders = visors::core::files::data_search_path();
  ASSERT_EQ(folders.size(), 4u);
  EXPECT_EQ(folders.back().parent_path().filename(), "visors");
}

}  // namespace
