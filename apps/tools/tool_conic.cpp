// `visors tool conic`: the embedded interior-point conic solver of src/visors/optim on one problem.
//   {"c":[n], "G":[[m x n]], "h":[m], "dims":{"l":k, "q":[q1,...]}, "A"?:[[p x n]], "b"?:[p],
//    "P"?:[[n x n]]}
//     -> {"status", "x", "y", "z", "s", "primal_objective", "dual_objective", "iterations",
//         "solve_time_us"}
// minimise 1/2 x'Px + c'x s.t. Ax = b, Gx + s = h, s in R+^l x Q^q1 x ... (SOC: s0 >= ||s1||).
// A and b may be absent or empty; m = l + sum(q) rows. Objectives that are infinite (certificate
// statuses) are written as null. Solver defaults of optim/conic_settings.hpp.

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "visors/optim/conic_problem.hpp"
#include "visors/optim/conic_solver.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

double finite_entry(const Json& value, const std::string& field) {
  if (!value.is_number()) throw ToolInputError(field, "must be a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw ToolInputError(field, "must be finite");
  return x;
}

Eigen::VectorXd read_vector(const Json& in, const std::string& key, Eigen::Index size) {
  const Json& value = in.at(key);
  if (!value.is_array()) throw ToolInputError(key, "must be an array of numbers");
  if (static_cast<Eigen::Index>(value.size()) != size) {
    throw ToolInputError(key, "must have " + std::to_string(size) + " entries, got " + std::to_string(value.size()));
  }
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i) {
    v(i) = finite_entry(value[static_cast<std::size_t>(i)], key + "[" + std::to_string(i) + "]");
  }
  return v;
}

Eigen::MatrixXd read_matrix(const Json& in, const std::string& key, Eigen::Index rows, Eigen::Index cols) {
  const Json& value = in.at(key);
  if (!value.is_array()) throw ToolInputError(key, "must be an array of rows");
  if (static_cast<Eigen::Index>(value.size()) != rows) {
    throw ToolInputError(key, "must have " + std::to_string(rows) + " rows, got " + std::to_string(value.size()));
  }
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const Json& row = value[static_cast<std::size_t>(r)];
    const std::string row_field = key + "[" + std::to_string(r) + "]";
    if (!row.is_array() || static_cast<Eigen::Index>(row.size()) != cols) {
      throw ToolInputError(row_field, "must be an array of " + std::to_string(cols) + " numbers");
    }
    for (Eigen::Index c = 0; c < cols; ++c) {
      m(r, c) = finite_entry(row[static_cast<std::size_t>(c)], row_field + "[" + std::to_string(c) + "]");
    }
  }
  return m;
}

int read_count(const Json& value, const std::string& field) {
  if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() > 1000000) {
    throw ToolInputError(field, "must be a non-negative integer");
  }
  return static_cast<int>(value.get<long long>());
}

Json vector_json(const Eigen::VectorXd& v) {
  Json out = Json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v(i));
  return out;
}

Json finite_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json run_conic(const Json& in) {
  if (!in.is_object()) throw ToolInputError("", "input must be a JSON object");
  reject_unknown_keys(in, {"c", "G", "h", "dims", "A", "b", "P"});
  for (const char* key : {"c", "G", "h", "dims"}) {
    if (!in.contains(key)) throw ToolInputError(key, "is required but missing");
  }
  const Json& dims_json = require_object(in, "dims");
  reject_unknown_keys(dims_json, {"l", "q"}, "dims");
  optim::ConicDimensions dims;
  dims.l = dims_json.contains("l") ? read_count(dims_json.at("l"), "dims.l") : 0;
  if (dims_json.contains("q")) {
    const Json& q = dims_json.at("q");
    if (!q.is_array()) throw ToolInputError("dims.q", "must be an array of cone dimensions");
    for (std::size_t k = 0; k < q.size(); ++k) {
      const std::string name = "dims.q[" + std::to_string(k) + "]";
      const int dim = read_count(q[k], name);
      if (dim < 1) throw ToolInputError(name, "must be >= 1 (a cone's dimension)");  // the library names the list only
      dims.q.push_back(dim);
    }
  }
  if (!in.at("c").is_array() || in.at("c").empty()) throw ToolInputError("c", "must be a non-empty array of numbers");
  dims.n = static_cast<int>(in.at("c").size());
  const bool has_a = in.contains("A") && !in.at("A").empty();
  if (in.contains("A") && !in.at("A").is_array()) throw ToolInputError("A", "must be an array of rows");
  dims.p = has_a ? static_cast<int>(in.at("A").size()) : 0;
  dims.quadratic = in.contains("P");
  take(optim::validate_dimensions(dims));

  optim::ConicProblem problem;
  problem.c = read_vector(in, "c", dims.n);
  problem.G = read_matrix(in, "G", dims.m(), dims.n);
  problem.h = read_vector(in, "h", dims.m());
  if (has_a) {
    problem.A = read_matrix(in, "A", dims.p, dims.n);
    if (!in.contains("b")) throw ToolInputError("b", "is required when A has rows");
    problem.b = read_vector(in, "b", dims.p);
  } else {
    problem.A.resize(0, dims.n);
    if (in.contains("b") && !(in.at("b").is_array() && in.at("b").empty())) {
      throw ToolInputError("b", "must be empty when A is empty");
    }
    problem.b.resize(0);
  }
  if (dims.quadratic) problem.P = read_matrix(in, "P", dims.n, dims.n);

  optim::ConicSolver solver = take(optim::ConicSolver::create(dims));
  const auto start = std::chrono::steady_clock::now();
  const optim::ConicInfo info = take(solver.solve(problem));
  const auto stop = std::chrono::steady_clock::now();
  return Json{{"status", std::string(optim::to_string(info.status))},
              {"x", vector_json(solver.x())},
              {"y", vector_json(solver.y())},
              {"z", vector_json(solver.z())},
              {"s", vector_json(solver.s())},
              {"primal_objective", finite_or_null(info.primal_objective)},
              {"dual_objective", finite_or_null(info.dual_objective)},
              {"iterations", info.iterations},
              {"solve_time_us", std::chrono::duration<double, std::micro>(stop - start).count()}};
}

const bool registered = register_tool(
    {"conic", "interior-point LP/SOCP/QP {c, G, h, dims{l, q}, A?, b?, P?} -> status, x, y, z, s", run_conic});

}  // namespace
}  // namespace visors::tools
