// Acceptance test of the conic solver against CVXOPT as an independent oracle
// (docs/algorithms/control.md#conic-solver).
// tests/optim/cvxopt_oracle.py (run here with /usr/bin/python3, which scripts/install-deps.sh
// provides together with python3-cvxopt) generates 320 seeded instances in eight classes and
// solves them with CVXOPT; every instance is solved again here and compared: same status,
// objective within 1e-7 relative, and our own residuals / certificates checked on the data.
// Missing Python or CVXOPT is a failure, not a skip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "visors/optim/conic_solver.hpp"

namespace {

using visors::optim::ConicDimensions;
using visors::optim::ConicProblem;
using visors::optim::ConicSettings;
using visors::optim::ConicSolver;
using visors::optim::ConicStatus;
using Json = nlohmann::json;

Eigen::VectorXd vec(const Json& j) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(j.size()));
  for (std::size_t i = 0; i < j.size(); ++i) v(static_cast<Eigen::Index>(i)) = j[i].get<double>();
  return v;
}

Eigen::MatrixXd mat(const Json& j, Eigen::Index rows, Eigen::Index cols) {
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index r = 0; r < rows; ++r) {
    for (Eigen::Index c = 0; c < cols; ++c) m(r, c) = j[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].get<double>();
  }
  return m;
}

// Smallest "eigenvalue margin" of v in K: orthant entries, s0 - ||s1|| per cone.
double cone_margin(const Eigen::VectorXd& v, const ConicDimensions& dims) {
  double margin = 0.0;
  for (int i = 0; i < dims.l; ++i) margin = std::min(margin, v(i));
  int o = dims.l;
  for (const int q : dims.q) {
    margin = std::min(margin, v(o) - v.segment(o + 1, q - 1).norm());
    o += q;
  }
  return margin;
}

double median(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : (v.size() % 2 == 1 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

struct ClassStats {
  int count = 0;
  int agree = 0;
  double max_rel_error = 0.0;
  std::vector<int> ours, theirs;
};

TEST(ConicOracle, AgreesWithCvxoptOnGeneratedInstances) {
  const std::filesystem::path script = std::filesystem::path(VISORS_SOURCE_DIR) / "tests/optim/cvxopt_oracle.py";
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("visors_optim_oracle_" + std::to_string(::getpid()) + ".json");
  ASSERT_TRUE(std::filesystem::exists("/usr/bin/python3")) << "/usr/bin/python3 missing: run scripts/install-deps.sh";
  const std::string command = "/usr/bin/python3 '" + script.string() + "' --out '" + out.string() + "'";
  const int rc = std::system(command.c_str());
  ASSERT_EQ(rc, 0) << "the CVXOPT oracle failed (python3-cvxopt and python3-numpy are installed by "
                      "scripts/install-deps.sh): " << command;
  Json doc;
  {
    std::ifstream in(out);
    doc = Json::parse(in);
  }
  std::filesystem::remove(out);
  const Json& instances = doc.at("instances");
  // measured 320 generated instances (2026-11); bound 300
  ASSERT_GE(instances.size(), 300u);

  ConicSettings settings;  // tighter than the defaults so that objectives agree to 1e-7
  settings.feasibility_tolerance = 1e-9;
  settings.absolute_gap_tolerance = 1e-9;
  settings.relative_gap_tolerance = 1e-9;
  const double kObjective = 1e-7;  // acceptance criterion: objective within 1e-7 relative
  const double kResidual = 1e-8;   // residual / certificate check on the returned point

  std::map<std::string, ClassStats> stats;
  std::vector<int> all_ours, all_theirs;
  for (std::size_t k = 0; k < instances.size(); ++k) {
    const Json& inst = instances[k];
    ConicDimensions dims;
    dims.n = inst.at("n").get<int>();
    dims.l = inst.at("l").get<int>();
    dims.q = inst.at("q").get<std::vector<int>>();
    dims.p = inst.at("p").get<int>();
    dims.quadratic = inst.contains("P");
    const int m = dims.m();
    ConicProblem pr;
    pr.c = vec(inst.at("c"));
    pr.G = mat(inst.at("G"), m, dims.n);
    pr.h = vec(inst.at("h"));
    pr.A = mat(inst.at("A"), dims.p, dims.n);
    pr.b = vec(inst.at("b"));
    if (dims.quadratic) pr.P = mat(inst.at("P"), dims.n, dims.n);
    const std::string cls = inst.at("cls").get<std::string>();
    const std::string expected = inst.at("status").get<std::string>();
    const std::string label = "instance " + std::to_string(k) + " (" + cls + ")";

    auto solver = ConicSolver::create(dims, settings);
    ASSERT_TRUE(solver.ok()) << label << ": " << solver.error().describe();
    ConicSolver s = std::move(solver).value();
    const auto info = s.solve(pr);
    ASSERT_TRUE(info.ok()) << label << ": " << info.error().describe();
    ClassStats& cs = stats[cls];
    ++cs.count;
    const std::string got(to_string(info->status));
    EXPECT_EQ(got, expected) << label;
    if (got != expected) continue;
    ++cs.agree;
    cs.ours.push_back(info->iterations);
    cs.theirs.push_back(inst.at("iterations").get<int>());
    all_ours.push_back(info->iterations);
    all_theirs.push_back(inst.at("iterations").get<int>());
    const Eigen::VectorXd& x = s.x();
    const Eigen::VectorXd& y = s.y();
    const Eigen::VectorXd& z = s.z();
    const Eigen::VectorXd& sl = s.s();
    if (expected == "optimal") {
      const double ref = inst.at("objective").get<double>();
      const double rel = std::abs(info->primal_objective - ref) / std::max(1.0, std::abs(ref));
      cs.max_rel_error = std::max(cs.max_rel_error, rel);
      EXPECT_LE(rel, kObjective) << label << ": ours " << info->primal_objective << " CVXOPT " << ref;
      const double bn = std::max(1.0, pr.b.norm()), hn = std::max(1.0, pr.h.norm()), cn = std::max(1.0, pr.c.norm());
      // kResidual = 1e-8 is the solver's feasibility_tolerance (conic_settings.hpp); measured <= 2.8e-9 objective, <= 9.4e-10 residuals (2026-11)
      EXPECT_LE((pr.A * x - pr.b).norm() / bn, kResidual) << label;
      EXPECT_LE((pr.G * x + sl - pr.h).norm() / hn, kResidual) << label;
      Eigen::VectorXd dual = pr.c + pr.A.transpose() * y + pr.G.transpose() * z;
      if (dims.quadratic) dual += pr.P * x;
      EXPECT_LE(dual.norm() / cn, kResidual) << label;
      EXPECT_GE(cone_margin(sl, dims), -kResidual) << label;
      EXPECT_GE(cone_margin(z, dims), -kResidual) << label;
    } else if (expected == "primal_infeasible") {
      // Farkas certificate: b'y + h'z = -1, A'y + G'z = 0, z in K.
      // loose: measured 2.2e-15 (2026-11), bound 1e-9 ~5e5x above (the certificate is normalised exactly)
      EXPECT_NEAR(pr.b.dot(y) + pr.h.dot(z), -1.0, 1e-9) << label;
      EXPECT_LE((pr.A.transpose() * y + pr.G.transpose() * z).norm() / std::max(1.0, pr.c.norm()), kResidual) << label;
      EXPECT_GE(cone_margin(z, dims), -kResidual) << label;
    } else if (expected == "dual_infeasible") {
      // Unbounded ray: c'x = -1, Ax = 0, Gx + s = 0, s in K.
      // loose: measured 1.3e-15 (2026-11), bound 1e-9 ~7e5x above
      EXPECT_NEAR(pr.c.dot(x), -1.0, 1e-9) << label;
      EXPECT_LE((pr.A * x).norm() / std::max(1.0, pr.b.norm()), kResidual) << label;
      EXPECT_LE((pr.G * x + sl).norm() / std::max(1.0, pr.h.norm()), kResidual) << label;
      EXPECT_GE(cone_margin(sl, dims), -kResidual) << label;
    }
  }
  std::printf("%-18s %5s %6s %12s %10s %10s\n", "class", "count", "agree", "max_rel_obj", "ours med/max", "cvxopt med/max");
  for (const auto& [name, cs] : stats) {
    std::printf("%-18s %5d %6d %12.3e %6.1f/%-4d %6.1f/%-4d\n", name.c_str(), cs.count, cs.agree, cs.max_rel_error,
                median(cs.ours), cs.ours.empty() ? 0 : *std::max_element(cs.ours.begin(), cs.ours.end()),
                median(cs.theirs), cs.theirs.empty() ? 0 : *std::max_element(cs.theirs.begin(), cs.theirs.end()));
  }
  if (!all_ours.empty()) {
    std::printf("all: %zu instances, iterations ours median %.1f max %d; CVXOPT median %.1f max %d\n",
                instances.size(), median(all_ours), *std::max_element(all_ours.begin(), all_ours.end()),
                median(all_theirs), *std::max_element(all_theirs.begin(), all_theirs.end()));
  }
}

}  // namespace
