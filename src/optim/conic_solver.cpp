#include "optim/conic_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/LU>

#include "optim/cone.hpp"
#include "optim/quasidefinite_ldl.hpp"
#include "optim/separable_kkt.hpp"

namespace visors::optim {
namespace {

using Vec = std::vector<double>;

double dot(const double* a, const double* b, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += a[i] * b[i];
  return sum;
}

double norm2(const double* a, int n) { return std::sqrt(dot(a, a, n)); }

double norm_inf(const double* a, int n) {
  double v = 0.0;
  for (int i = 0; i < n; ++i) v = std::max(v, std::abs(a[i]));
  return v;
}

// Compressed sparse rows with capacity for a dense matrix.
struct Csr {
  int rows = 0;
  std::vector<int> ptr;
  std::vector<int> col;
  Vec val;

  void reserve(int r, int c) {
    rows = r;
    ptr.assign(static_cast<std::size_t>(r) + 1, 0);
    col.assign(static_cast<std::size_t>(r) * static_cast<std::size_t>(c) + 1, 0);
    val.assign(col.size(), 0.0);
  }
  /// Rows of `dense` (rows x cols as reserved), zero entries skipped.
  void assign(const Eigen::MatrixXd& dense) {
    int count = 0;
    for (int i = 0; i < rows; ++i) {
      ptr[static_cast<std::size_t>(i)] = count;
      for (int j = 0; j < dense.cols(); ++j) {
        if (const double v = dense(i, j); v != 0.0) {
          col[static_cast<std::size_t>(count)] = j;
          val[static_cast<std::size_t>(count++)] = v;
        }
      }
    }
    ptr[static_cast<std::size_t>(rows)] = count;
  }
  // out = M v
  void multiply(const double* v, double* out) const {
    for (int i = 0; i < rows; ++i) {
      double sum = 0.0;
      for (int k = ptr[i]; k < ptr[i + 1]; ++k) sum += val[k] * v[col[k]];
      out[i] = sum;
    }
  }
  // out += M' v
  void multiply_transpose_add(const double* v, double* out) const {
    for (int i = 0; i < rows; ++i) {
      const double vi = v[i];
      if (vi == 0.0) continue;
      for (int k = ptr[i]; k < ptr[i + 1]; ++k) out[col[k]] += val[k] * vi;
    }
  }
};

Vec sized(int n) { return Vec(static_cast<std::size_t>(std::max(n, 0)) + 1, 0.0); }

}  // namespace

std::string_view to_string(ConicStatus status) {
  switch (status) {
    case ConicStatus::optimal: return "optimal";
    case ConicStatus::primal_infeasible: return "primal_infeasible";
    case ConicStatus::dual_infeasible: return "dual_infeasible";
    case ConicStatus::max_iterations: return "max_iterations";
    case ConicStatus::numerical_error: return "numerical_error";
  }
  return "numerical_error";
}

// Internal problem: the equilibrated data
//   minimise (1/2) x'Px + c'x  s.t.  A x = b,  G x + s = h,  s in K
// with x = D xs, y = E ys, z = F zs, s = F^{-1} ss between original and scaled variables.
struct ConicSolver::Workspace {
  int n = 0, p = 0, m = 0;  // original
  ConeProduct cone;
  NtScaling nt;
  QuasiDefiniteLdl ldl;
  // Fallback when the structured LDL' needed dynamic regularisation or its refinement stalled:
  // dense LU with partial pivoting of the same reduced matrix (backward stable for any
  // ordering; Golub & Van Loan alg. 3.4.1). Sized at setup.
  Eigen::MatrixXd dense;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd lu_rhs, lu_sol;
  bool use_lu = false;
  int fallbacks = 0;  // iterations that used the dense LU
  Csr G, A, P;
  Vec c, h, b;
  Vec dcol, erow, frow;  // Ruiz scalings D, E, F
  Vec colmax, rowmax, blockmax;
  std::vector<int> block_of_row;
  std::vector<int> bc_ptr, bc_col, marker, pos;
  Vec vbuf;
  // Separable cone blocks (eliminated in closed form before the LDL', see assemble_kkt): flags
  // per block and per column, how many blocks (or P) touch each column; per G row of such a
  // block its column c_r and 1/g_r, and the row r of G_k^-T A_k' (A(i, c_r) / g_r, i < p);
  // scratch for U = W_k G_k^-T A_k' (dim x p) and block vectors.
  std::vector<unsigned char> sep_block, sep_col;
  std::vector<int> col_uses, sep_gcol;
  bool any_separable = false;
  // Every column separable: the KKT solves go through the p x p Schur complement (schur) while
  // it factors; use_schur says the current iteration's factorisation is that one.
  bool all_separable = false;
  bool use_schur = false;
  SeparableKkt schur;
  Vec sep_ginv, sep_ak, ubuf, sep_in, sep_out;
  Vec pwork, rfac;  // PSD check of P: work copy and pivoted Cholesky factor R (P = R'R)
  std::vector<unsigned char> pdone;
  // Iterate and directions.
  Vec x, y, z, s, lambda, px, dxi, pdxi;
  double tau = 1.0, kappa = 1.0;
  Vec hx, ax, gxs, rx, ry, rz;
  Vec x1, y1, z1, x2, y2, z2;         // KKT solutions for (-c, b, h) and the step
  Vec ds_aff, dz_aff, tmp_s, tmp_z, ds, dzs, rs, ds_full;
  Vec bx, by, bz, ex, ey, ez, kx, ky, kz, red;  // KKT right sides, residuals, reduced vector
  double cnorm = 1.0, bnorm = 1.0, hnorm = 1.0;
};

ConicSolver::ConicSolver(const ConicDimensions& dims, const ConicSettings& settings)
    : dims_(dims), settings_(settings), work_(std::make_unique<Workspace>()) {
  Workspace& w = *work_;
  w.n = dims.n;
  w.p = dims.p;
  w.m = dims.m();
  w.cone = ConeProduct(dims.l, dims.q);
  w.nt = NtScaling(w.cone);
  w.ldl = QuasiDefiniteLdl(w.n + w.p);
  if (w.m == w.n) w.schur = SeparableKkt(w.m, w.p);
  const int full = w.n + w.p;
  w.dense = Eigen::MatrixXd::Zero(full, full);
  w.lu = Eigen::PartialPivLU<Eigen::MatrixXd>(full);
  w.lu_rhs = Eigen::VectorXd::Zero(full);
  w.lu_sol = Eigen::VectorXd::Zero(full);
  w.G.reserve(w.m, w.n);
  w.A.reserve(w.p, w.n);
  w.P.reserve(dims.quadratic ? w.n : 0, w.n);
  w.c = sized(w.n);
  w.h = sized(w.m);
  w.b = sized(w.p);
  w.dcol = sized(w.n);
  w.erow = sized(w.p);
  w.frow = sized(w.m);
  w.colmax = sized(w.n);
  w.rowmax = sized(w.p);
  const int blocks = w.nt.blocks();
  w.blockmax = sized(blocks);
  w.block_of_row.assign(static_cast<std::size_t>(w.m) + 1, 0);
  int max_block = 1;
  for (int k = 0; k < blocks; ++k) {
    max_block = std::max(max_block, w.nt.block_dim(k));
    for (int r = 0; r < w.nt.block_dim(k); ++r) w.block_of_row[w.nt.block_start(k) + r] = k;
  }
  w.bc_ptr.assign(static_cast<std::size_t>(blocks) + 1, 0);
  w.bc_col.assign(static_cast<std::size_t>(blocks) * static_cast<std::size_t>(w.n) + 1, 0);
  w.marker.assign(static_cast<std::size_t>(w.n) + 1, -1);
  w.pos.assign(static_cast<std::size_t>(w.n) + 1, 0);
  w.vbuf = sized(max_block * w.n);
  w.sep_block.assign(static_cast<std::size_t>(blocks) + 1, 0);
  w.sep_col.assign(static_cast<std::size_t>(w.n) + 1, 0);
  w.col_uses.assign(static_cast<std::size_t>(w.n) + 1, 0);
  w.sep_gcol.assign(static_cast<std::size_t>(w.m) + 1, 0);
  w.sep_ginv = sized(w.m);
  w.sep_ak = sized(w.m * w.p);
  w.ubuf = sized(max_block * w.p);
  for (Vec* v : {&w.sep_in, &w.sep_out}) *v = sized(max_block);
  if (dims.quadratic) {
    w.pwork = sized(w.n * w.n);
    w.rfac = sized(w.n * w.n);
    w.pdone.assign(static_cast<std::size_t>(w.n) + 1, 0);
  }
  for (Vec* v : {&w.x, &w.px, &w.dxi, &w.pdxi, &w.hx, &w.rx, &w.x1, &w.x2, &w.bx, &w.ex, &w.kx}) *v = sized(w.n);
  for (Vec* v : {&w.y, &w.ax, &w.ry, &w.y1, &w.y2, &w.by, &w.ey, &w.ky}) *v = sized(w.p);
  for (Vec* v : {&w.z, &w.s, &w.lambda, &w.gxs, &w.rz, &w.z1, &w.z2, &w.ds_aff, &w.dz_aff,
                 &w.tmp_s, &w.tmp_z, &w.ds, &w.dzs, &w.rs, &w.ds_full, &w.bz, &w.ez, &w.kz}) {
    *v = sized(w.m);
  }
  w.red = sized(w.n + w.p);
  x_out_ = Eigen::VectorXd::Zero(w.n);
  y_out_ = Eigen::VectorXd::Zero(w.p);
  z_out_ = Eigen::VectorXd::Zero(w.m);
  s_out_ = Eigen::VectorXd::Zero(w.m);
}

ConicSolver::ConicSolver(ConicSolver&&) noexcept = default;
ConicSolver& ConicSolver::operator=(ConicSolver&&) noexcept = default;
ConicSolver::~ConicSolver() = default;

core::Result<ConicSolver> ConicSolver::create(const ConicDimensions& dims, const ConicSettings& settings) {
  if (auto ok = validate_dimensions(dims); !ok) return ok.error();
  if (settings.max_iterations < 0) return core::Error{"settings.max_iterations", "must be >= 0"};
  if (!(settings.feasibility_tolerance > 0.0)) return core::Error{"settings.feasibility_tolerance", "must be > 0"};
  if (!(settings.absolute_gap_tolerance > 0.0)) return core::Error{"settings.absolute_gap_tolerance", "must be > 0"};
  if (!(settings.relative_gap_tolerance > 0.0)) return core::Error{"settings.relative_gap_tolerance", "must be > 0"};
  if (!(settings.step_fraction > 0.0 && settings.step_fraction < 1.0)) {
    return core::Error{"settings.step_fraction", "must be in (0, 1)"};
  }
  if (!(settings.static_regularisation >= 0.0)) return core::Error{"settings.static_regularisation", "must be >= 0"};
  if (!(settings.dynamic_delta > 0.0)) return core::Error{"settings.dynamic_delta", "must be > 0"};
  if (!(settings.dynamic_epsilon >= 0.0)) return core::Error{"settings.dynamic_epsilon", "must be >= 0"};
  if (settings.refinement_steps < 0) return core::Error{"settings.refinement_steps", "must be >= 0"};
  if (!(settings.refinement_tolerance > 0.0) || settings.refinement_tolerance >= 1e-3) {
    return core::Error{"settings.refinement_tolerance", "must be in (0, 1e-3)"};
  }
  if (settings.equilibration_passes < 0) return core::Error{"settings.equilibration_passes", "must be >= 0"};
  if (!(settings.psd_tolerance >= 0.0)) return core::Error{"settings.psd_tolerance", "must be >= 0"};
  return ConicSolver(dims, settings);
}

namespace {

// Pivoted Cholesky P = R'R (R upper trapezoidal after the column permutation, rows beyond the
// rank zero). Golub & Van Loan, Matrix Computations 4th ed., alg. 4.2.4 (outer-product form with
// diagonal pivoting). Returns false if P is not positive semidefinite within `tol` (relative).
bool factor_psd(const Eigen::MatrixXd& P, double tol, double* work, double* r,
                unsigned char* done) {
  const int n = static_cast<int>(P.rows());
  const auto at = [n](int i, int j) { return static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + static_cast<std::size_t>(j); };
  double scale = 1.0;
  for (int i = 0; i < n; ++i) {
    done[i] = 0;
    for (int j = 0; j < n; ++j) {
      work[at(i, j)] = P(i, j);
      r[at(i, j)] = 0.0;
      scale = std::max(scale, std::abs(P(i, j)));
    }
  }
  const double threshold = tol * scale;
  for (int k = 0; k < n; ++k) {
    int pivot = -1;
    double dmax = -std::numeric_limits<double>::infinity();
    for (int j = 0; j < n; ++j) {
      if (done[j] == 0 && work[at(j, j)] > dmax) {
        dmax = work[at(j, j)];
        pivot = j;
      }
    }
    if (dmax <= threshold) break;
    const double root = std::sqrt(dmax);
    done[pivot] = 1;
    r[at(k, pivot)] = root;
    for (int j = 0; j < n; ++j) {
      if (done[j] == 0) r[at(k, j)] = work[at(pivot, j)] / root;
    }
    for (int i = 0; i < n; ++i) {
      if (done[i] != 0) continue;
      for (int j = 0; j < n; ++j) {
        if (done[j] == 0) work[at(i, j)] -= r[at(k, i)] * r[at(k, j)];
      }
    }
  }
  // What is left must vanish: |a_ij| <= sqrt(a_ii a_jj) for a PSD remainder.
  for (int i = 0; i < n; ++i) {
    if (done[i] != 0) continue;
    for (int j = 0; j < n; ++j) {
      if (done[j] == 0 && std::abs(work[at(i, j)]) > std::sqrt(threshold) * std::sqrt(scale)) return false;
    }
    if (work[at(i, i)] < -threshold) return false;
  }
  return true;
}

}  // namespace

core::Result<ConicInfo> ConicSolver::solve(const ConicProblem& problem) {
  if (auto ok = validate_problem(problem, dims_); !ok) return ok.error();
  Workspace& w = *work_;
  const int n = w.n, p = w.p, m = w.m;
  const ConicSettings& st = settings_;

  // ---- Problem data, unscaled, in sparse rows.
  if (dims_.quadratic) {
    if (!factor_psd(problem.P, st.psd_tolerance, w.pwork.data(), w.rfac.data(), w.pdone.data())) {
      return core::Error{"P", "must be positive semidefinite"};
    }
  }
  w.G.assign(problem.G);
  w.A.assign(problem.A);
  if (w.P.rows > 0) w.P.assign(problem.P);
  for (int i = 0; i < m; ++i) w.h[i] = problem.h(i);
  for (int i = 0; i < p; ++i) w.b[i] = problem.b(i);
  for (int j = 0; j < n; ++j) w.c[j] = problem.c(j);
  w.cnorm = std::max(1.0, norm2(w.c.data(), n));
  w.bnorm = std::max(1.0, norm2(w.b.data(), p));
  w.hnorm = std::max(1.0, norm2(w.h.data(), m));

  // ---- Ruiz equilibration of [A; G] (Ruiz 2001, "A scaling algorithm to equilibrate both rows
  // and columns norms in matrices", RAL-TR-2001-034): repeatedly divide every row and column by
  // the square root of its infinity norm. A second-order cone's rows share one factor so the
  // scaled cone is the same cone.
  const int blocks = w.nt.blocks();
  std::fill(w.dcol.begin(), w.dcol.end(), 1.0);
  std::fill(w.erow.begin(), w.erow.end(), 1.0);
  std::fill(w.frow.begin(), w.frow.end(), 1.0);
  const auto root_inverse = [](double v) { return v > 0.0 ? 1.0 / std::sqrt(std::clamp(v, 1e-8, 1e8)) : 1.0; };
  for (int pass = 0; pass < st.equilibration_passes; ++pass) {
    std::fill(w.colmax.begin(), w.colmax.end(), 0.0);
    std::fill(w.blockmax.begin(), w.blockmax.end(), 0.0);
    for (int i = 0; i < p; ++i) {
      double rmax = 0.0;
      for (int k = w.A.ptr[i]; k < w.A.ptr[i + 1]; ++k) {
        const double v = std::abs(w.A.val[k]);
        rmax = std::max(rmax, v);
        w.colmax[w.A.col[k]] = std::max(w.colmax[w.A.col[k]], v);
      }
      w.rowmax[i] = rmax;
    }
    for (int i = 0; i < w.P.rows; ++i) {
      for (int k = w.P.ptr[i]; k < w.P.ptr[i + 1]; ++k) {
        w.colmax[w.P.col[k]] = std::max(w.colmax[w.P.col[k]], std::abs(w.P.val[k]));
      }
    }
    for (int i = 0; i < m; ++i) {
      const int blk = w.block_of_row[i];
      for (int k = w.G.ptr[i]; k < w.G.ptr[i + 1]; ++k) {
        const double v = std::abs(w.G.val[k]);
        w.blockmax[blk] = std::max(w.blockmax[blk], v);
        w.colmax[w.G.col[k]] = std::max(w.colmax[w.G.col[k]], v);
      }
    }
    for (int j = 0; j < n; ++j) w.colmax[j] = root_inverse(w.colmax[j]);
    for (int i = 0; i < p; ++i) w.rowmax[i] = root_inverse(w.rowmax[i]);
    for (int k = 0; k < blocks; ++k) w.blockmax[k] = root_inverse(w.blockmax[k]);
    for (int i = 0; i < p; ++i) {
      w.erow[i] *= w.rowmax[i];
      for (int k = w.A.ptr[i]; k < w.A.ptr[i + 1]; ++k) w.A.val[k] *= w.rowmax[i] * w.colmax[w.A.col[k]];
    }
    for (int i = 0; i < m; ++i) {
      const double f = w.blockmax[w.block_of_row[i]];
      w.frow[i] *= f;
      for (int k = w.G.ptr[i]; k < w.G.ptr[i + 1]; ++k) w.G.val[k] *= f * w.colmax[w.G.col[k]];
    }
    for (int i = 0; i < w.P.rows; ++i) {
      for (int k = w.P.ptr[i]; k < w.P.ptr[i + 1]; ++k) w.P.val[k] *= w.colmax[i] * w.colmax[w.P.col[k]];
    }
    for (int j = 0; j < n; ++j) w.dcol[j] *= w.colmax[j];
  }
  for (int j = 0; j < n; ++j) w.c[j] *= w.dcol[j];
  for (int i = 0; i < p; ++i) w.b[i] *= w.erow[i];
  for (int i = 0; i < m; ++i) w.h[i] *= w.frow[i];

  // ---- Structure of the reduced KKT matrix [G'W^-2 G + dI, A'; A, -dI]: block k of the cone
  // couples the columns its rows touch (W^-1 is dense within a block).
  //
  // A block is separable when each of its rows has one entry of G, in distinct columns that no
  // other block and no P entry touch (bounds x_j >= 0, norm cones on variables such as the
  // planner's ||dv_k|| <= t_k). Its diagonal block H_k = G_k'W_k^-2 G_k then has the closed-form
  // inverse G_k^-1 W_k^2 G_k^-T, and it is eliminated before the LDL': the y rows get
  // -A_k H_k^-1 A_k' = -U'U with U = W_k G_k^-T A_k' (a sum of squares, no cancellation), and its
  // columns become unit pivots. Forming and pivoting on H_k itself instead squares the
  // condition of W_k near the optimum (eigenvalues eta^-2 (w0 +- ||w1||)^2), where the fixed-order
  // LDL' would meet tiny, cancellation-made pivots.
  QuasiDefiniteLdl& ldl = w.ldl;
  {
    int count = 0;
    std::fill(w.col_uses.begin(), w.col_uses.end(), 0);
    for (int k = 0; k < blocks; ++k) {
      w.bc_ptr[k] = count;
      const int r0 = w.nt.block_start(k);
      const int r1 = r0 + w.nt.block_dim(k);
      for (int i = r0; i < r1; ++i) {
        for (int e = w.G.ptr[i]; e < w.G.ptr[i + 1]; ++e) w.marker[w.G.col[e]] = k;
      }
      for (int j = 0; j < n; ++j) {
        if (w.marker[j] == k) {
          w.bc_col[count++] = j;
          ++w.col_uses[j];
        }
      }
    }
    w.bc_ptr[blocks] = count;
    std::fill(w.marker.begin(), w.marker.end(), -1);
    for (int i = 0; i < w.P.rows; ++i) {
      for (int e = w.P.ptr[i]; e < w.P.ptr[i + 1]; ++e) w.col_uses[w.P.col[e]] += 2;
    }
    std::fill(w.sep_col.begin(), w.sep_col.end(), 0);
    w.any_separable = false;
    for (int k = 0; k < blocks; ++k) {
      const int r0 = w.nt.block_start(k);
      const int dim = w.nt.block_dim(k);
      bool separable = w.bc_ptr[k + 1] - w.bc_ptr[k] == dim;
      for (int r = r0; separable && r < r0 + dim; ++r) {
        separable = w.G.ptr[r + 1] - w.G.ptr[r] == 1 && w.col_uses[w.G.col[w.G.ptr[r]]] == 1;
      }
      w.sep_block[k] = separable ? 1 : 0;
      w.any_separable = w.any_separable || separable;
      for (int r = r0; separable && r < r0 + dim; ++r) {
        w.sep_gcol[r] = w.G.col[w.G.ptr[r]];
        w.sep_ginv[r] = 1.0 / w.G.val[w.G.ptr[r]];
        w.sep_col[w.sep_gcol[r]] = 1;
        w.marker[w.sep_gcol[r]] = r;  // column -> row, for the A entries below
      }
    }
    w.all_separable = std::all_of(w.sep_col.begin(), w.sep_col.begin() + n, [](unsigned char f) { return f != 0; });
    if (w.all_separable) {
      // Every column separable (then m = n): the Schur-complement path, no LDL' structure.
      for (int r = 0; r < m; ++r) w.schur.set_row(r, w.sep_gcol[r], w.G.val[w.G.ptr[r]]);
      w.schur.clear_equalities();
      for (int i = 0; i < p; ++i) {
        for (int e = w.A.ptr[i]; e < w.A.ptr[i + 1]; ++e) w.schur.set_equality_entry(i, w.marker[w.A.col[e]], w.A.val[e]);
      }
    } else {
      ldl.begin_structure(n + p, n);
      for (int k = 0; k < blocks; ++k) {
        for (int a = w.bc_ptr[k]; w.sep_block[k] == 0 && a < w.bc_ptr[k + 1]; ++a) {
          for (int bb = w.bc_ptr[k]; bb <= a; ++bb) ldl.mark(w.bc_col[a], w.bc_col[bb]);
        }
      }
      std::fill(w.sep_ak.begin(), w.sep_ak.end(), 0.0);
      for (int i = 0; i < p; ++i) {
        for (int e = w.A.ptr[i]; e < w.A.ptr[i + 1]; ++e) {
          const int j = w.A.col[e];
          if (w.sep_col[j] == 0) {
            ldl.mark(n + i, j);
          } else {
            const int r = w.marker[j];
            w.sep_ak[static_cast<std::size_t>(r * p + i)] = w.A.val[e] * w.sep_ginv[r];
          }
        }
        for (int i2 = 0; w.any_separable && i2 <= i; ++i2) ldl.mark(n + i, n + i2);
      }
      for (int i = 0; i < w.P.rows; ++i) {
        for (int e = w.P.ptr[i]; e < w.P.ptr[i + 1]; ++e) {
          if (w.P.col[e] <= i) ldl.mark(i, w.P.col[e]);
        }
      }
      ldl.analyse();
    }
    std::fill(w.marker.begin(), w.marker.end(), -1);
  }

  const double delta = st.static_regularisation;
  // Assembles the reduced matrix for the current scaling into the structured LDL' storage.
  // V = W_k^-1 G_k restricted to the columns block k touches (dim x nc, row-major, in vbuf).
  const auto scaled_block = [&](int k) -> double* {
    const int r0 = w.nt.block_start(k);
    const int dim = w.nt.block_dim(k);
    const int c0 = w.bc_ptr[k];
    const int nc = w.bc_ptr[k + 1] - c0;
    double* v = w.vbuf.data();
    std::fill(v, v + dim * nc, 0.0);
    for (int a = 0; a < nc; ++a) w.pos[w.bc_col[c0 + a]] = a;
    for (int r = 0; r < dim; ++r) {
      for (int e = w.G.ptr[r0 + r]; e < w.G.ptr[r0 + r + 1]; ++e) v[r * nc + w.pos[w.G.col[e]]] = w.G.val[e];
    }
    for (int a = 0; a < nc; ++a) w.nt.apply_inverse_block(k, v + a, v + a, nc);
    return v;
  };
  // y rows -= A_k H_k^-1 A_k' = U'U, U = W_k G_k^-T A_k' (dim x p, row-major in ubuf).
  const auto eliminate_separable = [&](int k) {
    const int r0 = w.nt.block_start(k);
    const int dim = w.nt.block_dim(k);
    double* u = w.ubuf.data();
    const double* ak = w.sep_ak.data() + static_cast<std::size_t>(r0 * p);
    for (int i = 0; i < p; ++i) w.nt.apply_block(k, ak + i, u + i, p);
    for (int i = 0; i < p; ++i) {
      for (int i2 = 0; i2 <= i; ++i2) {
        double sum = 0.0;
        for (int r = 0; r < dim; ++r) sum += u[r * p + i] * u[r * p + i2];
        ldl.at(n + i, n + i2) -= sum;
      }
    }
  };
  const auto assemble_kkt = [&]() {
    ldl.clear_values();
    for (int j = 0; j < n; ++j) ldl.at(j, j) = w.sep_col[j] != 0 ? 1.0 : delta;
    for (int i = 0; i < w.P.rows; ++i) {
      for (int e = w.P.ptr[i]; e < w.P.ptr[i + 1]; ++e) {
        if (w.P.col[e] <= i) ldl.at(i, w.P.col[e]) += w.P.val[e];
      }
    }
    for (int i = 0; i < p; ++i) {
      ldl.at(n + i, n + i) = -delta;
      for (int e = w.A.ptr[i]; e < w.A.ptr[i + 1]; ++e) {
        if (w.sep_col[w.A.col[e]] == 0) ldl.at(n + i, w.A.col[e]) += w.A.val[e];
      }
    }
    for (int k = 0; k < blocks; ++k) {
      const int dim = w.nt.block_dim(k);
      const int c0 = w.bc_ptr[k];
      const int nc = w.bc_ptr[k + 1] - c0;
      if (nc == 0) continue;
      if (w.sep_block[k] != 0) {
        eliminate_separable(k);
        continue;
      }
      const double* v = scaled_block(k);
      for (int a = 0; a < nc; ++a) {
        for (int bb = 0; bb <= a; ++bb) {
          double sum = 0.0;
          for (int r = 0; r < dim; ++r) sum += v[r * nc + a] * v[r * nc + bb];
          ldl.at(w.bc_col[c0 + a], w.bc_col[c0 + bb]) += sum;
        }
      }
    }
  };
  // The same reduced matrix, unreduced by the elimination, into the dense fallback storage.
  const auto assemble_dense = [&]() {
    Eigen::MatrixXd& K = w.dense;
    K.setZero();
    for (int j = 0; j < n; ++j) K(j, j) = delta;
    for (int i = 0; i < w.P.rows; ++i) {
      for (int e = w.P.ptr[i]; e < w.P.ptr[i + 1]; ++e) K(i, w.P.col[e]) += w.P.val[e];
    }
    for (int i = 0; i < p; ++i) {
      K(n + i, n + i) = -delta;
      for (int e = w.A.ptr[i]; e < w.A.ptr[i + 1]; ++e) {
        K(n + i, w.A.col[e]) += w.A.val[e];
        K(w.A.col[e], n + i) += w.A.val[e];
      }
    }
    for (int k = 0; k < blocks; ++k) {
      const int dim = w.nt.block_dim(k);
      const int c0 = w.bc_ptr[k];
      const int nc = w.bc_ptr[k + 1] - c0;
      if (nc == 0) continue;
      const double* v = scaled_block(k);
      for (int a = 0; a < nc; ++a) {
        for (int bb = 0; bb < nc; ++bb) {
          double sum = 0.0;
          for (int r = 0; r < dim; ++r) sum += v[r * nc + a] * v[r * nc + bb];
          K(w.bc_col[c0 + a], w.bc_col[c0 + bb]) += sum;
        }
      }
    }
  };
  // Switches this iteration to the dense LU with partial pivoting of the same reduced matrix: the
  // row exchanges pick A entries over the tiny, cancellation-made pivots that H takes near the
  // optimum (H then has one tiny eigenvalue per active cone), which the fixed-order LDL' must
  // accept or regularise. False on breakdown.
  const auto factor_dense = [&]() -> bool {
    assemble_dense();
    w.lu.compute(w.dense);
    w.use_lu = true;
    w.use_schur = false;
    ++w.fallbacks;
    const auto diagonal = w.lu.matrixLU().diagonal();
    return diagonal.allFinite() && diagonal.cwiseAbs().minCoeff() > 0.0;
  };
  // Factors: the Schur complement when every column is separable, else the structured LDL';
  // the dense LU when either fails (S singular, a pivot regularised). False on breakdown.
  const auto factor_kkt = [&]() -> bool {
    w.use_lu = false;
    w.use_schur = w.all_separable && w.schur.factor(w.nt);
    if (w.use_schur) return true;
    if (w.all_separable) return factor_dense();
    assemble_kkt();
    const int regularised = ldl.factor(st.dynamic_epsilon, st.dynamic_delta);
    if (regularised == 0) return true;
    return factor_dense();
  };

  // out = W^-2 in block by block, on the blocks of the LDL' (all of them when the dense LU is in
  // use); the separable blocks' rows, solved in closed form, get 0.
  const auto inverse_square = [&](const double* in, double* out) {
    for (int k = 0; k < blocks; ++k) {
      const int r0 = w.nt.block_start(k);
      const int dim = w.nt.block_dim(k);
      if (w.sep_block[k] != 0 && !w.use_lu) {
        std::fill(out + r0, out + r0 + dim, 0.0);
        continue;
      }
      w.nt.apply_inverse_square_block(k, in + r0, out + r0);
    }
  };
  // Separable block k of the unreduced system (its columns C, A_C the columns of A, g = G_k^-T bx_C
  // and ak = G_k^-T A_C', both by row r: divide by g_r):
  //   G_k'z_k + A_C'y = bx_C,  G_k x_C - W_k^2 z_k = bz_k
  //   =>  z_k = g - ak y,  x_C = G_k^-1 (bz_k + W_k^2 z_k),
  // and its share of the y rows, A_C x_C = ak'(bz_k + W_k^2 g) - U'U y, moves to the right side
  // before the LDL' solve. No W^-2 appears, so nothing of W's condition is squared.
  const auto separable_forward = [&](const double* bz, double* red) {
    double* g = w.sep_in.data();
    double* out = w.sep_out.data();
    for (int k = 0; k < blocks; ++k) {
      if (w.sep_block[k] == 0) continue;
      const int r0 = w.nt.block_start(k);
      const int dim = w.nt.block_dim(k);
      for (int r = 0; r < dim; ++r) g[r] = red[w.sep_gcol[r0 + r]] * w.sep_ginv[r0 + r];
      w.nt.apply_square_block(k, g, out);
      for (int r = 0; r < dim; ++r) {
        const double* ak = w.sep_ak.data() + static_cast<std::size_t>((r0 + r) * p);
        const double v = bz[r0 + r] + out[r];
        for (int i = 0; i < p; ++i) red[n + i] -= ak[i] * v;
      }
    }
  };
  // After the LDL' solve (red[C] still holds bx_C: unit pivots, no coupling): x_C into red, z_k
  // into oz.
  const auto separable_backward = [&](const double* bz, double* red, double* oz) {
    double* out = w.sep_out.data();
    for (int k = 0; k < blocks; ++k) {
      if (w.sep_block[k] == 0) continue;
      const int r0 = w.nt.block_start(k);
      const int dim = w.nt.block_dim(k);
      for (int r = 0; r < dim; ++r) {
        const double* ak = w.sep_ak.data() + static_cast<std::size_t>((r0 + r) * p);
        oz[r0 + r] = red[w.sep_gcol[r0 + r]] * w.sep_ginv[r0 + r] - dot(ak, red + n, p);
      }
      w.nt.apply_square_block(k, oz + r0, out);
      for (int r = 0; r < dim; ++r) red[w.sep_gcol[r0 + r]] = (bz[r0 + r] + out[r]) * w.sep_ginv[r0 + r];
    }
  };

  // One solve of the regularised reduced system for the right side (bx, by, bz) of
  //   [0 A' G'; A 0 0; G 0 -W^2] (ox, oy, oz) = (bx, by, bz):
  //   (G'W^-2 G) ox + A'oy = bx + G'W^-2 bz,  A ox = by,  oz = W^-2 (G ox - bz),
  // the separable blocks in closed form (separable_forward / separable_backward) unless the
  // dense LU is in use.
  const auto reduced_solve = [&](const double* bx, const double* by, const double* bz, double* ox,
                                 double* oy, double* oz) {
    if (w.use_schur) {
      w.schur.solve(w.nt, bx, by, bz, ox, oy, oz);
      return;
    }
    inverse_square(bz, w.tmp_s.data());
    double* red = w.red.data();
    for (int j = 0; j < n; ++j) red[j] = bx[j];
    w.G.multiply_transpose_add(w.tmp_s.data(), red);
    for (int i = 0; i < p; ++i) red[n + i] = by[i];
    if (w.use_lu) {
      for (int i = 0; i < n + p; ++i) w.lu_rhs(i) = red[i];
      w.lu_sol.noalias() = w.lu.solve(w.lu_rhs);
      for (int i = 0; i < n + p; ++i) red[i] = w.lu_sol(i);
    } else {
      separable_forward(bz, red);
      ldl.solve(red);
      separable_backward(bz, red, oz);
    }
    for (int j = 0; j < n; ++j) ox[j] = red[j];
    for (int i = 0; i < p; ++i) oy[i] = red[n + i];
    // oz = W^-2 (G ox - bz) on the other blocks (the separable rows of G ox are not needed).
    for (int k = 0; k < blocks; ++k) {
      if (w.sep_block[k] != 0 && !w.use_lu) continue;
      const int r0 = w.nt.block_start(k);
      const int dim = w.nt.block_dim(k);
      for (int r = r0; r < r0 + dim; ++r) {
        double v = -bz[r];
        for (int e = w.G.ptr[r]; e < w.G.ptr[r + 1]; ++e) v += w.G.val[e] * ox[w.G.col[e]];
        w.tmp_s[r] = v;
      }
      w.nt.apply_inverse_square_block(k, w.tmp_s.data() + r0, oz + r0);
    }
  };

  // (ex, ey, ez) = (bx, by, bz) - K (ox, oy, oz), K the unregularised, unreduced KKT matrix.
  const auto kkt_residual = [&](const double* bx, const double* by, const double* bz, const double* ox,
                                const double* oy, const double* oz) {
    w.P.multiply(ox, w.ex.data());
    if (w.P.rows == 0) std::fill(w.ex.begin(), w.ex.end(), 0.0);
    w.A.multiply_transpose_add(oy, w.ex.data());
    w.G.multiply_transpose_add(oz, w.ex.data());
    for (int j = 0; j < n; ++j) w.ex[j] = bx[j] - w.ex[j];
    w.A.multiply(ox, w.ey.data());
    for (int i = 0; i < p; ++i) w.ey[i] = by[i] - w.ey[i];
    w.nt.apply_square(oz, w.tmp_s.data());
    w.G.multiply(ox, w.ez.data());
    for (int i = 0; i < m; ++i) w.ez[i] = bz[i] - (w.ez[i] - w.tmp_s[i]);
  };
  // Solve with iterative refinement against the exact, unregularised, unreduced system.
  const auto refined_solve = [&](const double* bx, const double* by, const double* bz, double* ox,
                                 double* oy, double* oz) -> double {
    reduced_solve(bx, by, bz, ox, oy, oz);
    const double scale = std::max({norm_inf(bx, n), norm_inf(by, p), norm_inf(bz, m), 1e-300});
    double err = 0.0;
    for (int step = 0; step <= st.refinement_steps; ++step) {
      // e = rhs - K o.
      if (w.use_schur) {
        w.schur.residual(w.nt, bx, by, bz, ox, oy, oz, w.ex.data(), w.ey.data(), w.ez.data());
      } else {
        kkt_residual(bx, by, bz, ox, oy, oz);
      }
      const double previous = err;
      err = std::max({norm_inf(w.ex.data(), n), norm_inf(w.ey.data(), p), norm_inf(w.ez.data(), m)}) / scale;
      // Stop at working accuracy, at the step cap, or once a step no longer halves the residual.
      if (!(err > st.refinement_tolerance) || step == st.refinement_steps || (step > 0 && err > 0.5 * previous)) break;
      reduced_solve(w.ex.data(), w.ey.data(), w.ez.data(), w.kx.data(), w.ky.data(), w.kz.data());
      for (int j = 0; j < n; ++j) ox[j] += w.kx[j];
      for (int i = 0; i < p; ++i) oy[i] += w.ky[i];
      for (int i = 0; i < m; ++i) oz[i] += w.kz[i];
    }
    return err;
  };
  // Refined solve; if the structured factorisation leaves a relative residual above
  // kRefineTarget, the iteration switches to the dense LU and solves again.
  constexpr double kRefineTarget = 1e-6;
  const auto kkt_solve = [&](const double* bx, const double* by, const double* bz, double* ox,
                             double* oy, double* oz) {
    const double err = refined_solve(bx, by, bz, ox, oy, oz);
    if ((err > kRefineTarget || !std::isfinite(err)) && !w.use_lu && factor_dense()) {
      refined_solve(bx, by, bz, ox, oy, oz);
    }
  };

  ConicInfo info;
  const auto finish = [&](ConicStatus status, int iterations) -> ConicInfo {
    info.status = status;
    info.iterations = iterations;
    info.dense_fallbacks = w.fallbacks;
    x_out_.setZero();
    y_out_.setZero();
    z_out_.setZero();
    s_out_.setZero();
    const double inf = std::numeric_limits<double>::infinity();
    if (status == ConicStatus::primal_infeasible) {
      const double scale = -(dot(w.b.data(), w.y.data(), p) + dot(w.h.data(), w.z.data(), m));
      for (int i = 0; i < p; ++i) y_out_(i) = w.erow[i] * w.y[i] / scale;
      for (int i = 0; i < m; ++i) z_out_(i) = w.frow[i] * w.z[i] / scale;
      info.primal_objective = inf;
      info.dual_objective = inf;
      return info;
    }
    if (status == ConicStatus::dual_infeasible) {
      const double scale = -dot(w.c.data(), w.x.data(), n);
      for (int j = 0; j < n; ++j) x_out_(j) = w.dcol[j] * w.x[j] / scale;
      for (int i = 0; i < m; ++i) s_out_(i) = w.s[i] / w.frow[i] / scale;
      info.primal_objective = -inf;
      info.dual_objective = -inf;
      return info;
    }
    const double t = w.tau;
    for (int j = 0; j < n; ++j) x_out_(j) = w.dcol[j] * w.x[j] / t;
    for (int i = 0; i < p; ++i) y_out_(i) = w.erow[i] * w.y[i] / t;
    for (int i = 0; i < m; ++i) {
      z_out_(i) = w.frow[i] * w.z[i] / t;
      s_out_(i) = w.s[i] / w.frow[i] / t;
    }
    double objective = 0.0;
    for (int j = 0; j < n; ++j) objective += problem.c(j) * x_out_(j);
    if (dims_.quadratic) {
      double quad = 0.0;
      for (int i = 0; i < n; ++i) {
        double row = 0.0;
        for (int j = 0; j < n; ++j) row += problem.P(i, j) * x_out_(j);
        quad += x_out_(i) * row;
      }
      objective += 0.5 * quad;
    }
    info.primal_objective = objective;
    // Dual objective of the QP: -(1/2) x'Px - b'y - h'z (x'Px = 2 (objective - c'x)).
    double cx_out = 0.0;
    for (int j = 0; j < n; ++j) cx_out += problem.c(j) * x_out_(j);
    info.dual_objective = -(objective - cx_out) -
                          (dot(w.b.data(), w.y.data(), p) + dot(w.h.data(), w.z.data(), m)) / t;
    return info;
  };

  // ---- Starting point with W = I (Vandenberghe 2010 sec. 7.2 for conelp; sec. 7.3 for coneqp):
  // LP/SOCP: x minimises ||Gx - h|| s.t. Ax = b with s = h - Gx, and (y, z) minimise ||z|| s.t.
  // A'y + G'z + c = 0. QP: one solve of [P A' G'; A 0 0; G 0 -I] (x, y, z) = (-c, b, h), s = -z.
  // Then s and z are shifted into the interior of K along e.
  w.nt.set_identity();
  w.fallbacks = 0;
  if (!factor_kkt()) return finish(ConicStatus::numerical_error, 0);
  if (dims_.quadratic) {
    for (int j = 0; j < n; ++j) w.bx[j] = -w.c[j];
    kkt_solve(w.bx.data(), w.b.data(), w.h.data(), w.x.data(), w.y.data(), w.z.data());
    for (int i = 0; i < m; ++i) w.s[i] = -w.z[i];
  } else {
    for (int j = 0; j < n; ++j) w.bx[j] = 0.0;
    kkt_solve(w.bx.data(), w.b.data(), w.h.data(), w.x.data(), w.y1.data(), w.z1.data());
    for (int i = 0; i < m; ++i) w.s[i] = -w.z1[i];
    for (int j = 0; j < n; ++j) w.bx[j] = -w.c[j];
    for (int i = 0; i < p; ++i) w.by[i] = 0.0;
    for (int i = 0; i < m; ++i) w.bz[i] = 0.0;
    kkt_solve(w.bx.data(), w.by.data(), w.bz.data(), w.x1.data(), w.y.data(), w.z.data());
  }
  for (Vec* v : {&w.s, &w.z}) {
    const double shift = -w.cone.interior_margin(v->data());
    if (shift >= -1e-8 * std::max(1.0, norm2(v->data(), m))) w.cone.add_identity(v->data(), 1.0 + shift);
  }
  w.tau = 1.0;
  w.kappa = 1.0;

  const int nu = w.cone.degree();
  const double frac = st.step_fraction;
  for (int iter = 0;; ++iter) {
    // Residuals of the embedding (scaled data; Goulart & Chen 2024, "Clarabel: an interior-point
    // solver for conic programs with quadratic objectives", eq. (8), for the x'Px/tau term):
    //   rx = Px + A'y + G'z + c tau, ry = A x - b tau, rz = s + G x - h tau,
    //   rt = kappa + c'x + b'y + h'z + x'Px / tau.
    if (w.P.rows > 0) w.P.multiply(w.x.data(), w.px.data());
    const double xpx = w.P.rows > 0 ? dot(w.x.data(), w.px.data(), n) : 0.0;
    std::fill(w.hx.begin(), w.hx.end(), 0.0);
    w.A.multiply_transpose_add(w.y.data(), w.hx.data());
    w.G.multiply_transpose_add(w.z.data(), w.hx.data());
    w.A.multiply(w.x.data(), w.ax.data());
    w.G.multiply(w.x.data(), w.gxs.data());
    for (int i = 0; i < m; ++i) w.gxs[i] += w.s[i];
    for (int j = 0; j < n; ++j) w.rx[j] = w.hx[j] + w.c[j] * w.tau + (w.P.rows > 0 ? w.px[j] : 0.0);
    for (int i = 0; i < p; ++i) w.ry[i] = w.ax[i] - w.b[i] * w.tau;
    for (int i = 0; i < m; ++i) w.rz[i] = w.gxs[i] - w.h[i] * w.tau;
    const double cx = dot(w.c.data(), w.x.data(), n);
    const double by = dot(w.b.data(), w.y.data(), p);
    const double hz = dot(w.h.data(), w.z.data(), m);
    const double sz = dot(w.s.data(), w.z.data(), m);
    const double rt = w.kappa + cx + by + hz + xpx / w.tau;
    // Norms on the unscaled problem: rx_orig = D^-1 rx, ry_orig = E^-1 ry, rz_orig = F^-1 rz.
    const auto unscaled = [](const double* v, const double* scale, int len, bool divide) {
      double sum = 0.0;
      for (int i = 0; i < len; ++i) {
        const double u = divide ? v[i] / scale[i] : v[i] * scale[i];
        sum += u * u;
      }
      return std::sqrt(sum);
    };
    const double nrx = unscaled(w.rx.data(), w.dcol.data(), n, true);
    const double nry = unscaled(w.ry.data(), w.erow.data(), p, true);
    const double nrz = unscaled(w.rz.data(), w.frow.data(), m, true);
    const double quad = 0.5 * xpx / (w.tau * w.tau);  // (1/2) xi'P xi, xi = x / tau
    const double pcost = quad + cx / w.tau;
    const double dcost = -quad - (by + hz) / w.tau;
    const double gap = sz / (w.tau * w.tau);
    const double pres = std::max(nry / w.bnorm, nrz / w.hnorm) / w.tau;
    const double dres = nrx / w.cnorm / w.tau;
    double relgap = std::numeric_limits<double>::infinity();
    if (pcost < 0.0) relgap = gap / -pcost;
    else if (dcost > 0.0) relgap = gap / dcost;
    info.primal_residual = pres;
    info.dual_residual = dres;
    info.gap = gap;
    if (!std::isfinite(pres) || !std::isfinite(dres) || !std::isfinite(gap) || !std::isfinite(rt)) {
      return finish(ConicStatus::numerical_error, iter);
    }
    if (pres <= st.feasibility_tolerance && dres <= st.feasibility_tolerance &&
        (gap <= st.absolute_gap_tolerance || relgap <= st.relative_gap_tolerance)) {
      return finish(ConicStatus::optimal, iter);
    }
    if (hz + by < 0.0) {
      const double pinf = unscaled(w.hx.data(), w.dcol.data(), n, true) / w.cnorm / -(hz + by);
      if (pinf <= st.feasibility_tolerance) return finish(ConicStatus::primal_infeasible, iter);
    }
    if (cx < 0.0) {
      const double pray = w.P.rows > 0 ? unscaled(w.px.data(), w.dcol.data(), n, true) / w.cnorm : 0.0;
      const double dinf = std::max({unscaled(w.ax.data(), w.erow.data(), p, true) / w.bnorm,
                                    unscaled(w.gxs.data(), w.frow.data(), m, true) / w.hnorm, pray}) / -cx;
      if (dinf <= st.feasibility_tolerance) return finish(ConicStatus::dual_infeasible, iter);
    }
    if (iter >= st.max_iterations) return finish(ConicStatus::max_iterations, iter);

    // Scaling and factorisation for this iteration.
    if (!w.nt.update(w.s.data(), w.z.data(), w.lambda.data())) return finish(ConicStatus::numerical_error, iter);
    if (!factor_kkt()) return finish(ConicStatus::numerical_error, iter);
    const double mu = (sz + w.tau * w.kappa) / (nu + 1);

    // u1 = K^-1 (-c, b, h): the tau column of the embedding (Vandenberghe 2010 sec. 7.3). The
    // linearised tau row has coefficients q = (c + 2 P xi, b, h) and -(kappa/tau + xi'P xi).
    for (int j = 0; j < n; ++j) w.bx[j] = -w.c[j];
    kkt_solve(w.bx.data(), w.b.data(), w.h.data(), w.x1.data(), w.y1.data(), w.z1.data());
    const auto q_dot = [&](const double* dx, const double* dy, const double* dz) {
      double v = dot(w.c.data(), dx, n) + dot(w.b.data(), dy, p) + dot(w.h.data(), dz, m);
      if (w.P.rows > 0) v += 2.0 / w.tau * dot(w.px.data(), dx, n);
      return v;
    };
    // Denominator of dtau, q'u1 - kappa/tau - xi'P xi, in the cancellation-free form
    // -(x1 - xi)'P(x1 - xi) - ||W z1||^2 - kappa/tau (substitute K u1 = (-c, b, h) into q'u1):
    // near the optimum x1 -> xi and the direct difference loses every digit.
    double denom = -w.kappa / w.tau;
    w.nt.apply(w.z1.data(), w.tmp_z.data());
    denom -= dot(w.tmp_z.data(), w.tmp_z.data(), m);
    if (w.P.rows > 0) {
      for (int j = 0; j < n; ++j) w.dxi[j] = w.x1[j] - w.x[j] / w.tau;
      w.P.multiply(w.dxi.data(), w.pdxi.data());
      denom -= dot(w.dxi.data(), w.pdxi.data(), n);
    }

    // Newton system, with rs the target of lambda o (W dz + W^-T ds) and rk that of
    // kappa dtau + tau dkappa:
    //   K (dx, dy, dz) + dtau (c, -b, -h) = (-eta rx, -eta ry, -eta rz - W (lambda \ rs))
    //   (c + 2 P xi)'dx + b'dy + h'dz - (kappa/tau + xi'P xi) dtau = -eta rt - rk / tau
    // (with K including P); dkappa = (rk - kappa dtau) / tau.
    double dtau = 0.0, dkappa = 0.0;
    const auto direction = [&](double eta, double rk) -> bool {
      w.cone.divide(w.lambda.data(), w.rs.data(), w.dzs.data());  // dzs = lambda \ rs (temporary)
      w.nt.apply(w.dzs.data(), w.bz.data());
      for (int i = 0; i < m; ++i) w.bz[i] = -eta * w.rz[i] - w.bz[i];
      for (int j = 0; j < n; ++j) w.bx[j] = -eta * w.rx[j];
      for (int i = 0; i < p; ++i) w.by[i] = -eta * w.ry[i];
      kkt_solve(w.bx.data(), w.by.data(), w.bz.data(), w.x2.data(), w.y2.data(), w.z2.data());
      const double at = -eta * rt - rk / w.tau;
      const double qu2 = q_dot(w.x2.data(), w.y2.data(), w.z2.data());

      dtau = (at - qu2) / denom;
      if (!std::isfinite(dtau)) return false;
      for (int j = 0; j < n; ++j) w.x2[j] += dtau * w.x1[j];
      for (int i = 0; i < p; ++i) w.y2[i] += dtau * w.y1[i];
      for (int i = 0; i < m; ++i) w.z2[i] += dtau * w.z1[i];
      dkappa = (rk - w.kappa * dtau) / w.tau;
      // ds from the primal rows, ds = -eta rz - G dx + h dtau (equal in exact arithmetic to
      // W (lambda \ rs - W dz), but free of the W^2-sized roundoff of that form, so the primal
      // residual contracts by exactly 1 - alpha eta); kept unscaled in ds_full.
      w.G.multiply(w.x2.data(), w.ds_full.data());
      for (int i = 0; i < m; ++i) w.ds_full[i] = -eta * w.rz[i] - w.ds_full[i] + w.h[i] * dtau;
      // Scaled directions: dz~ = W dz, ds~ = W^-1 ds.
      w.nt.apply(w.z2.data(), w.dzs.data());
      w.nt.apply_inverse(w.ds_full.data(), w.ds.data());
      return true;
    };
    const auto step_to_boundary = [&](double cap) {
      double a = w.cone.max_step(w.lambda.data(), w.ds.data(), cap);
      a = w.cone.max_step(w.lambda.data(), w.dzs.data(), a);
      if (dtau < 0.0) a = std::min(a, -w.tau / dtau);
      if (dkappa < 0.0) a = std::min(a, -w.kappa / dkappa);
      return a;
    };

    // Predictor (affine scaling): rs = -lambda o lambda, rk = -tau kappa, eta = 1.
    w.cone.product(w.lambda.data(), w.lambda.data(), w.rs.data());
    for (int i = 0; i < m; ++i) w.rs[i] = -w.rs[i];
    if (!direction(1.0, -w.tau * w.kappa)) return finish(ConicStatus::numerical_error, iter);
    const double alpha_aff = step_to_boundary(1.0);
    const double sigma = std::pow(std::clamp(1.0 - alpha_aff, 0.0, 1.0), 3.0);
    for (int i = 0; i < m; ++i) {
      w.ds_aff[i] = w.ds[i];
      w.dz_aff[i] = w.dzs[i];
    }
    const double dtau_aff = dtau, dkappa_aff = dkappa;

    // Corrector (Mehrotra): rs = -lambda o lambda + sigma mu e - ds_aff o dz_aff,
    // rk = -tau kappa + sigma mu - dtau_aff dkappa_aff, eta = 1 - sigma.
    w.cone.product(w.ds_aff.data(), w.dz_aff.data(), w.tmp_s.data());
    w.cone.product(w.lambda.data(), w.lambda.data(), w.rs.data());
    for (int i = 0; i < m; ++i) w.rs[i] = -w.rs[i] - w.tmp_s[i];
    w.cone.add_identity(w.rs.data(), sigma * mu);
    if (!direction(1.0 - sigma, -w.tau * w.kappa + sigma * mu - dtau_aff * dkappa_aff)) {
      return finish(ConicStatus::numerical_error, iter);
    }
    const double alpha = std::min(1.0, frac * step_to_boundary(1e30));
    if (!(alpha > 0.0)) return finish(ConicStatus::numerical_error, iter);

    for (int i = 0; i < m; ++i) w.tmp_s[i] = w.ds_full[i];
    for (int j = 0; j < n; ++j) w.x[j] += alpha * w.x2[j];
    for (int i = 0; i < p; ++i) w.y[i] += alpha * w.y2[i];
    for (int i = 0; i < m; ++i) {
      w.z[i] += alpha * w.z2[i];
      w.s[i] += alpha * w.tmp_s[i];
    }
    w.tau += alpha * dtau;
    w.kappa += alpha * dkappa;
  }
}

}  // namespace visors::optim
