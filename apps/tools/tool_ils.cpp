// `visors tool ils`: integer least-squares ambiguity resolution (nav/integer_least_squares.hpp).
//   {"a": [n] cycles, "Q": [[n x n]] cycles^2, "candidates"?: m (default 2),
//    "min_success_rate"?: p (enables partial fixing)}
//   -> {"status": "ok" | "search_limit", "candidates": [[n integers], ...] best first,
//       "sqnorm": [m] ((a - z)' Q^-1 (a - z)), "ratio": sqnorm[1] / sqnorm[0],
//       "success_rate_bootstrap": P_IB of the decorrelated problem,
//       when min_success_rate is given:
//       "fixed_combinations": k (trailing decorrelated combinations whose P_IB >= p),
//       "success_rate_fixed": their P_IB, "fixed": [indices i of a determined by those k integers],
//       "partial_solution": [n] (a conditioned on the k fixed combinations; integers at "fixed")}
// Partial fixing works on integer combinations z = Z' a of the ambiguities; an original ambiguity
// is "fixed" when a = Z^-T z makes it depend on the fixed combinations only.

#include <Eigen/Cholesky>
#include <string>
#include <vector>

#include "visors/nav/integer_least_squares.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

void throw_input_error(nav::IlsStatus status, Eigen::Index n) {
  switch (status) {
    case nav::IlsStatus::kEmpty: throw ToolInputError("a", "must hold at least one ambiguity");
    case nav::IlsStatus::kTooManyAmbiguities:
      throw ToolInputError("a", "has " + std::to_string(n) + " ambiguities, above the capacity of " +
                                    std::to_string(nav::kMaxAmbiguities));
    case nav::IlsStatus::kSizeMismatch: throw ToolInputError("Q", "must be n x n with n the size of a");
    case nav::IlsStatus::kNotFinite: throw ToolInputError("Q", "must hold finite numbers");
    case nav::IlsStatus::kNotSymmetric: throw ToolInputError("Q", "must be symmetric");
    case nav::IlsStatus::kNotPositiveDefinite: throw ToolInputError("Q", "must be positive definite");
    case nav::IlsStatus::kOk:
    case nav::IlsStatus::kSearchLimit: return;
  }
}

Json columns_to_json(const nav::CandidateMatrix& m, Eigen::Index columns) {
  Json out = Json::array();
  for (Eigen::Index j = 0; j < columns; ++j) {
    Json column = Json::array();
    for (Eigen::Index i = 0; i < m.rows(); ++i) column.push_back(static_cast<long long>(m(i, j)));
    out.push_back(column);
  }
  return out;
}

// a conditioned on the k trailing combinations G a = z_fixed (G = Z(:, n-k..)'):
// a - Q G' (G Q G')^-1 (G a - z_fixed).
Json partial_solution(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q, const nav::IntegerLeastSquares& ils) {
  const nav::IlsSolution& s = ils.solution();
  const Eigen::MatrixXd G = ils.transformation().block(0, s.n - s.fixed, s.n, s.fixed).transpose();
  const Eigen::VectorXd misfit = G * a - s.z.col(0);
  const Eigen::VectorXd conditioned = a - Q * G.transpose() * (G * Q * G.transpose()).ldlt().solve(misfit);
  return std::vector<double>(conditioned.data(), conditioned.data() + conditioned.size());
}

// Indices of a that depend on the fixed (trailing k) combinations only: zero row entries of Z^-T
// in the leading n - k columns.
Json fixed_indices(const nav::IntegerLeastSquares& ils) {
  const nav::IlsSolution& s = ils.solution();
  nav::AmbiguityMatrix Z_inv_t;
  ils.decorrelated().decorrelation.transform.inverse_transpose_matrix(Z_inv_t);
  Json out = Json::array();
  for (Eigen::Index i = 0; i < s.n; ++i) {
    if (Z_inv_t.row(i).head(s.n - s.fixed).isZero(0.0)) out.push_back(i);
  }
  return out;
}

Json run_partial(const Eigen::VectorXd& a, const Eigen::MatrixXd& Q, double min_success_rate, nav::IntegerLeastSquares& ils) {
  if (!(min_success_rate > 0.0 && min_success_rate < 1.0)) throw ToolInputError("min_success_rate", "must be in (0, 1)");
  const Eigen::Index k = ils.partial_fix_size(min_success_rate);
  Json out{{"fixed_combinations", k}};
  if (k == 0) {
    out["success_rate_fixed"] = 1.0;
    out["fixed"] = Json::array();
    out["partial_solution"] = std::vector<double>(a.data(), a.data() + a.size());
    return out;
  }
  if (ils.search(k) == nav::IlsStatus::kSearchLimit) return Json{{"status", "search_limit"}};
  out["success_rate_fixed"] = ils.solution().success_rate;
  out["fixed"] = fixed_indices(ils);
  out["partial_solution"] = partial_solution(a, Q, ils);
  return out;
}

Json run_ils(const Json& in) {
  reject_unknown_keys(in, {"a", "Q", "candidates", "min_success_rate"});
  const std::vector<double> values = require_numbers(in, "a");
  const Eigen::VectorXd a = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  const int n = static_cast<int>(a.size());
  if (n == 0) throw ToolInputError("a", "must hold at least one ambiguity");
  const Eigen::MatrixXd Q = require_matrix(in, "Q", n, n);
  nav::IlsSettings settings;
  const double m = optional_number(in, "candidates").value_or(2.0);
  if (m != std::floor(m) || m < 1.0 || m > nav::kMaxCandidates) {
    throw ToolInputError("candidates", "must be an integer in [1, " + std::to_string(nav::kMaxCandidates) + "]");
  }
  settings.candidates = static_cast<int>(m);
  auto ils = take(nav::IntegerLeastSquares::create(settings));
  const nav::IlsStatus status = ils.resolve(a, Q);
  throw_input_error(status, n);
  if (status == nav::IlsStatus::kSearchLimit) return Json{{"status", "search_limit"}};
  const nav::IlsSolution& s = ils.solution();
  Json out{{"status", "ok"},
           {"candidates", columns_to_json(s.a, s.found)},
           {"sqnorm", std::vector<double>(s.sqnorm.data(), s.sqnorm.data() + s.found)},
           {"ratio", s.ratio},
           {"success_rate_bootstrap", ils.success_rate_bootstrap()}};
  if (const auto p = optional_number(in, "min_success_rate")) out.update(run_partial(a, Q, *p, ils));
  return out;
}

const bool registered = register_tool(
    {"ils", "integer least squares {a [n] cycles, Q [[n x n]] cycles^2, candidates?, min_success_rate?} -> candidates, "
            "sqnorm, ratio, success_rate_bootstrap (+ partial fixing)",
     run_ils});

}  // namespace
}  // namespace visors::tools
