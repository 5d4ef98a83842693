#include "visors/baseline/baseline_filter.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include "visors/nav/double_difference.hpp"
#include "visors/nav/fixed_solution.hpp"
#include "visors/nav/integer_least_squares.hpp"

namespace visors::baseline {

std::string_view to_string(SolutionStatus status) {
  switch (status) {
    case SolutionStatus::kNone: return "none";
    case SolutionStatus::kCode: return "code";
    case SolutionStatus::kFloat: return "float";
    case SolutionStatus::kPartial: return "partial";
    case SolutionStatus::kFix: return "fix";
  }
  return "?";
}

struct BaselineFilter::Ambiguity {
  nav::IntegerLeastSquares ils;
  nav::DoubleDifferenceAmbiguities dd;
  nav::FixedSolutionUpdate fixer;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(nav::kMaxAmbiguities, kStates);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(nav::kMaxAmbiguities);
  Eigen::VectorXd x_fixed = Eigen::VectorXd::Zero(kStates);
  Eigen::MatrixXd P_fixed = Eigen::MatrixXd::Zero(kStates, kStates);
};

core::Result<BaselineFilter> BaselineFilter::create(const BaselineSettings& settings) {
  if (auto v = validate(settings); !v) return v.error();
  auto ils = nav::IntegerLeastSquares::create();
  auto dd = nav::DoubleDifferenceAmbiguities::create(kStates);
  auto fixer = nav::FixedSolutionUpdate::create(kStates);
  if (!ils) return ils.error();
  if (!dd) return dd.error();
  if (!fixer) return fixer.error();
  auto ambiguity = std::make_unique<Ambiguity>(Ambiguity{std::move(ils).value(), std::move(dd).value(),
                                                         std::move(fixer).value()});
  return BaselineFilter(settings, std::move(ambiguity));
}

BaselineFilter::BaselineFilter(const BaselineSettings& settings, std::unique_ptr<Ambiguity> ambiguity)
    : settings_(settings),
      x_(Eigen::VectorXd::Zero(kStates)),
      P_(Eigen::MatrixXd::Zero(kStates, kStates)),
      ambiguity_(std::move(ambiguity)) {}

BaselineFilter::BaselineFilter(BaselineFilter&&) noexcept = default;
BaselineFilter& BaselineFilter::operator=(BaselineFilter&&) noexcept = default;
BaselineFilter::~BaselineFilter() = default;

void BaselineFilter::set_position(const Eigen::Vector3d& r_m, double sigma_m) {
  x_.head<3>() = r_m;
  P_.topRows<3>().setZero();
  P_.leftCols<3>().setZero();
  P_.topLeftCorner<3, 3>().diagonal().setConstant(sigma_m * sigma_m);
  initialised_ = true;
}

void BaselineFilter::predict(core::GpsTime t) {
  const double dt = last_ == core::GpsTime{} ? 0.0 : std::max(0.0, t.seconds_since(last_));
  last_ = t;
  const double q = settings_.ambiguity_noise_cyc_per_sqrt_s * settings_.ambiguity_noise_cyc_per_sqrt_s * dt;
  for (Eigen::Index i = kPositionStates; i < kStates; ++i) {
    if (active_[static_cast<std::size_t>(i)]) P_(i, i) += q;
  }
}

void BaselineFilter::reset_ambiguity(int frequency, int prn, double value_cyc) {
  const Eigen::Index i = ambiguity_index(frequency, prn);
  x_(i) = value_cyc;
  P_.row(i).setZero();
  P_.col(i).setZero();
  P_(i, i) = settings_.initial_ambiguity_sigma_cyc * settings_.initial_ambiguity_sigma_cyc;
  active_[static_cast<std::size_t>(i)] = true;
}

void BaselineFilter::release_ambiguity(int frequency, int prn) {
  const Eigen::Index i = ambiguity_index(frequency, prn);
  x_(i) = 0.0;
  P_.row(i).setZero();
  P_.col(i).setZero();
  active_[static_cast<std::size_t>(i)] = false;
}

bool BaselineFilter::ambiguity_active(int frequency, int prn) const {
  return active_[static_cast<std::size_t>(ambiguity_index(frequency, prn))];
}

namespace {

// Innovation of the system linearised at r_lin: v = y - H (x - (r_lin, 0)).
Eigen::VectorXd innovation(const DdSystem& s, const Eigen::VectorXd& x, const Eigen::Vector3d& r_lin) {
  Eigen::VectorXd dx = x;
  dx.head<3>() -= r_lin;
  return s.y - s.H * dx;
}

double sd_ambiguity_guess(const SingleDifference& sd, int f) {
  const auto fi = static_cast<std::size_t>(f);
  return (sd.phase_m[fi] - sd.code_m[fi]) / wavelength_m(f);
}

}  // namespace

// DD phase innovation gate (file comment). True when a slot was reinitialised.
bool BaselineFilter::gate_phase(const std::vector<SingleDifference>& sds, const std::vector<DdGroup>& groups,
                                const DdSystem& s, FilterEpochResult& result) {
  const Eigen::VectorXd v = innovation(s, x_, r_lin_);
  const Eigen::MatrixXd S = s.H * P_ * s.H.transpose() + s.R;
  bool reset = false;
  Eigen::Index row = 0;
  for (const auto& g : groups) {
    std::vector<int> failed;
    for (int member : g.members) {
      if (g.kind == Observable::kPhase && std::abs(v(row)) > settings_.phase_gate_sigma * std::sqrt(S(row, row))) {
        failed.push_back(member);
      }
      ++row;
    }
    if (failed.empty()) continue;
    const bool reference_suspect = 2 * failed.size() > g.members.size() && g.members.size() >= 2;
    const auto reinitialise = [&](int index, const char* reason) {
      const SingleDifference& sd = sds[static_cast<std::size_t>(index)];
      reset_ambiguity(g.frequency, sd.prn, sd_ambiguity_guess(sd, g.frequency));
      result.rejected.push_back({sd.prn, g.frequency, reason});
    };
    if (reference_suspect) {
      reinitialise(g.reference, "reference_phase_gate");
    } else {
      for (int index : failed) reinitialise(index, "phase_gate");
    }
    reset = true;
  }
  return reset;
}

void BaselineFilter::kalman_update(const DdSystem& s) {
  const Eigen::VectorXd v = innovation(s, x_, r_lin_);
  const Eigen::MatrixXd PHt = P_ * s.H.transpose();
  const Eigen::MatrixXd S = s.H * PHt + s.R;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(S);
  const Eigen::MatrixXd K = ldlt.solve(PHt.transpose()).transpose();
  x_ += K * v;
  // Joseph form: (I - K H) P (I - K H)' + K R K'.
  Eigen::MatrixXd IKH = -K * s.H;
  IKH.diagonal().array() += 1.0;
  P_ = IKH * P_ * IKH.transpose() + K * s.R * K.transpose();
  P_ = 0.5 * (P_ + P_.transpose()).eval();
}

FilterEpochResult BaselineFilter::update(const std::vector<SingleDifference>& sds) {
  FilterEpochResult result;
  r_lin_ = x_.head<3>();
  const auto phase_usable = [&](int i, int f) { return ambiguity_active(f, sds[static_cast<std::size_t>(i)].prn); };
  const auto any = [](int, int) { return true; };
  std::vector<DdGroup> phase_groups;
  DdSystem s;
  for (int pass = 0; pass < 3; ++pass) {
    phase_groups = make_groups(sds, Observable::kPhase, phase_usable);
    std::vector<DdGroup> groups = phase_groups;
    for (auto& g : make_groups(sds, Observable::kCode, any)) groups.push_back(std::move(g));
    s = build_dd_system(sds, groups, true);
    if (s.rows.empty() || pass == 2 || !gate_phase(sds, groups, s, result)) break;
  }
  if (s.rows.empty()) return result;
  kalman_update(s);
  for (const auto& row : s.rows) (row.kind == Observable::kPhase ? result.phase_rows : result.code_rows) += 1;
  result.float_ok = x_.allFinite();
  result.r_float_m = x_.head<3>();
  result.cov_float_m2 = P_.topLeftCorner<3, 3>();
  if (settings_.ambiguity_mode != AmbiguityMode::kOff && result.float_ok) resolve(sds, phase_groups, s, result);
  return result;
}

// Integer ambiguity resolution of the epoch's DD phase ambiguities (file comment).
void BaselineFilter::resolve(const std::vector<SingleDifference>& sds, const std::vector<DdGroup>& phase_groups,
                             const DdSystem& s, FilterEpochResult& result) {
  Ambiguity& a = *ambiguity_;
  a.dd.reset(kStates);
  std::vector<Eigen::Index> others;
  for (const auto& g : phase_groups) {
    others.clear();
    for (int m : g.members) others.push_back(ambiguity_index(g.frequency, sds[static_cast<std::size_t>(m)].prn));
    a.dd.add_group(ambiguity_index(g.frequency, sds[static_cast<std::size_t>(g.reference)].prn), others);
  }
  result.ambiguities = a.dd.size();
  if (a.dd.size() == 0 || !a.dd.evaluate(x_, P_)) return;
  result.fix = nav::resolve_ambiguities(a.ils, a.dd.a(), a.dd.Q(), settings_.acceptance);
  if (result.fix.outcome == nav::FixOutcome::kFloat) return;
  const Eigen::Index k = nav::fixed_constraints(result.fix, a.ils, a.dd, a.C, a.z);
  a.x_fixed = x_;
  a.P_fixed = P_;
  if (a.fixer.apply(a.x_fixed, a.P_fixed, a.C.topRows(k), a.z.head(k), 0.0) != nav::FixedSolutionUpdate::Status::kOk) {
    return;
  }
  // Wrong-fix check: the fixed solution must explain every DD phase to the gate.
  const Eigen::VectorXd v = innovation(s, a.x_fixed, r_lin_);
  for (Eigen::Index r = 0; r < v.size(); ++r) {
    if (s.rows[static_cast<std::size_t>(r)].kind == Observable::kPhase &&
        std::abs(v(r)) > settings_.phase_gate_sigma * std::sqrt(s.R(r, r))) {
      result.wrong_fix_refused = true;
      return;
    }
  }
  result.fix_accepted = true;
  result.r_fixed_m = a.x_fixed.head<3>();
  result.cov_fixed_m2 = a.P_fixed.topLeftCorner<3, 3>();
  if (settings_.ambiguity_mode == AmbiguityMode::kHold && result.fix.outcome == nav::FixOutcome::kFixed) {
    a.fixer.apply(x_, P_, a.C.topRows(k), a.z.head(k), settings_.hold_variance_cyc2);
  }
}

}  // namespace visors::baseline
