#include "visors/optim/conic_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/LU>

#include "visors/optim/cone.hpp"
#include "visors/optim/quasidefinite_ldl.hpp"
#include "visors/optim/separable_kkt.hpp"

// Reading guide. ConicSolver::solve (at the end of this file) is the interior-point iteration;
// every step of it is one member function of ConicSolver::Workspace, defined in the order solve
// calls them:
//   load -> equilibrate -> analyse_kkt -> initial_point ->
//   loop { compute_residuals, check_termination, update_scaling, factor_kkt, solve_tau_column,
//          predictor, corrector, step_length, take_step } -> unscale.
// The KKT machinery the phases share (assembly, factorisation, solve with refinement) sits
// between the analysis and the initial point.

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

// ||S^-1 v|| for the diagonal scaling S = diag(scale): the norm of a scaled-problem residual
// measured on the unscaled problem (rx_orig = D^-1 rx, ry_orig = E^-1 ry, rz_orig = F^-1 rz).
double unscaled_norm(const double* v, const double* scale, int len) {
  double sum = 0.0;
  for (int i = 0; i < len; ++i) {
    const double u = v[i] / scale[i];
    sum += u * u;
  }
  return std::sqrt(sum);
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

std::string_view to_string(ConicStatus status) {
  switch (status) {
    case ConicStatus::kOptimal: return "optimal";
    case ConicStatus::kPrimalInfeasible: return "primal_infeasible";
    case ConicStatus::kDualInfeasible: return "dual_infeasible";
    case ConicStatus::kMaxIterations: return "max_iterations";
    case ConicStatus::kNumericalError: return "numerical_error";
  }
  return "numerical_error";
}

// Internal problem: the equilibrated data
//   minimise (1/2) x'Px + c'x  s.t.  A x = b,  G x + s = h,  s in K
// with x = D xs, y = E ys, z = F zs, s = F^{-1} ss between original and scaled variables.
// Everything solve() touches lives here, sized by the constructor; the member functions are the
// phases of solve(), none of which allocates.
struct ConicSolver::Workspace {
  Workspace(const ConicDimensions& dims, const ConicSettings& conic_settings);

  // ---- Phases of solve(), in call order.
  /// Problem data, unscaled, into sparse rows, and the norms of the stopping tests. False (and
  /// nothing loaded) when P is not positive semidefinite.
  bool load(const ConicProblem& problem);
  /// Ruiz equilibration of [A; G] (and P's columns), then scaling of c, b, h.
  void equilibrate();
  /// Block/column structure of the reduced KKT matrix: separable blocks, then either the Schur
  /// complement (every column separable) or the LDL' symbolic analysis.
  void analyse_kkt();
  /// Starting point with W = I; false when the first factorisation breaks down.
  bool initial_point();
  /// Residuals of the homogeneous embedding at the current iterate.
  void compute_residuals();
  /// Stopping tests; also records the stopping quantities in `info`.
  [[nodiscard]] std::optional<ConicStatus> check_termination(int iteration, ConicInfo& info) const;
  /// Nesterov-Todd scaling at the current (s, z); false if either left the interior.
  bool update_scaling();
  /// Factors the KKT matrix for the current scaling (Schur, structured LDL' or dense LU).
  bool factor_kkt();
  /// mu, u1 = K^-1 (-c, b, h) and the dtau denominator, shared by predictor and corrector.
  void solve_tau_column();
  /// Affine-scaling direction, its step to the boundary and Mehrotra's sigma.
  bool predictor();
  /// Combined (centring + second-order correction) direction.
  bool corrector();
  /// Step length along the combined direction: a fraction of the distance to the boundary.
  [[nodiscard]] double step_length() const;
  /// Moves the iterate (x, y, z, s, tau, kappa) by alpha along the combined direction.
  void take_step(double alpha);
  /// Outputs in the original variables (iterate / tau, or a normalised certificate).
  void unscale(ConicStatus status, const ConicProblem& problem, ConicInfo& info, Eigen::VectorXd& x_out,
               Eigen::VectorXd& y_out, Eigen::VectorXd& z_out, Eigen::VectorXd& s_out) const;

  // ---- Helpers of the phases.
  void mark_block_columns();
  void find_separable_blocks();
  void analyse_schur();
  void analyse_ldl();
  double* scaled_block(int k);
  void eliminate_separable(int k);
  void assemble_kkt();
  void assemble_dense();
  bool factor_dense();
  void inverse_square(const double* in, double* out) const;
  void separable_forward(const double* bz, double* red);
  void separable_backward(const double* bz, double* red, double* oz);
  void reduced_solve(const double* bx, const double* by, const double* bz, double* ox, double* oy, double* oz);
  void kkt_residual(const double* bx, const double* by, const double* bz, const double* ox, const double* oy,
                    const double* oz);
  double refined_solve(const double* bx, const double* by, const double* bz, double* ox, double* oy, double* oz);
  void kkt_solve(const double* bx, const double* by, const double* bz, double* ox, double* oy, double* oz);
  [[nodiscard]] double q_dot(const double* dx, const double* dy, const double* dz) const;
  bool direction(double eta, double rk);
  [[nodiscard]] double step_to_boundary(double cap) const;
  void unscale_iterate(const ConicProblem& problem, ConicInfo& info, Eigen::VectorXd& x_out, Eigen::VectorXd& y_out,
                       Eigen::VectorXd& z_out, Eigen::VectorXd& s_out) const;

  // ---- Dimensions, settings, cone.
  int n = 0, p = 0, m = 0;  // original
  int blocks = 0;           // cone blocks: one per orthant row, one per SOC
  bool quadratic = false;
  ConicSettings settings;
  ConeProduct cone;
  NtScaling nt;
  // ---- Scaled problem data and the Ruiz scalings.
  Csr G, A, P;
  Vec c, h, b;
  double cnorm = 1.0, bnorm = 1.0, hnorm = 1.0;  // max(1, ||.||) of the unscaled c, b, h
  Vec dcol, erow, frow;                          // Ruiz scalings D, E, F
  Vec colmax, rowmax, blockmax;
  std::vector<int> block_of_row;
  Vec pwork, rfac;  // PSD check of P: work copy and pivoted Cholesky factor R (P = R'R)
  std::vector<unsigned char> pdone;
  // ---- KKT structure: the columns each block touches (bc_ptr / bc_col), scratch.
  QuasiDefiniteLdl ldl;
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
  // Fallback when the structured LDL' needed dynamic regularisation or its refinement stalled:
  // dense LU with partial pivoting of the same reduced matrix (backward stable for any
  // ordering; Golub & Van Loan alg. 3.4.1). Sized at setup.
  Eigen::MatrixXd dense;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd lu_rhs, lu_sol;
  bool use_lu = false;
  int fallbacks = 0;  // iterations that used the dense LU
  // ---- Iterate, residuals and directions.
  Vec x, y, z, s, lambda, px, dxi, pdxi;
  double tau = 1.0, kappa = 1.0;
  Vec hx, ax, gxs, rx, ry, rz;
  Vec x1, y1, z1, x2, y2, z2;  // KKT solutions for (-c, b, h) and the step
  Vec ds_aff, dz_aff, tmp_s, tmp_z, ds, dzs, rs, ds_full;
  Vec rhs_x, rhs_y, rhs_z;  // KKT right sides
  Vec ex, ey, ez;           // KKT residuals of the refinement
  Vec kx, ky, kz;           // refinement corrections
  Vec reduced;              // right side / solution of the reduced system
  // Scalars of the embedding at the current iterate (compute_residuals): x'Px, c'x, b'y, h'z,
  // s'z and the residual rt of the tau row.
  double xpx = 0.0, ctx = 0.0, bty = 0.0, htz = 0.0, stz = 0.0, rt = 0.0;
  // Scalars of the current Newton step: mu, the dtau denominator, the last direction's
  // (dtau, dkappa), the predictor's copies and Mehrotra's sigma.
  double mu = 0.0, denom = 0.0, dtau = 0.0, dkappa = 0.0, dtau_aff = 0.0, dkappa_aff = 0.0, sigma = 0.0;
};

// Sizes every buffer solve() uses, for problems of dimensions `dims`: the phases allocate nothing.
ConicSolver::Workspace::Workspace(const ConicDimensions& dims, const ConicSettings& conic_settings)
    : n(dims.n), p(dims.p), m(dims.m()), quadratic(dims.quadratic), settings(conic_settings) {
  cone = ConeProduct(dims.l, dims.q);
  nt = NtScaling(cone);
  blocks = nt.blocks();
  ldl = QuasiDefiniteLdl(n + p);
  if (m == n) schur = SeparableKkt(m, p);
  const int full = n + p;
  dense = Eigen::MatrixXd::Zero(full, full);
  lu = Eigen::PartialPivLU<Eigen::MatrixXd>(full);
  lu_rhs = Eigen::VectorXd::Zero(full);
  lu_sol = Eigen::VectorXd::Zero(full);
  G.reserve(m, n);
  A.reserve(p, n);
  P.reserve(quadratic ? n : 0, n);
  c = sized(n);
  h = sized(m);
  b = sized(p);
  dcol = sized(n);
  erow = sized(p);
  frow = sized(m);
  colmax = sized(n);
  rowmax = sized(p);
  blockmax = sized(blocks);
  block_of_row.assign(static_cast<std::size_t>(m) + 1, 0);
  int max_block = 1;
  for (int k = 0; k < blocks; ++k) {
    max_block = std::max(max_block, nt.block_dim(k));
    for (int r = 0; r < nt.block_dim(k); ++r) block_of_row[nt.block_start(k) + r] = k;
  }
  bc_ptr.assign(static_cast<std::size_t>(blocks) + 1, 0);
  bc_col.assign(static_cast<std::size_t>(blocks) * static_cast<std::size_t>(n) + 1, 0);
  marker.assign(static_cast<std::size_t>(n) + 1, -1);
  pos.assign(static_cast<std::size_t>(n) + 1, 0);
  vbuf = sized(max_block * n);
  sep_block.assign(static_cast<std::size_t>(blocks) + 1, 0);
  sep_col.assign(static_cast<std::size_t>(n) + 1, 0);
  col_uses.assign(static_cast<std::size_t>(n) + 1, 0);
  sep_gcol.assign(static_cast<std::size_t>(m) + 1, 0);
  sep_ginv = sized(m);
  sep_ak = sized(m * p);
  ubuf = sized(max_block * p);
  for (Vec* v : {&sep_in, &sep_out}) *v = sized(max_block);
  if (quadratic) {
    pwork = sized(n * n);
    rfac = sized(n * n);
    pdone.assign(static_cast<std::size_t>(n) + 1, 0);
  }
  for (Vec* v : {&x, &px, &dxi, &pdxi, &hx, &rx, &x1, &x2, &rhs_x, &ex, &kx}) *v = sized(n);
  for (Vec* v : {&y, &ax, &ry, &y1, &y2, &rhs_y, &ey, &ky}) *v = sized(p);
  for (Vec* v : {&z, &s, &lambda, &gxs, &rz, &z1, &z2, &ds_aff, &dz_aff, &tmp_s, &tmp_z, &ds, &dzs, &rs, &ds_full,
                 &rhs_z, &ez, &kz}) {
    *v = sized(m);
  }
  reduced = sized(n + p);
}

ConicSolver::ConicSolver(const ConicDimensions& dims, const ConicSettings& settings)
    : dims_(dims), settings_(settings), work_(std::make_unique<Workspace>(dims, settings)) {
  x_out_ = Eigen::VectorXd::Zero(work_->n);
  y_out_ = Eigen::VectorXd::Zero(work_->p);
  z_out_ = Eigen::VectorXd::Zero(work_->m);
  s_out_ = Eigen::VectorXd::Zero(work_->m);
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

// ================================================================ Problem data

// P is checked first (pivoted Cholesky, factor_psd), so a rejected P leaves the previous data in
// place. The norms are those of the unscaled data, for the stopping tests of conic_settings.hpp.
bool ConicSolver::Workspace::load(const ConicProblem& problem) {
  if (quadratic) {
    if (!factor_psd(problem.P, settings.psd_tolerance, pwork.data(), rfac.data(), pdone.data())) return false;
  }
  G.assign(problem.G);
  A.assign(problem.A);
  if (P.rows > 0) P.assign(problem.P);
  for (int i = 0; i < m; ++i) h[i] = problem.h(i);
  for (int i = 0; i < p; ++i) b[i] = problem.b(i);
  for (int j = 0; j < n; ++j) c[j] = problem.c(j);
  cnorm = std::max(1.0, norm2(c.data(), n));
  bnorm = std::max(1.0, norm2(b.data(), p));
  hnorm = std::max(1.0, norm2(h.data(), m));
  return true;
}

// Ruiz equilibration of [A; G] (Ruiz 2001, "A scaling algorithm to equilibrate both rows and
// columns norms in matrices", RAL-TR-2001-034): repeatedly divide every row and column by the
// square root of its infinity norm. A second-order cone's rows share one factor so the scaled
// cone is the same cone; P's entries take part in the column norms and get D P D.
void ConicSolver::Workspace::equilibrate() {
  std::fill(dcol.begin(), dcol.end(), 1.0);
  std::fill(erow.begin(), erow.end(), 1.0);
  std::fill(frow.begin(), frow.end(), 1.0);
  const auto root_inverse = [](double v) { return v > 0.0 ? 1.0 / std::sqrt(std::clamp(v, 1e-8, 1e8)) : 1.0; };
  for (int pass = 0; pass < settings.equilibration_passes; ++pass) {
    // Infinity norms: colmax per column, rowmax per row of A, blockmax per cone block of G.
    std::fill(colmax.begin(), colmax.end(), 0.0);
    std::fill(blockmax.begin(), blockmax.end(), 0.0);
    for (int i = 0; i < p; ++i) {
      double rmax = 0.0;
      for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) {
        const double v = std::abs(A.val[k]);
        rmax = std::max(rmax, v);
        colmax[A.col[k]] = std::max(colmax[A.col[k]], v);
      }
      rowmax[i] = rmax;
    }
    for (int i = 0; i < P.rows; ++i) {
      for (int k = P.ptr[i]; k < P.ptr[i + 1]; ++k) colmax[P.col[k]] = std::max(colmax[P.col[k]], std::abs(P.val[k]));
    }
    for (int i = 0; i < m; ++i) {
      const int blk = block_of_row[i];
      for (int k = G.ptr[i]; k < G.ptr[i + 1]; ++k) {
        const double v = std::abs(G.val[k]);
        blockmax[blk] = std::max(blockmax[blk], v);
        colmax[G.col[k]] = std::max(colmax[G.col[k]], v);
      }
    }
    // Their inverse square roots scale the data and accumulate into D, E, F.
    for (int j = 0; j < n; ++j) colmax[j] = root_inverse(colmax[j]);
    for (int i = 0; i < p; ++i) rowmax[i] = root_inverse(rowmax[i]);
    for (int k = 0; k < blocks; ++k) blockmax[k] = root_inverse(blockmax[k]);
    for (int i = 0; i < p; ++i) {
      erow[i] *= rowmax[i];
      for (int k = A.ptr[i]; k < A.ptr[i + 1]; ++k) A.val[k] *= rowmax[i] * colmax[A.col[k]];
    }
    for (int i = 0; i < m; ++i) {
      const double f = blockmax[block_of_row[i]];
      frow[i] *= f;
      for (int k = G.ptr[i]; k < G.ptr[i + 1]; ++k) G.val[k] *= f * colmax[G.col[k]];
    }
    for (int i = 0; i < P.rows; ++i) {
      for (int k = P.ptr[i]; k < P.ptr[i + 1]; ++k) P.val[k] *= colmax[i] * colmax[P.col[k]];
    }
    for (int j = 0; j < n; ++j) dcol[j] *= colmax[j];
  }
  for (int j = 0; j < n; ++j) c[j] *= dcol[j];
  for (int i = 0; i < p; ++i) b[i] *= erow[i];
  for (int i = 0; i < m; ++i) h[i] *= frow[i];
}

// ================================================================ KKT structure

// Structure of the reduced KKT matrix [G'W^-2 G + dI, A'; A, -dI]: block k of the cone couples
// the columns its rows touch (W^-1 is dense within a block).
//
// A block is separable when each of its rows has one entry of G, in distinct columns that no
// other block and no P entry touch (bounds x_j >= 0, norm cones on variables such as the
// planner's ||dv_k|| <= t_k). Its diagonal block H_k = G_k'W_k^-2 G_k then has the closed-form
// inverse G_k^-1 W_k^2 G_k^-T, and it is eliminated before the LDL': the y rows get
// -A_k H_k^-1 A_k' = -U'U with U = W_k G_k^-T A_k' (a sum of squares, no cancellation), and its
// columns become unit pivots. Forming and pivoting on H_k itself instead squares the
// condition of W_k near the optimum (eigenvalues eta^-2 (w0 +- ||w1||)^2), where the fixed-order
// LDL' would meet tiny, cancellation-made pivots.
void ConicSolver::Workspace::analyse_kkt() {
  mark_block_columns();
  find_separable_blocks();
  if (all_separable) {
    analyse_schur();
  } else {
    analyse_ldl();
  }
  std::fill(marker.begin(), marker.end(), -1);
}

// bc_col[bc_ptr[k] .. bc_ptr[k + 1]) = the columns block k touches, ascending; col_uses counts
// the blocks touching each column, plus 2 per P entry in it (so a P column is never separable).
void ConicSolver::Workspace::mark_block_columns() {
  int count = 0;
  std::fill(col_uses.begin(), col_uses.end(), 0);
  for (int k = 0; k < blocks; ++k) {
    bc_ptr[k] = count;
    const int r0 = nt.block_start(k);
    const int r1 = r0 + nt.block_dim(k);
    for (int i = r0; i < r1; ++i) {
      for (int e = G.ptr[i]; e < G.ptr[i + 1]; ++e) marker[G.col[e]] = k;
    }
    for (int j = 0; j < n; ++j) {
      if (marker[j] == k) {
        bc_col[count++] = j;
        ++col_uses[j];
      }
    }
  }
  bc_ptr[blocks] = count;
  std::fill(marker.begin(), marker.end(), -1);
  for (int i = 0; i < P.rows; ++i) {
    for (int e = P.ptr[i]; e < P.ptr[i + 1]; ++e) col_uses[P.col[e]] += 2;
  }
}

// Flags the separable blocks and their columns; per row r of such a block its column sep_gcol[r]
// and 1/g_r, and marker[column] = r (read by the analyses, cleared by analyse_kkt).
void ConicSolver::Workspace::find_separable_blocks() {
  std::fill(sep_col.begin(), sep_col.end(), 0);
  any_separable = false;
  for (int k = 0; k < blocks; ++k) {
    const int r0 = nt.block_start(k);
    const int dim = nt.block_dim(k);
    bool separable = bc_ptr[k + 1] - bc_ptr[k] == dim;
    for (int r = r0; separable && r < r0 + dim; ++r) {
      separable = G.ptr[r + 1] - G.ptr[r] == 1 && col_uses[G.col[G.ptr[r]]] == 1;
    }
    sep_block[k] = separable ? 1 : 0;
    any_separable = any_separable || separable;
    for (int r = r0; separable && r < r0 + dim; ++r) {
      sep_gcol[r] = G.col[G.ptr[r]];
      sep_ginv[r] = 1.0 / G.val[G.ptr[r]];
      sep_col[sep_gcol[r]] = 1;
      marker[sep_gcol[r]] = r;  // column -> row, for the A entries
    }
  }
  all_separable = std::all_of(sep_col.begin(), sep_col.begin() + n, [](unsigned char f) { return f != 0; });
}

// Every column separable (then m = n): the KKT solves are the p x p Schur complement of
// separable_kkt.hpp, given G's one entry per row and A by cone row.
void ConicSolver::Workspace::analyse_schur() {
  for (int r = 0; r < m; ++r) schur.set_row(r, sep_gcol[r], G.val[G.ptr[r]]);
  schur.clear_equalities();
  for (int i = 0; i < p; ++i) {
    for (int e = A.ptr[i]; e < A.ptr[i + 1]; ++e) schur.set_equality_entry(i, marker[A.col[e]], A.val[e]);
  }
}

// Symbolic LDL' of the reduced matrix: the dense coupling of each non-separable block's columns,
// A's entries in non-separable columns, a dense y-y block when any block is eliminated (its
// -U'U), P's lower triangle. A's entries in separable columns become the rows of G_k^-T A_k'.
void ConicSolver::Workspace::analyse_ldl() {
  ldl.begin_structure(n + p, n);
  for (int k = 0; k < blocks; ++k) {
    for (int a = bc_ptr[k]; sep_block[k] == 0 && a < bc_ptr[k + 1]; ++a) {
      for (int bb = bc_ptr[k]; bb <= a; ++bb) ldl.mark(bc_col[a], bc_col[bb]);
    }
  }
  std::fill(sep_ak.begin(), sep_ak.end(), 0.0);
  for (int i = 0; i < p; ++i) {
    for (int e = A.ptr[i]; e < A.ptr[i + 1]; ++e) {
      const int j = A.col[e];
      if (sep_col[j] == 0) {
        ldl.mark(n + i, j);
      } else {
        const int r = marker[j];
        sep_ak[static_cast<std::size_t>(r * p + i)] = A.val[e] * sep_ginv[r];
      }
    }
    for (int i2 = 0; any_separable && i2 <= i; ++i2) ldl.mark(n + i, n + i2);
  }
  for (int i = 0; i < P.rows; ++i) {
    for (int e = P.ptr[i]; e < P.ptr[i + 1]; ++e) {
      if (P.col[e] <= i) ldl.mark(i, P.col[e]);
    }
  }
  ldl.analyse();
}

// ================================================================ KKT assembly and factorisation

// V = W_k^-1 G_k restricted to the columns block k touches (dim x nc, row-major, in vbuf).
double* ConicSolver::Workspace::scaled_block(int k) {
  const int r0 = nt.block_start(k);
  const int dim = nt.block_dim(k);
  const int c0 = bc_ptr[k];
  const int nc = bc_ptr[k + 1] - c0;
  double* v = vbuf.data();
  std::fill(v, v + dim * nc, 0.0);
  for (int a = 0; a < nc; ++a) pos[bc_col[c0 + a]] = a;
  for (int r = 0; r < dim; ++r) {
    for (int e = G.ptr[r0 + r]; e < G.ptr[r0 + r + 1]; ++e) v[r * nc + pos[G.col[e]]] = G.val[e];
  }
  for (int a = 0; a < nc; ++a) nt.apply_inverse_block(k, v + a, v + a, nc);
  return v;
}

// y rows -= A_k H_k^-1 A_k' = U'U, U = W_k G_k^-T A_k' (dim x p, row-major in ubuf).
void ConicSolver::Workspace::eliminate_separable(int k) {
  const int r0 = nt.block_start(k);
  const int dim = nt.block_dim(k);
  double* u = ubuf.data();
  const double* ak = sep_ak.data() + static_cast<std::size_t>(r0 * p);
  for (int i = 0; i < p; ++i) nt.apply_block(k, ak + i, u + i, p);
  for (int i = 0; i < p; ++i) {
    for (int i2 = 0; i2 <= i; ++i2) {
      double sum = 0.0;
      for (int r = 0; r < dim; ++r) sum += u[r * p + i] * u[r * p + i2];
      ldl.at(n + i, n + i2) -= sum;
    }
  }
}

// The reduced matrix [P + G'W^-2 G + dI, A'; A, -dI] (d the static regularisation) for the
// current scaling into the structured LDL' storage (lower triangle), the separable blocks
// eliminated (unit pivots on their columns, -U'U on the y rows).
void ConicSolver::Workspace::assemble_kkt() {
  const double delta = settings.static_regularisation;
  ldl.clear_values();
  for (int j = 0; j < n; ++j) ldl.at(j, j) = sep_col[j] != 0 ? 1.0 : delta;
  for (int i = 0; i < P.rows; ++i) {
    for (int e = P.ptr[i]; e < P.ptr[i + 1]; ++e) {
      if (P.col[e] <= i) ldl.at(i, P.col[e]) += P.val[e];
    }
  }
  for (int i = 0; i < p; ++i) {
    ldl.at(n + i, n + i) = -delta;
    for (int e = A.ptr[i]; e < A.ptr[i + 1]; ++e) {
      if (sep_col[A.col[e]] == 0) ldl.at(n + i, A.col[e]) += A.val[e];
    }
  }
  for (int k = 0; k < blocks; ++k) {
    const int dim = nt.block_dim(k);
    const int c0 = bc_ptr[k];
    const int nc = bc_ptr[k + 1] - c0;
    if (nc == 0) continue;
    if (sep_block[k] != 0) {
      eliminate_separable(k);
      continue;
    }
    const double* v = scaled_block(k);
    for (int a = 0; a < nc; ++a) {
      for (int bb = 0; bb <= a; ++bb) {
        double sum = 0.0;
        for (int r = 0; r < dim; ++r) sum += v[r * nc + a] * v[r * nc + bb];
        ldl.at(bc_col[c0 + a], bc_col[c0 + bb]) += sum;
      }
    }
  }
}

// The same reduced matrix, unreduced by the elimination and both triangles, into the dense
// fallback storage.
void ConicSolver::Workspace::assemble_dense() {
  const double delta = settings.static_regularisation;
  Eigen::MatrixXd& K = dense;
  K.setZero();
  for (int j = 0; j < n; ++j) K(j, j) = delta;
  for (int i = 0; i < P.rows; ++i) {
    for (int e = P.ptr[i]; e < P.ptr[i + 1]; ++e) K(i, P.col[e]) += P.val[e];
  }
  for (int i = 0; i < p; ++i) {
    K(n + i, n + i) = -delta;
    for (int e = A.ptr[i]; e < A.ptr[i + 1]; ++e) {
      K(n + i, A.col[e]) += A.val[e];
      K(A.col[e], n + i) += A.val[e];
    }
  }
  for (int k = 0; k < blocks; ++k) {
    const int dim = nt.block_dim(k);
    const int c0 = bc_ptr[k];
    const int nc = bc_ptr[k + 1] - c0;
    if (nc == 0) continue;
    const double* v = scaled_block(k);
    for (int a = 0; a < nc; ++a) {
      for (int bb = 0; bb < nc; ++bb) {
        double sum = 0.0;
        for (int r = 0; r < dim; ++r) sum += v[r * nc + a] * v[r * nc + bb];
        K(bc_col[c0 + a], bc_col[c0 + bb]) += sum;
      }
    }
  }
}

// Switches this iteration to the dense LU with partial pivoting of the same reduced matrix
// (Golub & Van Loan alg. 3.4.1): the row exchanges pick A entries over the tiny,
// cancellation-made pivots that H takes near the optimum (H then has one tiny eigenvalue per
// active cone), which the fixed-order LDL' must accept or regularise. False on breakdown.
bool ConicSolver::Workspace::factor_dense() {
  assemble_dense();
  lu.compute(dense);
  use_lu = true;
  use_schur = false;
  ++fallbacks;
  const auto diagonal = lu.matrixLU().diagonal();
  return diagonal.allFinite() && diagonal.cwiseAbs().minCoeff() > 0.0;
}

// Factors: the Schur complement when every column is separable, else the structured LDL' with
// dynamic regularisation (quasidefinite_ldl.hpp); the dense LU when either fails (S singular, a
// pivot regularised). False on breakdown.
bool ConicSolver::Workspace::factor_kkt() {
  use_lu = false;
  use_schur = all_separable && schur.factor(nt);
  if (use_schur) return true;
  if (all_separable) return factor_dense();
  assemble_kkt();
  const int regularised = ldl.factor(settings.dynamic_epsilon, settings.dynamic_delta);
  if (regularised == 0) return true;
  return factor_dense();
}

// ================================================================ KKT solve

// out = W^-2 in block by block, on the blocks of the LDL' (all of them when the dense LU is in
// use); the separable blocks' rows, solved in closed form, get 0.
void ConicSolver::Workspace::inverse_square(const double* in, double* out) const {
  for (int k = 0; k < blocks; ++k) {
    const int r0 = nt.block_start(k);
    const int dim = nt.block_dim(k);
    if (sep_block[k] != 0 && !use_lu) {
      std::fill(out + r0, out + r0 + dim, 0.0);
      continue;
    }
    nt.apply_inverse_square_block(k, in + r0, out + r0);
  }
}

// Separable block k of the unreduced system (its columns C, A_C the columns of A, g = G_k^-T bx_C
// and ak = G_k^-T A_C', both by row r: divide by g_r):
//   G_k'z_k + A_C'y = bx_C,  G_k x_C - W_k^2 z_k = bz_k
//   =>  z_k = g - ak y,  x_C = G_k^-1 (bz_k + W_k^2 z_k),
// and its share of the y rows, A_C x_C = ak'(bz_k + W_k^2 g) - U'U y, moves to the right side
// before the LDL' solve. No W^-2 appears, so nothing of W's condition is squared.
void ConicSolver::Workspace::separable_forward(const double* bz, double* red) {
  double* g = sep_in.data();
  double* out = sep_out.data();
  for (int k = 0; k < blocks; ++k) {
    if (sep_block[k] == 0) continue;
    const int r0 = nt.block_start(k);
    const int dim = nt.block_dim(k);
    for (int r = 0; r < dim; ++r) g[r] = red[sep_gcol[r0 + r]] * sep_ginv[r0 + r];
    nt.apply_square_block(k, g, out);
    for (int r = 0; r < dim; ++r) {
      const double* ak = sep_ak.data() + static_cast<std::size_t>((r0 + r) * p);
      const double v = bz[r0 + r] + out[r];
      for (int i = 0; i < p; ++i) red[n + i] -= ak[i] * v;
    }
  }
}

// After the LDL' solve (red[C] still holds bx_C: unit pivots, no coupling): x_C into red, z_k
// into oz.
void ConicSolver::Workspace::separable_backward(const double* bz, double* red, double* oz) {
  double* out = sep_out.data();
  for (int k = 0; k < blocks; ++k) {
    if (sep_block[k] == 0) continue;
    const int r0 = nt.block_start(k);
    const int dim = nt.block_dim(k);
    for (int r = 0; r < dim; ++r) {
      const double* ak = sep_ak.data() + static_cast<std::size_t>((r0 + r) * p);
      oz[r0 + r] = red[sep_gcol[r0 + r]] * sep_ginv[r0 + r] - dot(ak, red + n, p);
    }
    nt.apply_square_block(k, oz + r0, out);
    for (int r = 0; r < dim; ++r) red[sep_gcol[r0 + r]] = (bz[r0 + r] + out[r]) * sep_ginv[r0 + r];
  }
}

// One solve of the regularised reduced system for the right side (bx, by, bz) of
//   [P A' G'; A 0 0; G 0 -W^2] (ox, oy, oz) = (bx, by, bz):
//   (P + G'W^-2 G) ox + A'oy = bx + G'W^-2 bz,  A ox = by,  oz = W^-2 (G ox - bz),
// the separable blocks in closed form (separable_forward / separable_backward) unless the
// dense LU is in use; the Schur complement does all of it when it is the factorisation.
void ConicSolver::Workspace::reduced_solve(const double* bx, const double* by, const double* bz, double* ox,
                                           double* oy, double* oz) {
  if (use_schur) {
    schur.solve(nt, bx, by, bz, ox, oy, oz);
    return;
  }
  inverse_square(bz, tmp_s.data());
  double* red = reduced.data();
  for (int j = 0; j < n; ++j) red[j] = bx[j];
  G.multiply_transpose_add(tmp_s.data(), red);
  for (int i = 0; i < p; ++i) red[n + i] = by[i];
  if (use_lu) {
    for (int i = 0; i < n + p; ++i) lu_rhs(i) = red[i];
    lu_sol.noalias() = lu.solve(lu_rhs);
    for (int i = 0; i < n + p; ++i) red[i] = lu_sol(i);
  } else {
    separable_forward(bz, red);
    ldl.solve(red);
    separable_backward(bz, red, oz);
  }
  for (int j = 0; j < n; ++j) ox[j] = red[j];
  for (int i = 0; i < p; ++i) oy[i] = red[n + i];
  // oz = W^-2 (G ox - bz) on the other blocks (the separable rows of G ox are not needed).
  for (int k = 0; k < blocks; ++k) {
    if (sep_block[k] != 0 && !use_lu) continue;
    const int r0 = nt.block_start(k);
    const int dim = nt.block_dim(k);
    for (int r = r0; r < r0 + dim; ++r) {
      double v = -bz[r];
      for (int e = G.ptr[r]; e < G.ptr[r + 1]; ++e) v += G.val[e] * ox[G.col[e]];
      tmp_s[r] = v;
    }
    nt.apply_inverse_square_block(k, tmp_s.data() + r0, oz + r0);
  }
}

// (ex, ey, ez) = (bx, by, bz) - K (ox, oy, oz), K the unregularised, unreduced KKT matrix.
void ConicSolver::Workspace::kkt_residual(const double* bx, const double* by, const double* bz, const double* ox,
                                          const double* oy, const double* oz) {
  P.multiply(ox, ex.data());
  if (P.rows == 0) std::fill(ex.begin(), ex.end(), 0.0);
  A.multiply_transpose_add(oy, ex.data());
  G.multiply_transpose_add(oz, ex.data());
  for (int j = 0; j < n; ++j) ex[j] = bx[j] - ex[j];
  A.multiply(ox, ey.data());
  for (int i = 0; i < p; ++i) ey[i] = by[i] - ey[i];
  nt.apply_square(oz, tmp_s.data());
  G.multiply(ox, ez.data());
  for (int i = 0; i < m; ++i) ez[i] = bz[i] - (ez[i] - tmp_s[i]);
}

// Solve with iterative refinement against the exact, unregularised, unreduced system (which
// removes the static regularisation's effect); returns the final relative residual.
double ConicSolver::Workspace::refined_solve(const double* bx, const double* by, const double* bz, double* ox,
                                             double* oy, double* oz) {
  reduced_solve(bx, by, bz, ox, oy, oz);
  const double scale = std::max({norm_inf(bx, n), norm_inf(by, p), norm_inf(bz, m), 1e-300});
  double err = 0.0;
  for (int step = 0; step <= settings.refinement_steps; ++step) {
    // e = rhs - K o.
    if (use_schur) {
      schur.residual(nt, bx, by, bz, ox, oy, oz, ex.data(), ey.data(), ez.data());
    } else {
      kkt_residual(bx, by, bz, ox, oy, oz);
    }
    const double previous = err;
    err = std::max({norm_inf(ex.data(), n), norm_inf(ey.data(), p), norm_inf(ez.data(), m)}) / scale;
    // Stop at working accuracy, at the step cap, or once a step no longer halves the residual.
    if (!(err > settings.refinement_tolerance) || step == settings.refinement_steps || (step > 0 && err > 0.5 * previous)) {
      break;
    }
    reduced_solve(ex.data(), ey.data(), ez.data(), kx.data(), ky.data(), kz.data());
    for (int j = 0; j < n; ++j) ox[j] += kx[j];
    for (int i = 0; i < p; ++i) oy[i] += ky[i];
    for (int i = 0; i < m; ++i) oz[i] += kz[i];
  }
  return err;
}

// Refined solve; if the structured factorisation leaves a relative residual above
// kRefineTarget, the iteration switches to the dense LU and solves again.
void ConicSolver::Workspace::kkt_solve(const double* bx, const double* by, const double* bz, double* ox, double* oy,
                                       double* oz) {
  constexpr double kRefineTarget = 1e-6;
  const double err = refined_solve(bx, by, bz, ox, oy, oz);
  if ((err > kRefineTarget || !std::isfinite(err)) && !use_lu && factor_dense()) {
    refined_solve(bx, by, bz, ox, oy, oz);
  }
}

// ================================================================ Initial point

// Starting point with W = I (Vandenberghe 2010 sec. 7.2 for conelp; sec. 7.3 for coneqp):
// LP/SOCP: x minimises ||Gx - h|| s.t. Ax = b with s = h - Gx, and (y, z) minimise ||z|| s.t.
// A'y + G'z + c = 0. QP: one solve of [P A' G'; A 0 0; G 0 -I] (x, y, z) = (-c, b, h), s = -z.
// Then s and z are shifted into the interior of K along e; tau = kappa = 1.
bool ConicSolver::Workspace::initial_point() {
  nt.set_identity();
  fallbacks = 0;
  if (!factor_kkt()) return false;
  if (quadratic) {
    for (int j = 0; j < n; ++j) rhs_x[j] = -c[j];
    kkt_solve(rhs_x.data(), b.data(), h.data(), x.data(), y.data(), z.data());
    for (int i = 0; i < m; ++i) s[i] = -z[i];
  } else {
    for (int j = 0; j < n; ++j) rhs_x[j] = 0.0;
    kkt_solve(rhs_x.data(), b.data(), h.data(), x.data(), y1.data(), z1.data());
    for (int i = 0; i < m; ++i) s[i] = -z1[i];
    for (int j = 0; j < n; ++j) rhs_x[j] = -c[j];
    for (int i = 0; i < p; ++i) rhs_y[i] = 0.0;
    for (int i = 0; i < m; ++i) rhs_z[i] = 0.0;
    kkt_solve(rhs_x.data(), rhs_y.data(), rhs_z.data(), x1.data(), y.data(), z.data());
  }
  for (Vec* v : {&s, &z}) {
    const double shift = -cone.interior_margin(v->data());
    if (shift >= -1e-8 * std::max(1.0, norm2(v->data(), m))) cone.add_identity(v->data(), 1.0 + shift);
  }
  tau = 1.0;
  kappa = 1.0;
  return true;
}

// ================================================================ Residuals and termination

// Residuals of the homogeneous self-dual embedding on the scaled data (Goulart & Chen 2024,
// "Clarabel: an interior-point solver for conic programs with quadratic objectives", eq. (8),
// for the x'Px/tau term):
//   rx = Px + A'y + G'z + c tau, ry = A x - b tau, rz = s + G x - h tau,
//   rt = kappa + c'x + b'y + h'z + x'Px / tau.
// Keeps the pieces the certificates need: hx = A'y + G'z, ax = Ax, gxs = Gx + s, px = Px.
void ConicSolver::Workspace::compute_residuals() {
  if (P.rows > 0) P.multiply(x.data(), px.data());
  xpx = P.rows > 0 ? dot(x.data(), px.data(), n) : 0.0;
  std::fill(hx.begin(), hx.end(), 0.0);
  A.multiply_transpose_add(y.data(), hx.data());
  G.multiply_transpose_add(z.data(), hx.data());
  A.multiply(x.data(), ax.data());
  G.multiply(x.data(), gxs.data());
  for (int i = 0; i < m; ++i) gxs[i] += s[i];
  for (int j = 0; j < n; ++j) rx[j] = hx[j] + c[j] * tau + (P.rows > 0 ? px[j] : 0.0);
  for (int i = 0; i < p; ++i) ry[i] = ax[i] - b[i] * tau;
  for (int i = 0; i < m; ++i) rz[i] = gxs[i] - h[i] * tau;
  ctx = dot(c.data(), x.data(), n);
  bty = dot(b.data(), y.data(), p);
  htz = dot(h.data(), z.data(), m);
  stz = dot(s.data(), z.data(), m);
  rt = kappa + ctx + bty + htz + xpx / tau;
}

// The stopping tests of conic_settings.hpp (Vandenberghe 2010 sec. 7, CVXOPT conelp), on the
// unscaled problem with x, y, z, s divided by tau: optimal when both residuals and the gap are
// small; primal infeasible when b'y + h'z < 0 certifies it (A'y + G'z ~ 0); dual infeasible when
// c'x < 0 certifies it (Ax ~ 0, Gx + s ~ 0, Px ~ 0); else the iteration cap. A non-finite
// quantity is a numerical error.
std::optional<ConicStatus> ConicSolver::Workspace::check_termination(int iteration, ConicInfo& info) const {
  const double nrx = unscaled_norm(rx.data(), dcol.data(), n);
  const double nry = unscaled_norm(ry.data(), erow.data(), p);
  const double nrz = unscaled_norm(rz.data(), frow.data(), m);
  const double quad = 0.5 * xpx / (tau * tau);  // (1/2) xi'P xi, xi = x / tau
  const double pcost = quad + ctx / tau;
  const double dcost = -quad - (bty + htz) / tau;
  const double gap = stz / (tau * tau);
  const double pres = std::max(nry / bnorm, nrz / hnorm) / tau;
  const double dres = nrx / cnorm / tau;
  double relgap = std::numeric_limits<double>::infinity();
  if (pcost < 0.0) relgap = gap / -pcost;
  else if (dcost > 0.0) relgap = gap / dcost;
  info.primal_residual = pres;
  info.dual_residual = dres;
  info.gap = gap;
  if (!std::isfinite(pres) || !std::isfinite(dres) || !std::isfinite(gap) || !std::isfinite(rt)) {
    return ConicStatus::kNumericalError;
  }
  if (pres <= settings.feasibility_tolerance && dres <= settings.feasibility_tolerance &&
      (gap <= settings.absolute_gap_tolerance || relgap <= settings.relative_gap_tolerance)) {
    return ConicStatus::kOptimal;
  }
  if (htz + bty < 0.0) {
    const double pinf = unscaled_norm(hx.data(), dcol.data(), n) / cnorm / -(htz + bty);
    if (pinf <= settings.feasibility_tolerance) return ConicStatus::kPrimalInfeasible;
  }
  if (ctx < 0.0) {
    const double pray = P.rows > 0 ? unscaled_norm(px.data(), dcol.data(), n) / cnorm : 0.0;
    const double dinf = std::max({unscaled_norm(ax.data(), erow.data(), p) / bnorm,
                                  unscaled_norm(gxs.data(), frow.data(), m) / hnorm, pray}) / -ctx;
    if (dinf <= settings.feasibility_tolerance) return ConicStatus::kDualInfeasible;
  }
  if (iteration >= settings.max_iterations) return ConicStatus::kMaxIterations;
  return std::nullopt;
}

// ================================================================ Newton step

// Nesterov-Todd scaling W at the current (s, z), with lambda = W z = W^-1 s (cone.hpp: ECOS
// sec. 3.2, Vandenberghe 2010 sec. 4.3). False if s or z is no longer interior.
bool ConicSolver::Workspace::update_scaling() { return nt.update(s.data(), z.data(), lambda.data()); }

// u1 = K^-1 (-c, b, h): the tau column of the embedding (Vandenberghe 2010 sec. 7.3). The
// linearised tau row has coefficients q = (c + 2 P xi, b, h) and -(kappa/tau + xi'P xi).
// Also mu = (s'z + tau kappa) / (nu + 1), nu the cone degree.
void ConicSolver::Workspace::solve_tau_column() {
  mu = (stz + tau * kappa) / (cone.degree() + 1);
  dtau = dkappa = 0.0;
  for (int j = 0; j < n; ++j) rhs_x[j] = -c[j];
  kkt_solve(rhs_x.data(), b.data(), h.data(), x1.data(), y1.data(), z1.data());
  // Denominator of dtau, q'u1 - kappa/tau - xi'P xi, in the cancellation-free form
  // -(x1 - xi)'P(x1 - xi) - ||W z1||^2 - kappa/tau (substitute K u1 = (-c, b, h) into q'u1):
  // near the optimum x1 -> xi and the direct difference loses every digit.
  denom = -kappa / tau;
  nt.apply(z1.data(), tmp_z.data());
  denom -= dot(tmp_z.data(), tmp_z.data(), m);
  if (P.rows > 0) {
    for (int j = 0; j < n; ++j) dxi[j] = x1[j] - x[j] / tau;
    P.multiply(dxi.data(), pdxi.data());
    denom -= dot(dxi.data(), pdxi.data(), n);
  }
}

// q'(dx, dy, dz) with q = (c + 2 P xi, b, h), the coefficients of the linearised tau row.
double ConicSolver::Workspace::q_dot(const double* dx, const double* dy, const double* dz) const {
  double v = dot(c.data(), dx, n) + dot(b.data(), dy, p) + dot(h.data(), dz, m);
  if (P.rows > 0) v += 2.0 / tau * dot(px.data(), dx, n);
  return v;
}

// Newton system of the embedding (Vandenberghe 2010 sec. 7.3, as in ECOS), with rs the target
// of lambda o (W dz + W^-T ds) and rk that of kappa dtau + tau dkappa:
//   K (dx, dy, dz) + dtau (c, -b, -h) = (-eta rx, -eta ry, -eta rz - W (lambda \ rs))
//   (c + 2 P xi)'dx + b'dy + h'dz - (kappa/tau + xi'P xi) dtau = -eta rt - rk / tau
// (with K including P); dkappa = (rk - kappa dtau) / tau. The direction is (x2, y2, z2,
// ds_full, dtau, dkappa), ds and dzs its scaled s and z parts. False if dtau is not finite.
bool ConicSolver::Workspace::direction(double eta, double rk) {
  cone.divide(lambda.data(), rs.data(), dzs.data());  // dzs = lambda \ rs (temporary)
  nt.apply(dzs.data(), rhs_z.data());
  for (int i = 0; i < m; ++i) rhs_z[i] = -eta * rz[i] - rhs_z[i];
  for (int j = 0; j < n; ++j) rhs_x[j] = -eta * rx[j];
  for (int i = 0; i < p; ++i) rhs_y[i] = -eta * ry[i];
  kkt_solve(rhs_x.data(), rhs_y.data(), rhs_z.data(), x2.data(), y2.data(), z2.data());
  const double at = -eta * rt - rk / tau;
  const double qu2 = q_dot(x2.data(), y2.data(), z2.data());

  dtau = (at - qu2) / denom;
  if (!std::isfinite(dtau)) return false;
  for (int j = 0; j < n; ++j) x2[j] += dtau * x1[j];
  for (int i = 0; i < p; ++i) y2[i] += dtau * y1[i];
  for (int i = 0; i < m; ++i) z2[i] += dtau * z1[i];
  dkappa = (rk - kappa * dtau) / tau;
  // ds from the primal rows, ds = -eta rz - G dx + h dtau (equal in exact arithmetic to
  // W (lambda \ rs - W dz), but free of the W^2-sized roundoff of that form, so the primal
  // residual contracts by exactly 1 - alpha eta); kept unscaled in ds_full.
  G.multiply(x2.data(), ds_full.data());
  for (int i = 0; i < m; ++i) ds_full[i] = -eta * rz[i] - ds_full[i] + h[i] * dtau;
  // Scaled directions: dz~ = W dz, ds~ = W^-1 ds.
  nt.apply(z2.data(), dzs.data());
  nt.apply_inverse(ds_full.data(), ds.data());
  return true;
}

// Largest step <= cap keeping lambda + a ds~, lambda + a dz~ in K and tau, kappa positive.
double ConicSolver::Workspace::step_to_boundary(double cap) const {
  double a = cone.max_step(lambda.data(), ds.data(), cap);
  a = cone.max_step(lambda.data(), dzs.data(), a);
  if (dtau < 0.0) a = std::min(a, -tau / dtau);
  if (dkappa < 0.0) a = std::min(a, -kappa / dkappa);
  return a;
}

// Predictor (affine scaling): rs = -lambda o lambda, rk = -tau kappa, eta = 1. Mehrotra's
// centring sigma = (1 - alpha_aff)^3 from its step to the boundary (ECOS, CVXOPT).
bool ConicSolver::Workspace::predictor() {
  cone.product(lambda.data(), lambda.data(), rs.data());
  for (int i = 0; i < m; ++i) rs[i] = -rs[i];
  if (!direction(1.0, -tau * kappa)) return false;
  const double alpha_aff = step_to_boundary(1.0);
  sigma = std::pow(std::clamp(1.0 - alpha_aff, 0.0, 1.0), 3.0);
  for (int i = 0; i < m; ++i) {
    ds_aff[i] = ds[i];
    dz_aff[i] = dzs[i];
  }
  dtau_aff = dtau;
  dkappa_aff = dkappa;
  return true;
}

// Corrector (Mehrotra): rs = -lambda o lambda + sigma mu e - ds_aff o dz_aff,
// rk = -tau kappa + sigma mu - dtau_aff dkappa_aff, eta = 1 - sigma.
bool ConicSolver::Workspace::corrector() {
  cone.product(ds_aff.data(), dz_aff.data(), tmp_s.data());
  cone.product(lambda.data(), lambda.data(), rs.data());
  for (int i = 0; i < m; ++i) rs[i] = -rs[i] - tmp_s[i];
  cone.add_identity(rs.data(), sigma * mu);
  return direction(1.0 - sigma, -tau * kappa + sigma * mu - dtau_aff * dkappa_aff);
}

// A fraction (step_fraction, 0.99 as in ECOS and CVXOPT) of the step to the boundary, at most 1.
double ConicSolver::Workspace::step_length() const {
  return std::min(1.0, settings.step_fraction * step_to_boundary(1e30));
}

// x, y, z, s, tau, kappa += alpha (dx, dy, dz, ds, dtau, dkappa); ds unscaled (ds_full).
void ConicSolver::Workspace::take_step(double alpha) {
  for (int i = 0; i < m; ++i) tmp_s[i] = ds_full[i];
  for (int j = 0; j < n; ++j) x[j] += alpha * x2[j];
  for (int i = 0; i < p; ++i) y[i] += alpha * y2[i];
  for (int i = 0; i < m; ++i) {
    z[i] += alpha * z2[i];
    s[i] += alpha * tmp_s[i];
  }
  tau += alpha * dtau;
  kappa += alpha * dkappa;
}

// ================================================================ Outputs

// Back to the original variables (x = D xs, y = E ys, z = F zs, s = F^-1 ss). Primal infeasible:
// (y, z) normalised so that b'y + h'z = -1, x = s = 0; dual infeasible: (x, s) normalised so that
// c'x = -1, y = z = 0; otherwise the iterate divided by tau, with its objectives.
void ConicSolver::Workspace::unscale(ConicStatus status, const ConicProblem& problem, ConicInfo& info,
                                     Eigen::VectorXd& x_out, Eigen::VectorXd& y_out, Eigen::VectorXd& z_out,
                                     Eigen::VectorXd& s_out) const {
  x_out.setZero();
  y_out.setZero();
  z_out.setZero();
  s_out.setZero();
  const double inf = std::numeric_limits<double>::infinity();
  if (status == ConicStatus::kPrimalInfeasible) {
    const double scale = -(dot(b.data(), y.data(), p) + dot(h.data(), z.data(), m));
    for (int i = 0; i < p; ++i) y_out(i) = erow[i] * y[i] / scale;
    for (int i = 0; i < m; ++i) z_out(i) = frow[i] * z[i] / scale;
    info.primal_objective = inf;
    info.dual_objective = inf;
    return;
  }
  if (status == ConicStatus::kDualInfeasible) {
    const double scale = -dot(c.data(), x.data(), n);
    for (int j = 0; j < n; ++j) x_out(j) = dcol[j] * x[j] / scale;
    for (int i = 0; i < m; ++i) s_out(i) = s[i] / frow[i] / scale;
    info.primal_objective = -inf;
    info.dual_objective = -inf;
    return;
  }
  unscale_iterate(problem, info, x_out, y_out, z_out, s_out);
}

// The iterate / tau in the original variables; the objectives on the original data:
// (1/2) x'Px + c'x and the QP dual objective -(1/2) x'Px - b'y - h'z.
void ConicSolver::Workspace::unscale_iterate(const ConicProblem& problem, ConicInfo& info, Eigen::VectorXd& x_out,
                                             Eigen::VectorXd& y_out, Eigen::VectorXd& z_out,
                                             Eigen::VectorXd& s_out) const {
  const double t = tau;
  for (int j = 0; j < n; ++j) x_out(j) = dcol[j] * x[j] / t;
  for (int i = 0; i < p; ++i) y_out(i) = erow[i] * y[i] / t;
  for (int i = 0; i < m; ++i) {
    z_out(i) = frow[i] * z[i] / t;
    s_out(i) = s[i] / frow[i] / t;
  }
  double objective = 0.0;
  for (int j = 0; j < n; ++j) objective += problem.c(j) * x_out(j);
  if (quadratic) {
    double quad = 0.0;
    for (int i = 0; i < n; ++i) {
      double row = 0.0;
      for (int j = 0; j < n; ++j) row += problem.P(i, j) * x_out(j);
      quad += x_out(i) * row;
    }
    objective += 0.5 * quad;
  }
  info.primal_objective = objective;
  // x'Px = 2 (objective - c'x).
  double cx_out = 0.0;
  for (int j = 0; j < n; ++j) cx_out += problem.c(j) * x_out(j);
  info.dual_objective = -(objective - cx_out) - (dot(b.data(), y.data(), p) + dot(h.data(), z.data(), m)) / t;
}

// ================================================================ The iteration

// Homogeneous self-dual interior-point method (Vandenberghe 2010 sec. 7; ECOS): after the data
// are loaded, equilibrated and the KKT structure analysed once, each iteration computes the
// embedding's residuals, stops if a test is met, rescales (Nesterov-Todd), factors the KKT
// matrix, and takes a Mehrotra predictor-corrector step a fraction of the way to the boundary.
core::Outcome<ConicInfo> ConicSolver::solve(const ConicProblem& problem) {
  if (auto ok = validate_problem(problem, dims_); !ok) return ok;
  Workspace& w = *work_;
  if (!w.load(problem)) return core::Status{core::Problem::kOutOfRange, "P", "must be positive semidefinite"};
  w.equilibrate();
  w.analyse_kkt();

  ConicInfo info;
  const auto finish = [&](ConicStatus status, int iterations) -> ConicInfo {
    info.status = status;
    info.iterations = iterations;
    info.dense_fallbacks = w.fallbacks;
    w.unscale(status, problem, info, x_out_, y_out_, z_out_, s_out_);
    return info;
  };

  if (!w.initial_point()) return finish(ConicStatus::kNumericalError, 0);
  for (int iter = 0;; ++iter) {
    w.compute_residuals();
    if (const auto stop = w.check_termination(iter, info)) return finish(*stop, iter);
    if (!w.update_scaling()) return finish(ConicStatus::kNumericalError, iter);
    if (!w.factor_kkt()) return finish(ConicStatus::kNumericalError, iter);
    w.solve_tau_column();
    if (!w.predictor()) return finish(ConicStatus::kNumericalError, iter);
    if (!w.corrector()) return finish(ConicStatus::kNumericalError, iter);
    const double alpha = w.step_length();
    if (!(alpha > 0.0)) return finish(ConicStatus::kNumericalError, iter);
    w.take_step(alpha);
  }
}

}  // namespace visors::optim
