// `visors tool ils` through the real binary: the RTKLIB t_lambda utest1 case, partial fixing, and
// every class of bad input (exit 2, the field named).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/run_tool.hpp"

namespace {

// RTKLIB test/utest/t_lambda.c utest1 (T. Takasu, RTKLIB 2.4.2, github.com/tomojitakasu/RTKLIB):
// its inputs a, Q and its expected two best candidates and squared norms, tolerance 1e-4.
constexpr char kUtest1[] =
    R"("a":[1585184.171,-6716599.430,3915742.905,7627233.455,9565990.879,989457273.200],)"
    R"("Q":[[0.227134,0.112202,0.112202,0.112202,0.112202,0.103473],[0.112202,0.227134,0.112202,0.112202,0.112202,0.103473],)"
    R"([0.112202,0.112202,0.227134,0.112202,0.112202,0.103473],[0.112202,0.112202,0.112202,0.227134,0.112202,0.103473],)"
    R"([0.112202,0.112202,0.112202,0.112202,0.227134,0.103473],[0.103473,0.103473,0.103473,0.103473,0.103473,0.434339]])";

TEST(ToolIls, Utest1CandidatesAreRtklibs) {
  const auto run = visors::test::run_tool("ils", std::string("{") + kUtest1 + "}");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  // t_lambda.c utest1 F1 and F2.
  EXPECT_EQ(out["candidates"][0], (nlohmann::json{1585184, -6716599, 3915743, 7627234, 9565991, 989457273}));
  EXPECT_EQ(out["candidates"][1], (nlohmann::json{1585184, -6716600, 3915743, 7627233, 9565991, 989457273}));
}

TEST(ToolIls, Utest1SquaredNormsAndRatio) {
  const auto run = visors::test::run_tool("ils", std::string("{") + kUtest1 + "}");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  EXPECT_NEAR(out["sqnorm"][0].get<double>(), 3.507984, 1e-4);  // t_lambda.c utest1 s, to 1e-4 there
  EXPECT_NEAR(out["sqnorm"][1].get<double>(), 3.708456, 1e-4);
  EXPECT_NEAR(out["ratio"].get<double>(), 3.708456 / 3.507984, 1e-4);  // the ratio of t_lambda.c's two squared norms, 1.0571
}

// Partial fixing at p = 0.5: the success rate of the fixed combinations reaches p, the indices
// reported as fixed are integers in the conditioned solution, and the others are not all integer.
TEST(ToolIls, PartialFixReachesTheRequestedSuccessRate) {
  const auto run = visors::test::run_tool("ils", std::string("{") + kUtest1 + R"(,"min_success_rate":0.5})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  EXPECT_GE(out["success_rate_fixed"].get<double>(), 0.5);
  EXPECT_GE(out["fixed_combinations"].get<int>(), 1);
  for (const auto& i : out["fixed"]) {
    const double v = out["partial_solution"][i.get<std::size_t>()].get<double>();
    EXPECT_NEAR(v, std::round(v), 1e-6) << "index " << i;
  }
}

TEST(ToolIls, AsymmetricQIsRejectedByName) {
  const auto run = visors::test::run_tool("ils", R"({"a":[0.1,0.2],"Q":[[1,0.5],[0.4,1]]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("Q: must be symmetric"), std::string::npos) << run.err;
}

TEST(ToolIls, IndefiniteQIsRejectedByName) {
  const auto run = visors::test::run_tool("ils", R"({"a":[0.1,0.2],"Q":[[1,2],[2,1]]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("Q: must be positive definite"), std::string::npos) << run.err;
}

TEST(ToolIls, SizesThatDisagreeAreRejectedByName) {
  const auto run = visors::test::run_tool("ils", R"({"a":[0.1,0.2,0.3],"Q":[[1,0],[0,1]]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("Q"), std::string::npos) << run.err;
}

TEST(ToolIls, NonNumericValueIsRejectedByName) {
  const auto run = visors::test::run_tool("ils", R"({"a":[0.1,"NaN"],"Q":[[1,0],[0,1]]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("a"), std::string::npos) << run.err;
}

TEST(ToolIls, MoreAmbiguitiesThanTheCapacityAreRejectedByName) {
  std::string a = "[", q = "[";
  for (int i = 0; i < 65; ++i) {  // capacity 64 (nav/ambiguity_capacity.hpp)
    a += (i ? ",0.1" : "0.1");
    q += i ? ",[" : "[";
    for (int j = 0; j < 65; ++j) q += std::string(j ? "," : "") + (i == j ? "1" : "0");
    q += "]";
  }
  const auto run = visors::test::run_tool("ils", "{\"a\":" + a + "],\"Q\":" + q + "]}");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("a: has 65 ambiguities, above the capacity of 64"), std::string::npos) << run.err;
}

}  // namespace
