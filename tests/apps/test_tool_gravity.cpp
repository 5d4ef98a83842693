// `visors tool gravity` through the real binary: the digest's reference vectors (§2.4) and bad
// input (exit code 2, field named on stderr).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "apps/run_tool.hpp"

namespace {

// Absolute path of a shared data file found through VISORS_DATA_PATH, or empty (test skips).
std::string shared_file(const std::string& relative) {
  const char* env = std::getenv("VISORS_DATA_PATH");
  if (env == nullptr) return {};
  std::stringstream entries(env);
  std::string entry;
  while (std::getline(entries, entry, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(entry) / relative;
    if (!entry.empty() && std::filesystem::is_regular_file(candidate)) return candidate.string();
  }
  return {};
}
#define REQUIRE_SHARED(var, relative)                                                                \
  const std::string var = shared_file(relative);                                                     \
  if (var.empty()) GTEST_SKIP() << relative << " not found: set VISORS_DATA_PATH to the shared data " \
                                               "folder (e.g. /work/shared/data)"

// Body-fixed position of the Montenbruck & Gill test (digest §2.4-1) [m].
const std::string kMgPosition = R"("r_itrf":[6525919.0,1710416.0,2508886.0])";

std::string input(const std::string& model, int degree, int order, const std::string& position = kMgPosition) {
  std::string s = R"({"model":")";
  s += model;
  s += R"(","degree":)" + std::to_string(degree) + R"(,"order":)" + std::to_string(order) + ",";
  s += position;
  s += "}";
  return s;
}

double max_abs_difference(const nlohmann::json& a, double x, double y, double z) {
  return std::max({std::abs(a[0].get<double>() - x), std::abs(a[1].get<double>() - y),
                   std::abs(a[2].get<double>() - z)});
}

// Digest §2.4-1: JGM-3 20x20 (Montenbruck & Gill test vector), 1e-7 m/s^2.
TEST(ToolGravity, Jgm3MontenbruckGillVector) {
  REQUIRE_SHARED(model, "gravity/JGM3.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 20));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LT(max_abs_difference(run.json()["a_itrf"], -6.979261862, -1.82928315091, -2.68999053339), 1e-7);
}

// Digest §2.4-2: GGM05S 60x60, 1e-7 m/s^2; the model named relative to the data path.
TEST(ToolGravity, Ggm05s60DigestVectorDataRelative) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d90.gfc");
  const auto run = visors::test::run_tool("gravity", input("gravity/GGM05S_d90.gfc", 60, 60));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LT(max_abs_difference(run.json()["a_itrf"], -6.9792607656, -1.8292848885, -2.6899854388), 1e-7);
}

// The header constants are echoed (GGM05S: GM 3.986004415e14, R 6378136.3) and U is GM/r to
// the J2 level (|U - GM/r| / (GM/r) ~ 1e-3).
TEST(ToolGravity, EchoesModelConstantsAndPotential) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d90.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 20));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.json()["gm"].get<double>(), 3.986004415e14);
  EXPECT_EQ(run.json()["radius"].get<double>(), 6378136.3);
  const double r = std::sqrt(6525919.0 * 6525919.0 + 1710416.0 * 1710416.0 + 2508886.0 * 2508886.0);
  const double central = 3.986004415e14 / r;
  EXPECT_LT(std::abs(run.json()["potential"].get<double>() - central) / central, 2e-3);
}

TEST(ToolGravity, UnknownModelFileNamesModel) {
  const auto run = visors::test::run_tool("gravity", input("gravity/NO_SUCH_MODEL.gfc", 20, 20));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("model"), std::string::npos) << run.err;
}

TEST(ToolGravity, DegreeAboveFileNamesDegree) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d70.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 71, 71));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("degree"), std::string::npos) << run.err;
}

TEST(ToolGravity, OrderAboveDegreeNamesOrder) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d70.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 21));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("order"), std::string::npos) << run.err;
}

TEST(ToolGravity, PositionInsideEarthNamesRItrf) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d70.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 20, R"("r_itrf":[0.0,0.0,6300000.0])"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("r_itrf: position is inside the Earth"), std::string::npos) << run.err;
}

TEST(ToolGravity, UnknownKeyRejected) {
  const auto run = visors::test::run_tool(
      "gravity", R"({"model":"x.gfc","degree":2,"order":2,"r_itrf":[7e6,0,0],"mu":1})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("mu"), std::string::npos) << run.err;
}

}  // namespace
