#include "visors/nav/cdgps_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "visors/nav/ambiguity_slots.hpp"
#include "visors/nav/double_difference.hpp"
#include "visors/nav/fixed_solution.hpp"
#include "visors/nav/gauss_markov.hpp"
#include "visors/nav/gps_measurement_model.hpp"
#include "visors/nav/integer_least_squares.hpp"
#include "visors/nav/orbit_time_update.hpp"
#include "visors/nav/scalar_update.hpp"
#include "visors/nav/sd_multipath.hpp"

namespace visors::nav {
namespace {

constexpr double kLambda = gnss::kL1WavelengthM;
constexpr Craft kCrafts[2] = {Craft::kDsc, Craft::kOsc};

// One scalar measurement of the epoch, predicted at the prior state.
struct Scalar {
  int prn = 0;
  int slot = -1;
  int state = -1;          // its ambiguity state
  double z = 0.0;          // measured [m]
  double coefficient = 1;  // d value / d ambiguity (1 for B [m], lambda for N [cycles])
  bool reinitialise = false;
  // The ambiguity's value from this epoch's code, in its state's unit: GRAPHIC minus code
  // (B - I, I the code's ionospheric delay) or SD phase minus SD code over lambda (the SD
  // integer, 2 dI / lambda and the codes' noise off). Independent of the state's error.
  double from_code = 0.0;
  double variance_scale = 1.0;  // elevation weighting (settings)
  double sin_elevation = 1.0;   // sine of the elevation above the antenna plane (SDCP: the lower receiver's)
  MeasurementPrediction p;
};

// The own part of the empirical accelerations' steady-state sigma on RTN axis `axis`
// (cdgps_settings.hpp) [m/s^2].
double own_sigma(const CdgpsSettings& s, int axis) {
  return axis == 1 && s.empirical_along_track_sigma_mps2 >= 0.0 ? s.empirical_along_track_sigma_mps2 : s.empirical_sigma_mps2;
}

}  // namespace

struct CdgpsFilter::Impl {
  Impl(dynamics::ForceModel dsc, dynamics::ForceModel osc, AmbiguitySlotBank graphic_bank, AmbiguitySlotBank sdcp_bank,
       SdMultipathStates multipath_, DoubleDifferenceAmbiguities dd_, IntegerLeastSquares ils_, FixedSolutionUpdate fixer_)
      : models{std::move(dsc), std::move(osc)},
        graphic(std::move(graphic_bank)),
        sdcp(std::move(sdcp_bank)),
        multipath(multipath_),
        dd(std::move(dd_)),
        ils(std::move(ils_)),
        fixer(std::move(fixer_)) {}

  std::array<dynamics::ForceModel, 2> models;
  AmbiguitySlotBank graphic;
  AmbiguitySlotBank sdcp;
  SdMultipathStates multipath;  // bank M, in step with sdcp's slots
  // The codes' zenith variances (settings only: formed once at create()).
  CodeVariance graphic_zenith{};
  CodeVariance sd_code_zenith{};
  DoubleDifferenceAmbiguities dd;
  IntegerLeastSquares ils;
  FixedSolutionUpdate fixer;
  bool initialised = false;
  core::GpsTime initialised_at;  // the cold start (min_float_s_before_fix counts from it)
  core::GpsTime t;
  NavVector x = NavVector::Zero();
  NavMatrix P = NavMatrix::Identity();
  NavVector x_prior = NavVector::Zero();
  NavVector x_fixed = NavVector::Zero();
  NavMatrix P_fixed = NavMatrix::Identity();
  ScalarUpdateWorkspace workspace;
  std::array<int, kGpsSlots> lock{};  // epochs of continuous SDCP lock per slot
  std::array<core::GpsTime, kGpsSlots> graphic_last{}, sdcp_last{};  // last epoch each slot was measured
  std::array<Scalar, kGpsSlots> graphic_scalars{};
  std::array<Scalar, kGpsSlots> sdcp_scalars{};
  std::array<Scalar, kGpsSlots> code_scalars{};  // SD code of the common satellites (no ambiguity)
  int graphic_count = 0;
  int sdcp_count = 0;
  int code_count = 0;
  bool fixed_valid = false;  // x_fixed, P_fixed hold this epoch's fixed solution
  // Attitude turns (phase_centre_gain_mask): each spacecraft's body-to-RTN attitude at the last
  // epoch, and per body axis the last epoch at which a turn exposed it.
  std::array<Eigen::Matrix3d, 2> body_to_rtn{};
  core::GpsTime attitude_t;
  bool have_attitude = false;
  std::array<std::optional<core::GpsTime>, 3> last_exposed{};  // per body axis: the last turn that exposed it
  Eigen::Matrix<double, kMaxAmbiguities, kNavStates> C;
  Eigen::Matrix<double, kMaxAmbiguities, 1> z_fixed;
  std::array<Eigen::Index, kGpsSlots> dd_others{};
  std::array<RangePrediction, 2 * 33> ranges{};  // per craft and PRN, this epoch
  std::array<bool, 2 * 33> ranged{};
  std::array<core::GpsTime, 2 * 33> ranged_toe{};   // t_oe of the broadcast record each range used
  std::array<core::GpsTime, kGpsSlots> graphic_toe{};  // ... at each GRAPHIC slot's last measurement
  std::array<double, 2 * 33> weight_scale{};  // 1 / sin^2(elevation above the antenna plane), floored
  std::array<double, 2 * 33> sin_elevation{};  // sin(elevation above the antenna plane)

  double scale(Craft c, int prn) const {
    return weighting ? weight_scale[static_cast<std::size_t>(33 * static_cast<int>(c) + prn)] : 1.0;
  }
  bool weighting = false;
  const RangePrediction* range(Craft c, int prn) const {
    const auto i = static_cast<std::size_t>(33 * static_cast<int>(c) + prn);
    return ranged[i] ? &ranges[i] : nullptr;
  }
  void compute_ranges(const CdgpsEpochInput& in, const gnss::EphemerisSource& eph, core::OnboardEarthFrame& frame,
                      double sin_floor, CdgpsEpochReport& report);
  void select(const CdgpsEpochInput& in, Craft local, CdgpsEpochReport& report);
  void assign_slots(AmbiguitySlotBank& bank, std::array<core::GpsTime, kGpsSlots>& last_measured,
                    std::array<Scalar, kGpsSlots>& scalars, int& count, double variance, double timeout_s,
                    CdgpsEpochReport& report, bool with_multipath);
  void predict_scalars(Craft local);
  void start_ambiguities(AmbiguitySlotBank& bank, std::array<Scalar, kGpsSlots>& scalars, int count, double variance,
                         bool with_multipath);
  void follow_ephemeris_switches(Craft local, double variance, CdgpsEpochReport& report);
  double innovation(const Scalar& m) const { return m.z - (m.p.value_m + m.p.h.dot(x - x_prior)); }
  double innovations(const std::array<Scalar, kGpsSlots>& scalars, int count, std::array<double, kGpsSlots>& values) const;
  void order_by_consensus(std::array<Scalar, kGpsSlots>& scalars, int count);
  bool absorb_clock_jump(const std::array<Scalar, kGpsSlots>& scalars, int count, int clock_state, double variance_m2,
                         const CdgpsSettings& s);
  void process(const CdgpsSettings& s, CdgpsEpochReport& report);
  Eigen::Vector3d phase_centre_gain_mask(const CdgpsEpochInput& in, const CdgpsSettings& s);
  std::array<core::StateVector, 2> propagate_mean_states(NavVector& xs, double dt, const CdgpsSettings& s);
  void update_sd_code(const CdgpsSettings& s, CdgpsEpochReport& report);
  void resolve(const CdgpsSettings& s, CdgpsEpochReport& report);
  Eigen::Index rows_to_hold(Eigen::Index k, double hold_variance);
  void record_fixed_combinations(Eigen::Index k, CdgpsEpochReport& report) const;
};

core::Result<CdgpsFilter> CdgpsFilter::create(const CdgpsSettings& settings, dynamics::ForceModel dsc_model,
                                              dynamics::ForceModel osc_model) {
  if (const core::Status ok = check(settings); !ok) return ok.error();
  auto graphic = AmbiguitySlotBank::create(state::kGraphicAmbiguities);
  auto sdcp = AmbiguitySlotBank::create(state::kSdcpAmbiguities);
  auto dd = DoubleDifferenceAmbiguities::create(kNavStates);
  auto ils = IntegerLeastSquares::create();
  auto fixer = FixedSolutionUpdate::create(kNavStates, kGpsSlots);
  if (!graphic || !sdcp || !dd || !ils || !fixer) return core::Error{"", "internal capacity"};
  auto impl = std::make_unique<Impl>(std::move(dsc_model), std::move(osc_model), std::move(graphic).value(),
                                     std::move(sdcp).value(),
                                     SdMultipathStates(settings.sdcp_multipath_sigma_m, settings.sdcp_multipath_tau_s),
                                     std::move(dd).value(), std::move(ils).value(), std::move(fixer).value());
  impl->graphic_zenith = graphic_variance(settings);
  impl->sd_code_zenith = sd_code_variance(settings);
  return CdgpsFilter(settings, std::move(impl));
}

CdgpsFilter::CdgpsFilter(const CdgpsSettings& settings, std::unique_ptr<Impl> impl)
    : settings_(settings), impl_(std::move(impl)) {}
CdgpsFilter::CdgpsFilter(CdgpsFilter&&) noexcept = default;
CdgpsFilter& CdgpsFilter::operator=(CdgpsFilter&&) noexcept = default;
CdgpsFilter::~CdgpsFilter() = default;

bool CdgpsFilter::initialised() const { return impl_->initialised; }
core::GpsTime CdgpsFilter::epoch() const { return impl_->t; }
const NavVector& CdgpsFilter::x() const { return impl_->x; }
const NavMatrix& CdgpsFilter::P() const { return impl_->P; }
const NavVector& CdgpsFilter::x_fixed() const { return impl_->x_fixed; }
const NavMatrix& CdgpsFilter::P_fixed() const { return impl_->P_fixed; }

CdgpsFilter::SlotList CdgpsFilter::sdcp_slots() const {
  SlotList out;
  for (int slot : impl_->sdcp.active_slots()) {
    out.prn[static_cast<std::size_t>(out.count)] = impl_->sdcp.prn_of(slot);
    out.state[static_cast<std::size_t>(out.count)] = impl_->sdcp.state_of(slot);
    ++out.count;
  }
  return out;
}

core::StateVector CdgpsFilter::centre_of_mass(const NavVector& x, Craft craft) {
  return {x.segment<3>(state::position(craft)), state::kVelocityUnit * x.segment<3>(state::velocity(craft))};
}

void CdgpsFilter::initialise(core::GpsTime t, const core::StateVector& dsc_gcrf, const core::StateVector& osc_gcrf,
                             double dsc_clock_m, double osc_clock_m) {
  Impl& m = *impl_;
  const CdgpsSettings& s = settings_;
  m.t = t;
  m.x.setZero();
  m.P.setZero();
  const core::StateVector* states[2] = {&dsc_gcrf, &osc_gcrf};
  const double clocks[2] = {dsc_clock_m, osc_clock_m};
  for (int k = 0; k < 2; ++k) {
    const Craft c = kCrafts[k];
    m.x.segment<3>(state::position(c)) = states[k]->r;
    m.x.segment<3>(state::velocity(c)) = states[k]->v / state::kVelocityUnit;
    m.x(state::clock(c)) = clocks[k];
    const auto variance = [&](int i, double sigma_si) { m.P(i, i) = std::pow(sigma_si / unit(i), 2); };
    for (int i = 0; i < 3; ++i) {
      variance(state::position(c) + i, s.position_sigma_m);
      variance(state::velocity(c) + i, s.velocity_sigma_mps);
      variance(state::empirical_acceleration(c) + i, std::hypot(s.empirical_common_sigma_mps2, own_sigma(s, i)));
      variance(state::phase_center(c) + i, s.phase_center_sigma_m);
    }
    variance(state::clock(c), s.clock_sigma_m);
  }
  for (int i = 0; i < 3; ++i) {  // the empirical accelerations' common part (add_empirical_noise)
    const int a = state::empirical_acceleration(Craft::kDsc) + i, b = state::empirical_acceleration(Craft::kOsc) + i;
    m.P(a, b) = m.P(b, a) = std::pow(s.empirical_common_sigma_mps2 / state::kEmpiricalUnit, 2);
  }
  for (int i = state::kGraphicAmbiguities; i < kNavStates; ++i) m.P(i, i) = AmbiguitySlotBank::kParkedVariance;
  m.graphic.release_all(m.x, m.P);
  m.sdcp.release_all(m.x, m.P);  // the multipath bank is parked with it (x, P zero, parked diagonal above)
  m.lock.fill(0);
  m.x_fixed = m.x;
  m.P_fixed = m.P;
  m.initialised = true;
  m.initialised_at = t;
}

// One spacecraft's (r, v, a_emp) rows and columns of P carried by Phi (from the mean's two ends),
// in the state units.
static void transition_dynamic_block(NavMatrix& P, Craft c, const core::StateVector& x0, const core::StateVector& x1,
                                     double gm, double dt, const CdgpsSettings& s) {
  const int first = state::position(c);
  Eigen::Matrix<double, 9, 9> phi = dynamic_transition(x0, x1, gm, dt, s.empirical_tau_s);
  Eigen::Matrix<double, 9, 1> units;
  for (int i = 0; i < 9; ++i) units(i) = unit(first + i);
  phi = units.cwiseInverse().asDiagonal() * phi * units.asDiagonal();  // S^-1 Phi S
  P.middleRows<9>(first) = (phi * P.middleRows<9>(first)).eval();
  P.middleCols<9>(first) = (P.middleCols<9>(first) * phi.transpose()).eval();
}

// The process noise of the empirical accelerations (CdgpsSettings: a part common to both
// spacecraft and an independent part of each), as the Gauss-Markov chain per RTN axis (q, over r,
// v, a) in the blocks of crafts a and b: q(i, j) F_a[i] F_b[j]' with F = (R, R, I), R the
// spacecraft's RTN -> GCRF at the start (r, v in GCRF, a in its RTN; the two RTN frames 40 m
// apart differ by 6e-6 rad). The whole Q = G (q_c x I) G' + blockdiag(F q_i F') is positive
// semidefinite by construction.
static void add_empirical_noise(NavMatrix& P, const std::array<core::StateVector, 2>& x0, double dt, const CdgpsSettings& s) {
  const Eigen::Matrix3d q_common = gauss_markov_chain(dt, s.empirical_tau_s, s.empirical_common_sigma_mps2).noise;
  const Eigen::Matrix3d q_own = gauss_markov_chain(dt, s.empirical_tau_s, s.empirical_sigma_mps2).noise;
  // An along-track own sigma of its own adds (q_T - q_own) along each spacecraft's T axis.
  const bool along_track = s.empirical_along_track_sigma_mps2 >= 0.0;
  const Eigen::Matrix3d q_along =
      along_track ? Eigen::Matrix3d(gauss_markov_chain(dt, s.empirical_tau_s, own_sigma(s, 1)).noise - q_own)
                  : Eigen::Matrix3d::Zero();
  std::array<std::array<Eigen::Matrix3d, 3>, 2> frames;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Matrix3d R = core::gcrf_to_rtn_matrix(x0[static_cast<std::size_t>(k)]).transpose();
    frames[static_cast<std::size_t>(k)] = {R, R, Eigen::Matrix3d::Identity()};
  }
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      const Eigen::Matrix3d q = a == b ? Eigen::Matrix3d(q_common + q_own) : q_common;
      const int row = state::position(kCrafts[a]), col = state::position(kCrafts[b]);
      const auto& Fa = frames[static_cast<std::size_t>(a)];
      const auto& Fb = frames[static_cast<std::size_t>(b)];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          const double units = unit(row + 3 * i) * unit(col + 3 * j);
          P.block<3, 3>(row + 3 * i, col + 3 * j) +=
              q(i, j) / units * Fa[static_cast<std::size_t>(i)] * Fb[static_cast<std::size_t>(j)].transpose();
          if (along_track && a == b) {
            const Eigen::Vector3d ti = Fa[static_cast<std::size_t>(i)].col(1), tj = Fb[static_cast<std::size_t>(j)].col(1);
            P.block<3, 3>(row + 3 * i, col + 3 * j) += q_along(i, j) / units * ti * tj.transpose();
          }
        }
      }
    }
  }
}

void CdgpsFilter::predict(core::GpsTime t) {
  Impl& m = *impl_;
  const double dt = t.seconds_since(m.t);
  if (!m.initialised || !(dt > 0.0)) return;
  const std::array<core::StateVector, 2> before = m.propagate_mean_states(m.x, dt, settings_);
  for (int k = 0; k < 2; ++k) {
    const Craft c = kCrafts[k];
    transition_dynamic_block(m.P, c, before[static_cast<std::size_t>(k)], centre_of_mass(m.x, c),
                             m.models[static_cast<std::size_t>(k)].gm(), dt, settings_);
    m.P(state::clock(c), state::clock(c)) += settings_.clock_random_walk_m * settings_.clock_random_walk_m * dt;
  }
  add_empirical_noise(m.P, before, dt, settings_);
  const double graphic_q = settings_.graphic_bias_random_walk_m * settings_.graphic_bias_random_walk_m * dt;
  for (int slot : m.graphic.active_slots()) m.P(m.graphic.state_of(slot), m.graphic.state_of(slot)) += graphic_q;
  m.multipath.propagate(m.sdcp, dt, m.x, m.P);
  m.P = (0.5 * (m.P + m.P.transpose())).eval();
  m.t = t;
  m.fixed_valid = false;  // the fixed solution was of the previous epoch
}

// Both spacecraft's position, velocity and empirical acceleration in x carried dt from the epoch
// by RK4 under the on-board model plus the empirical acceleration (its Gauss-Markov mean);
// returns the centres of mass before (for the covariance's transition).
std::array<core::StateVector, 2> CdgpsFilter::Impl::propagate_mean_states(NavVector& xs, double dt, const CdgpsSettings& s) {
  std::array<core::StateVector, 2> before;
  for (int k = 0; k < 2; ++k) {
    const Craft c = kCrafts[k];
    before[static_cast<std::size_t>(k)] = centre_of_mass(xs, c);
    const Eigen::Vector3d a0 = state::kEmpiricalUnit * xs.segment<3>(state::empirical_acceleration(c));
    const MeanPropagation mean = propagate_mean(models[static_cast<std::size_t>(k)], t, before[static_cast<std::size_t>(k)],
                                                a0, s.empirical_tau_s, dt, s.max_step_s);
    xs.segment<3>(state::position(c)) = mean.x_gcrf.r;
    xs.segment<3>(state::velocity(c)) = mean.x_gcrf.v / state::kVelocityUnit;
    xs.segment<3>(state::empirical_acceleration(c)) = mean.a_emp_rtn_mps2 / state::kEmpiricalUnit;
  }
  return before;
}

NavVector CdgpsFilter::forecast(const NavVector& from, core::GpsTime t) {
  Impl& m = *impl_;
  NavVector out = from;
  const double dt = t.seconds_since(m.t);
  if (!m.initialised || !(dt > 0.0)) return out;
  if (dt > kShortForecastS) {
    (void)m.propagate_mean_states(out, dt, settings_);
    return out;
  }
  for (int k = 0; k < 2; ++k) {
    const Craft c = kCrafts[k];
    auto& model = m.models[static_cast<std::size_t>(k)];
    const Eigen::Vector3d a0 = state::kEmpiricalUnit * out.segment<3>(state::empirical_acceleration(c));
    const MeanPropagation mean = forecast_mean(model, m.t, centre_of_mass(out, c), a0, settings_.empirical_tau_s, dt, model.gm());
    out.segment<3>(state::position(c)) = mean.x_gcrf.r;
    out.segment<3>(state::velocity(c)) = mean.x_gcrf.v / state::kVelocityUnit;
    out.segment<3>(state::empirical_acceleration(c)) = mean.a_emp_rtn_mps2 / state::kEmpiricalUnit;
  }
  return out;
}

ScalarUpdateStatus CdgpsFilter::update_laser_range(double z_m, double sigma_m, const LaserRangeGeometry& geometry) {
  Impl& m = *impl_;
  if (!m.initialised || !std::isfinite(z_m) || !(sigma_m > 0.0)) return ScalarUpdateStatus::kInvalid;
  const MeasurementPrediction p = predict_laser_range(m.x, geometry);
  const auto status =
      scalar_update(m.x, m.P, p.h, z_m - p.value_m, sigma_m * sigma_m, settings_.gate_sigmas, m.workspace).status;
  if (m.fixed_valid) {
    const MeasurementPrediction fixed = predict_laser_range(m.x_fixed, geometry);
    (void)scalar_update(m.x_fixed, m.P_fixed, fixed.h, z_m - fixed.value_m, sigma_m * sigma_m, settings_.gate_sigmas,
                        m.workspace);
  }
  return status;
}

bool CdgpsFilter::apply_impulse(Craft craft, const Eigen::Vector3d& dv_gcrf_mps, double elapsed_s) {
  Impl& m = *impl_;
  if (!m.initialised || !dv_gcrf_mps.allFinite() || !(elapsed_s >= 0.0) || !std::isfinite(elapsed_s)) return false;
  const int r = state::position(craft);
  const int v = state::velocity(craft);
  const double magnitude = dv_gcrf_mps.norm();
  m.x.segment<3>(v) += dv_gcrf_mps / state::kVelocityUnit;
  m.x.segment<3>(r) += dv_gcrf_mps * elapsed_s;
  if (magnitude == 0.0) return true;
  const Eigen::Vector3d u = dv_gcrf_mps / magnitude;
  const double along = settings_.impulse_magnitude_sigma * magnitude;
  const double across = settings_.impulse_direction_sigma_deg * core::kDegToRad * magnitude;
  const Eigen::Matrix3d covariance =
      along * along * u * u.transpose() + across * across * (Eigen::Matrix3d::Identity() - u * u.transpose());
  // The execution error e enters as dr = elapsed e, dv = e (state units: v in kVelocityUnit).
  m.P.block<3, 3>(v, v) += covariance / (state::kVelocityUnit * state::kVelocityUnit);
  if (elapsed_s > 0.0) {
    m.P.block<3, 3>(r, r) += elapsed_s * elapsed_s * covariance;
    m.P.block<3, 3>(r, v) += elapsed_s * covariance / state::kVelocityUnit;
    m.P.block<3, 3>(v, r) += elapsed_s * covariance / state::kVelocityUnit;
  }
  return true;
}

// Ranges of every satellite each receiver observed and whose ephemeris is usable, at the prior.
void CdgpsFilter::Impl::compute_ranges(const CdgpsEpochInput& in, const gnss::EphemerisSource& eph,
                                       core::OnboardEarthFrame& frame, double sin_floor, CdgpsEpochReport& report) {
  ranged.fill(false);
  const GpsReceiverEpoch* epochs[2] = {in.dsc, in.osc};
  const AntennaGeometry* antennas[2] = {&in.dsc_antenna, &in.osc_antenna};
  for (int k = 0; k < 2; ++k) {
    if (epochs[k] == nullptr) continue;
    const ReceiverEstimate receiver = receiver_estimate(x, kCrafts[k]);
    for (int i = 0; i < epochs[k]->count; ++i) {
      const GpsObservation& o = epochs[k]->observations[static_cast<std::size_t>(i)];
      if (!plausible(o)) {
        ++report.implausible_observations;
        continue;
      }
      const int prn = o.prn;
      const gnss::BroadcastEphemeris* e = eph.select(prn, t);
      if (e == nullptr) {
        ++report.missing_ephemeris;
        continue;
      }
      const auto index = static_cast<std::size_t>(33 * k + prn);
      ranges[index] = predict_range(t, receiver, *antennas[k], *e, frame);
      ranged[index] = true;
      ranged_toe[index] = e->toe;
      const double sine = (antennas[k]->body_to_gcrf * antennas[k]->boresight_body).dot(ranges[index].line_of_sight_gcrf);
      weight_scale[index] = 1.0 / std::pow(std::max(sine, sin_floor), 2);
      sin_elevation[index] = sine;
    }
  }
}

// The epoch's GRAPHIC (local receiver) and SDCP (both receivers) measurements.
void CdgpsFilter::Impl::select(const CdgpsEpochInput& in, Craft local, CdgpsEpochReport& report) {
  graphic_count = sdcp_count = 0;
  const GpsReceiverEpoch* own = local == Craft::kDsc ? in.dsc : in.osc;
  for (int i = 0; own != nullptr && i < own->count; ++i) {
    const GpsObservation& o = own->observations[static_cast<std::size_t>(i)];
    if (range(local, o.prn) == nullptr) continue;
    if (o.half_cycle) {
      ++report.half_cycle_skipped;
      continue;
    }
    Scalar& m = graphic_scalars[static_cast<std::size_t>(graphic_count++)];
    m = Scalar{};
    m.prn = o.prn;
    m.z = 0.5 * (o.code_m + kLambda * o.phase_cycles);
    m.from_code = m.z - o.code_m;
    m.reinitialise = o.loss_of_lock;
  }
  code_count = 0;
  for (int i = 0; in.osc != nullptr && in.dsc != nullptr && i < in.osc->count; ++i) {
    const GpsObservation& o = in.osc->observations[static_cast<std::size_t>(i)];
    const GpsObservation* d = in.dsc->find(o.prn);
    if (d == nullptr || range(Craft::kOsc, o.prn) == nullptr || range(Craft::kDsc, o.prn) == nullptr) continue;
    Scalar& c = code_scalars[static_cast<std::size_t>(code_count++)];  // the code has no half cycle
    c = Scalar{};
    c.prn = o.prn;
    c.z = o.code_m - d->code_m;
    if (o.half_cycle || d->half_cycle) {
      ++report.half_cycle_skipped;
      continue;
    }
    Scalar& m = sdcp_scalars[static_cast<std::size_t>(sdcp_count++)];
    m = Scalar{};
    m.prn = o.prn;
    m.z = kLambda * (o.phase_cycles - d->phase_cycles);
    m.coefficient = kLambda;
    m.from_code = (m.z - c.z) / kLambda;
    m.reinitialise = o.loss_of_lock || d->loss_of_lock;
  }
}

// Releases the slots of satellites no longer measured, takes slots for new ones (marked for
// initialisation), drops measurements a full bank cannot hold.
void CdgpsFilter::Impl::assign_slots(AmbiguitySlotBank& bank, std::array<core::GpsTime, kGpsSlots>& last_measured,
                                     std::array<Scalar, kGpsSlots>& scalars, int& count, double variance,
                                     double timeout_s, CdgpsEpochReport& report, bool with_multipath) {
  for (int slot : bank.active_slots()) {
    const int prn = bank.prn_of(slot);
    const bool measured = std::any_of(scalars.begin(), scalars.begin() + count, [prn](const Scalar& m) { return m.prn == prn; });
    auto& last = last_measured[static_cast<std::size_t>(slot)];
    if (measured) {
      last = t;
    } else if (t.seconds_since(last) > timeout_s) {
      bank.release(slot, x, P);
      if (with_multipath) SdMultipathStates::park(slot, x, P);
    }
  }
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    Scalar m = scalars[static_cast<std::size_t>(i)];
    m.slot = bank.slot_of(m.prn);
    if (m.slot < 0) {
      m.slot = bank.acquire(m.prn, 0.0, variance, x, P);
      m.reinitialise = true;
    }
    if (m.slot < 0) continue;
    last_measured[static_cast<std::size_t>(m.slot)] = t;
    m.state = bank.state_of(m.slot);
    report.new_ambiguities += m.reinitialise ? 1 : 0;
    scalars[static_cast<std::size_t>(kept++)] = m;
  }
  count = kept;
}

void CdgpsFilter::Impl::predict_scalars(Craft local) {
  x_prior = x;
  for (int i = 0; i < graphic_count; ++i) {
    Scalar& m = graphic_scalars[static_cast<std::size_t>(i)];
    m.p = predict_graphic(x, local, *range(local, m.prn), m.state);
    m.variance_scale = scale(local, m.prn);
  }
  for (int i = 0; i < sdcp_count; ++i) {
    Scalar& m = sdcp_scalars[static_cast<std::size_t>(i)];
    m.p = predict_sdcp(x, *range(Craft::kOsc, m.prn), *range(Craft::kDsc, m.prn), m.state, kLambda);
    m.variance_scale = 0.5 * (scale(Craft::kOsc, m.prn) + scale(Craft::kDsc, m.prn));  // two phases
    m.sin_elevation = std::min(sin_elevation[static_cast<std::size_t>(33 * static_cast<int>(Craft::kOsc) + m.prn)],
                               sin_elevation[static_cast<std::size_t>(33 * static_cast<int>(Craft::kDsc) + m.prn)]);
    if (multipath.enabled()) {  // z = ... + lambda N + m: the slot's multipath state (sd_multipath.hpp)
      const int mp = SdMultipathStates::state_of(m.slot);
      m.p.h(mp) = state::kMultipathUnit;
      m.p.value_m += state::kMultipathUnit * x(mp);
      multipath.set_elevation_scale(m.slot, m.variance_scale);
    }
  }
  for (int i = 0; i < code_count; ++i) {
    Scalar& m = code_scalars[static_cast<std::size_t>(i)];
    m.p = predict_sd_code(x, *range(Craft::kOsc, m.prn), *range(Craft::kDsc, m.prn));
    m.variance_scale = 0.5 * (scale(Craft::kOsc, m.prn) + scale(Craft::kDsc, m.prn));  // two codes
  }
}

// New or flagged ambiguities start at their code value (Scalar::from_code) with the prior
// variance, uncorrelated with the state; the measurement then updates the rest of the state as
// usual. Not at the measurement's residual at the predicted state (the textbook start): that value
// carries the state's error, which an uncorrelated prior then hides: after a 30-minute coast,
// 200 m off, every ambiguity absorbed the 200 m with a prior of 19 m, the filter believed its
// state and never recovered (4 runs in 20, one wrong fix).
void CdgpsFilter::Impl::start_ambiguities(AmbiguitySlotBank& bank, std::array<Scalar, kGpsSlots>& scalars, int count,
                                          double variance, bool with_multipath) {
  for (int i = 0; i < count; ++i) {
    const Scalar& m = scalars[static_cast<std::size_t>(i)];
    if (!m.reinitialise) continue;
    (void)bank.reinitialise(m.slot, m.from_code, variance, x, P);
    if (with_multipath) multipath.start(m.slot, x, P);
  }
}

// A new broadcast data set (every 2 h) moves the modelled range of its satellite by the change of
// the broadcast error along the line of sight, which the GRAPHIC bias of that satellite must take:
// its variance grows by `variance` at the switch. (The SDCP do not see it: 1e-6 of it at 40 m.)
void CdgpsFilter::Impl::follow_ephemeris_switches(Craft local, double variance, CdgpsEpochReport& report) {
  for (int i = 0; i < graphic_count; ++i) {
    const Scalar& m = graphic_scalars[static_cast<std::size_t>(i)];
    const core::GpsTime toe = ranged_toe[static_cast<std::size_t>(33 * static_cast<int>(local) + m.prn)];
    core::GpsTime& last = graphic_toe[static_cast<std::size_t>(m.slot)];
    if (!m.reinitialise && last != toe) {
      P(m.state, m.state) += variance;
      ++report.ephemeris_switches;
    }
    last = toe;
  }
}

// The innovations of the first `count` scalars into `values`, and their median (the upper one
// for an even count; 0 for none).
double CdgpsFilter::Impl::innovations(const std::array<Scalar, kGpsSlots>& scalars, int count,
                                      std::array<double, kGpsSlots>& values) const {
  for (int i = 0; i < count; ++i) values[static_cast<std::size_t>(i)] = innovation(scalars[static_cast<std::size_t>(i)]);
  if (count == 0) return 0.0;
  std::array<double, kGpsSlots> sorted = values;
  std::nth_element(sorted.begin(), sorted.begin() + count / 2, sorted.begin() + count);
  return sorted[static_cast<std::size_t>(count / 2)];
}

// A receiver steering its clock (by a millisecond: 299,792 m) moves every measurement of that
// receiver by the same amount at once. Seen here as the epoch's median scalar failing its own
// gate (the majority of the satellites, not one blunder, disagree with the prior beyond
// gate_sigmas): the median innovation is taken into the clock state, which sets every scalar
// back near zero, and the ambiguities stay (code and phase moved alike). Needs 3 scalars or
// more (a median of fewer is one satellite). The local receiver's from its GRAPHIC, the remote
// one's from the SD codes (remote minus local clock), after the local's.
bool CdgpsFilter::Impl::absorb_clock_jump(const std::array<Scalar, kGpsSlots>& scalars, int count, int clock_state,
                                          double variance_m2, const CdgpsSettings& s) {
  if (count < 3) return false;
  std::array<double, kGpsSlots> values{};
  const double median = innovations(scalars, count, values);
  const Scalar* at_median = &scalars[0];
  for (int i = 0; i < count; ++i) {
    if (values[static_cast<std::size_t>(i)] == median) at_median = &scalars[static_cast<std::size_t>(i)];
  }
  const NavRow& h = at_median->p.h;
  const double spread = std::sqrt((h * P * h.transpose()).value() + at_median->variance_scale * variance_m2);
  const double partial = h(clock_state);
  if (std::abs(median) <= s.gate_sigmas * spread || std::abs(partial) < 0.5) return false;
  x(clock_state) += median / partial;
  return true;
}

// The order of the sequential updates: the receiver clocks are nearly free at each epoch (a random
// walk of metres), so the first scalar processed mostly sets the clock (GRAPHIC) or the clock
// difference (SDCP), and a slip or a code blunder in it would pass its own gate and make every
// other scalar fail. Processing first the scalar whose innovation is the median of the epoch's
// (then the others by their distance from it) lets a minority of faulty measurements be the ones
// that fail.
void CdgpsFilter::Impl::order_by_consensus(std::array<Scalar, kGpsSlots>& scalars, int count) {
  std::array<double, kGpsSlots> values{};
  const double median = innovations(scalars, count, values);
  std::array<int, kGpsSlots> order{};
  for (int i = 0; i < count; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.begin() + count, [&](int a, int b) {
    return std::abs(values[static_cast<std::size_t>(a)] - median) < std::abs(values[static_cast<std::size_t>(b)] - median);
  });
  std::array<Scalar, kGpsSlots> copy = scalars;
  for (int i = 0; i < count; ++i) scalars[static_cast<std::size_t>(i)] = copy[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])];
}

// The epoch's SD codes as one scalar: the mean of those whose innovation lies within the gate of
// the median's (a code blunder or strong multipath left out: the gate uses each one's predicted
// innovation variance, h P h' + its per-epoch variance, over the spacecraft blocks its row spans),
// with the mean row and the mean of their variances / m (sd_code_variance: the weight's, gated on
// the per-epoch one's). One update instead of m: the position information of 0.3 m codes is
// nothing next to the phase; the clock difference is what it is for.
void CdgpsFilter::Impl::update_sd_code(const CdgpsSettings& s, CdgpsEpochReport& report) {
  if (!s.sd_code || code_count == 0) return;
  constexpr int n = 2 * kSpacecraftStates;  // the rows' span: both spacecraft blocks
  std::array<double, kGpsSlots> values{};
  const double median = innovations(code_scalars, code_count, values);
  NavRow h = NavRow::Zero();
  const CodeVariance& zenith = sd_code_zenith;
  double innovation_sum = 0.0, variance_sum = 0.0, gate_sum = 0.0;
  int used = 0;
  for (int i = 0; i < code_count; ++i) {
    const Scalar& m = code_scalars[static_cast<std::size_t>(i)];
    const auto row = m.p.h.head<n>();
    const double spread = std::sqrt(row * P.topLeftCorner<n, n>().selfadjointView<Eigen::Lower>() * row.transpose() +
                                    m.variance_scale * zenith.gate);
    if (std::abs(values[static_cast<std::size_t>(i)] - median) > s.gate_sigmas * spread) {
      ++report.sd_code_rejected;
      continue;
    }
    h += m.p.h;
    innovation_sum += values[static_cast<std::size_t>(i)];
    variance_sum += m.variance_scale * zenith.weight;
    gate_sum += m.variance_scale * zenith.gate;
    ++used;
  }
  if (used == 0) return;
  const double count = used;
  const double squared = count * count;
  const auto r = scalar_update_lower(x, P, h / count, innovation_sum / count, variance_sum / squared, gate_sum / squared,
                                     s.gate_sigmas, workspace);
  if (r.status != ScalarUpdateStatus::kAccepted) {
    report.sd_code_rejected += used;
    return;
  }
  report.sd_code_used = used;
  report.nis_sum += r.normalised_innovation_squared;
  ++report.nis_count;
}

// Which body axes of the phase-centre states are estimated this epoch (cdgps_settings.hpp,
// phase_center_consider_between_turns), as a gain mask (1: estimated): those a turn of either
// spacecraft's attitude in its own orbital frame (the reported attitude against the estimated
// centre of mass's RTN axes) faster than the threshold has exposed, until
// phase_center_free_after_turn_s after it. A turn exposes the offsets normal to its axis only
// (the one along it keeps its direction): body axis i counts as exposed when the turn axis is
// more than ~25 deg from it (|k_i| < 0.9). The calibration yaws (about Z) expose X and Y, the
// observation slews (about Y) X and Z; an axis left free after a turn that cannot see it would
// drift with whatever error it is handed, as the states did when always free.
Eigen::Vector3d CdgpsFilter::Impl::phase_centre_gain_mask(const CdgpsEpochInput& in, const CdgpsSettings& s) {
  if (!s.phase_center_consider_between_turns) return Eigen::Vector3d::Ones();
  constexpr double kTurnAxisCosine = 0.9;
  const AntennaGeometry* antennas[2] = {&in.dsc_antenna, &in.osc_antenna};
  const double dt = have_attitude ? t.seconds_since(attitude_t) : 0.0;
  for (int k = 0; k < 2; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Eigen::Matrix3d now = core::gcrf_to_rtn_matrix(centre_of_mass(x, kCrafts[k])) * antennas[k]->body_to_gcrf;
    if (have_attitude && dt > 0.0) {
      const Eigen::AngleAxisd turn(Eigen::Matrix3d(body_to_rtn[i].transpose() * now));  // axis in body axes
      if (turn.angle() / dt > s.phase_center_turn_rate_deg_s * core::kDegToRad) {
        for (int axis = 0; axis < 3; ++axis) {
          if (std::abs(turn.axis()(axis)) < kTurnAxisCosine) last_exposed[static_cast<std::size_t>(axis)] = t;
        }
      }
    }
    body_to_rtn[i] = now;
  }
  attitude_t = t;
  have_attitude = true;
  Eigen::Vector3d mask = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < (s.phase_center_boresight_estimated ? 3 : 2); ++axis) {
    const auto& when = last_exposed[static_cast<std::size_t>(axis)];
    if (when && t.seconds_since(*when) <= s.phase_center_free_after_turn_s) mask(axis) = 1.0;
  }
  return mask;
}

// Sequential scalar updates, GRAPHIC, SD code, then SDCP, each in consensus order (file comment
// of cdgps_filter.hpp), on the lower triangle of P, mirrored once at the end.
void CdgpsFilter::Impl::process(const CdgpsSettings& s, CdgpsEpochReport& report) {
  const auto account = [&report](const ScalarUpdateResult& r) {
    report.nis_sum += r.normalised_innovation_squared;
    ++report.nis_count;
  };
  for (int i = 0; i < graphic_count; ++i) {
    const Scalar& m = graphic_scalars[static_cast<std::size_t>(i)];
    const auto r = scalar_update_lower(x, P, m.p.h, innovation(m), m.variance_scale * graphic_zenith.weight,
                                       m.variance_scale * graphic_zenith.gate, s.gate_sigmas, workspace);
    if (r.status == ScalarUpdateStatus::kAccepted) {
      ++report.graphic_used;
      report.graphic_nis_sum += r.normalised_innovation_squared;
      account(r);
    } else {
      ++report.graphic_rejected;
    }
  }
  update_sd_code(s, report);
  for (int i = 0; i < sdcp_count; ++i) {
    Scalar& m = sdcp_scalars[static_cast<std::size_t>(i)];
    const double variance = m.variance_scale * s.sdcp_sigma_m * s.sdcp_sigma_m;  // per epoch: the gate's
    const double weight_variance = s.sdcp_correlation_inflation * variance;       // the update's
    if (m.reinitialise) lock[static_cast<std::size_t>(m.slot)] = 0;
    auto r = scalar_update_lower(x, P, m.p.h, innovation(m), weight_variance, variance, s.gate_sigmas, workspace);
    if (r.status == ScalarUpdateStatus::kRejected) {  // a slip the indicator missed
      ++report.sdcp_rejected;
      ++report.detected_slips;
      ++report.new_ambiguities;
      (void)sdcp.reinitialise(m.slot, m.from_code, std::pow(s.sdcp_ambiguity_sigma_cycles, 2), x, P);
      multipath.start(m.slot, x, P);
      lock[static_cast<std::size_t>(m.slot)] = 0;
      r = scalar_update_lower(x, P, m.p.h, innovation(m), weight_variance, variance, s.gate_sigmas, workspace);
    }
    if (r.status == ScalarUpdateStatus::kAccepted) {
      ++report.sdcp_used;
      report.sdcp_nis_sum += r.normalised_innovation_squared;
      account(r);
      ++lock[static_cast<std::size_t>(m.slot)];
    } else {
      m.slot = -1;  // not used for the integer resolution of this epoch
    }
  }
  mirror_lower(P);  // the updates above kept the lower triangle only (scalar_update.hpp)
}

// Integer ambiguity resolution on the DDs of this epoch's SDCP slots (file comment), those of the
// satellites above min_fix_elevation_deg at both receivers; the lower ones stay float.
void CdgpsFilter::Impl::resolve(const CdgpsSettings& s, CdgpsEpochReport& report) {
  const bool masked = s.min_fix_elevation_deg > 0.0;
  const double sin_mask = std::sin(s.min_fix_elevation_deg * core::kDegToRad);
  const auto fixable = [=](const Scalar& m) { return m.slot >= 0 && (!masked || m.sin_elevation >= sin_mask); };
  int reference = -1, others = 0;
  for (int i = 0; i < sdcp_count; ++i) {
    const Scalar& m = sdcp_scalars[static_cast<std::size_t>(i)];
    if (!fixable(m)) continue;
    if (reference < 0 || lock[static_cast<std::size_t>(m.slot)] > lock[static_cast<std::size_t>(sdcp_scalars[static_cast<std::size_t>(reference)].slot)]) {
      reference = i;
    }
  }
  if (reference < 0) return;
  report.dd_prns[0] = sdcp_scalars[static_cast<std::size_t>(reference)].prn;
  for (int i = 0; i < sdcp_count; ++i) {
    const Scalar& m = sdcp_scalars[static_cast<std::size_t>(i)];
    if (!fixable(m) || i == reference) continue;
    report.dd_prns[static_cast<std::size_t>(others + 1)] = m.prn;
    dd_others[static_cast<std::size_t>(others++)] = m.state;
  }
  dd.reset(kNavStates);
  dd.add_group(sdcp_scalars[static_cast<std::size_t>(reference)].state,
               std::span<const Eigen::Index>(dd_others.data(), static_cast<std::size_t>(others)));
  report.double_differences = static_cast<int>(dd.size());
  if (dd.size() == 0 || !dd.evaluate(x, P)) return;
  report.fix = resolve_ambiguities(ils, dd.a(), dd.Q(), s.acceptance);
  if (report.fix.outcome == FixOutcome::kFloat) return;
  const Eigen::Index k = fixed_constraints(report.fix, ils, dd, C, z_fixed);
  x_fixed = x;
  P_fixed = P;
  if (k == 0 || fixer.apply(x_fixed, P_fixed, C.topRows(k), z_fixed.head(k), 0.0, workspace.gain_mask) != FixedSolutionUpdate::Status::kOk) return;
  // Wrong-fix check (docs/algorithms/cdgps-filter.md#wrong-fix-check): the fixed solution must
  // explain every SDCP used to the gate.
  for (int i = 0; i < sdcp_count; ++i) {
    const Scalar& m = sdcp_scalars[static_cast<std::size_t>(i)];
    const double residual = m.z - (m.p.value_m + m.p.h.dot(x_fixed - x_prior));
    if (m.slot >= 0 && std::abs(residual) > s.gate_sigmas * s.sdcp_sigma_m * std::sqrt(m.variance_scale)) {
      report.wrong_fix_refused = true;
      return;
    }
  }
  report.fix_applied = true;
  if (report.fix.outcome == FixOutcome::kFixed) {
    // The full fix's integers in the original DD space (ils.solution().a, best candidate), in
    // the order of the DD rows: dd_prns[1..].
    const auto& integers = ils.solution().a;
    for (Eigen::Index r = 0; r < dd.size(); ++r) {
      report.dd_integer_cycles[static_cast<std::size_t>(r + 1)] = std::llround(integers(r, 0));
    }
  } else {
    record_fixed_combinations(k, report);
  }
  if (s.hold && report.fix.outcome == FixOutcome::kFixed) {
    const Eigen::Index held = rows_to_hold(k, s.hold_variance_cycles2);
    report.held = held > 0 && fixer.apply(x, P, C.topRows(held), z_fixed.head(held), s.hold_variance_cycles2, workspace.gain_mask) ==
                                  FixedSolutionUpdate::Status::kOk;
  }
}

// A partial fix's k combinations Z(:, n-k..n-1) and their integers, in the DD space of the
// report's dd_prns (CdgpsEpochReport::fixed_combinations).
void CdgpsFilter::Impl::record_fixed_combinations(Eigen::Index k, CdgpsEpochReport& report) const {
  const AmbiguityMatrix& Z = ils.transformation();
  const Eigen::Index n = dd.size();
  constexpr double kLargest = std::numeric_limits<std::int32_t>::max();
  if (k > n || Z.rows() != n || (Z.rightCols(k).array().abs() > kLargest).any()) return;
  for (Eigen::Index i = 0; i < k; ++i) {
    auto& coefficients = report.combination_coefficients[static_cast<std::size_t>(i)];
    for (Eigen::Index r = 0; r < n; ++r) {
      coefficients[static_cast<std::size_t>(r + 1)] = static_cast<std::int32_t>(std::llround(Z(r, n - k + i)));
    }
    report.combination_integers[static_cast<std::size_t>(i)] = std::llround(z_fixed(i));
  }
  report.fixed_combinations = static_cast<int>(k);
}

// The fixed combinations the hold still has to constrain, moved to the top k' rows of C and z:
// those whose float variance c P c' exceeds the hold variance. Once held, a combination's
// variance stays below it (ambiguities have no process noise), so each is held once, not again
// at every epoch (an update of k rows each time). C has entries only in the SDCP ambiguity
// columns.
Eigen::Index CdgpsFilter::Impl::rows_to_hold(Eigen::Index k, double hold_variance) {
  constexpr int a = state::kSdcpAmbiguities;
  Eigen::Index kept = 0;
  for (Eigen::Index i = 0; i < k; ++i) {
    const auto c = C.row(i).segment<kGpsSlots>(a);
    const double variance = c * P.block<kGpsSlots, kGpsSlots>(a, a) * c.transpose();
    if (!(variance > hold_variance)) continue;
    if (kept != i) {
      C.row(kept) = C.row(i);
      z_fixed(kept) = z_fixed(i);
    }
    ++kept;
  }
  return kept;
}

CdgpsEpochReport CdgpsFilter::update(const CdgpsEpochInput& input, const gnss::EphemerisSource& ephemerides,
                                     core::OnboardEarthFrame& frame) {
  Impl& m = *impl_;
  CdgpsEpochReport report;
  const auto refuse = [&report](const char* reason) {
    report.reason = reason;
    return report;
  };
  const GpsReceiverEpoch* own = settings_.local == Craft::kDsc ? input.dsc : input.osc;
  if (!m.initialised) return refuse("not_initialised");
  if (own == nullptr || own->t != m.t) return refuse("time_tag");
  if (input.dsc != nullptr && !check(*input.dsc)) return refuse("dsc");
  if (input.osc != nullptr && !check(*input.osc)) return refuse("osc");
  const GpsReceiverEpoch* other = settings_.local == Craft::kDsc ? input.osc : input.dsc;
  CdgpsEpochInput in = input;
  if (other != nullptr && other->t != m.t) (settings_.local == Craft::kDsc ? in.osc : in.dsc) = nullptr;  // not this epoch's
  report.accepted = true;
  m.weighting = settings_.elevation_weighting;
  const double sin_floor = std::sin(settings_.min_weighting_elevation_deg * M_PI / 180.0);
  m.compute_ranges(in, ephemerides, frame, sin_floor, report);
  m.select(in, settings_.local, report);
  m.assign_slots(m.graphic, m.graphic_last, m.graphic_scalars, m.graphic_count,
                 std::pow(settings_.graphic_ambiguity_sigma_m, 2), settings_.slot_timeout_s, report, false);
  m.assign_slots(m.sdcp, m.sdcp_last, m.sdcp_scalars, m.sdcp_count, std::pow(settings_.sdcp_ambiguity_sigma_cycles, 2),
                 settings_.slot_timeout_s, report, true);
  m.predict_scalars(settings_.local);
  m.start_ambiguities(m.graphic, m.graphic_scalars, m.graphic_count, std::pow(settings_.graphic_ambiguity_sigma_m, 2),
                      false);
  m.start_ambiguities(m.sdcp, m.sdcp_scalars, m.sdcp_count, std::pow(settings_.sdcp_ambiguity_sigma_cycles, 2), true);
  m.follow_ephemeris_switches(settings_.local, std::pow(settings_.ephemeris_switch_sigma_m, 2), report);
  const Craft remote = settings_.local == Craft::kDsc ? Craft::kOsc : Craft::kDsc;
  report.clock_jumps += m.absorb_clock_jump(m.graphic_scalars, m.graphic_count, state::clock(settings_.local),
                                            m.graphic_zenith.gate, settings_) ? 1 : 0;
  if (settings_.sd_code) {
    report.clock_jumps += m.absorb_clock_jump(m.code_scalars, m.code_count, state::clock(remote),
                                              m.sd_code_zenith.gate, settings_) ? 1 : 0;
  }
  const Eigen::Vector3d free = m.phase_centre_gain_mask(in, settings_);
  for (const Craft c : kCrafts) m.workspace.gain_mask.segment<3>(state::phase_center(c)) = free;
  report.phase_centre_axes_estimated = static_cast<int>(free.sum());
  m.order_by_consensus(m.graphic_scalars, m.graphic_count);
  m.order_by_consensus(m.sdcp_scalars, m.sdcp_count);
  m.process(settings_, report);
  if (settings_.ambiguity_resolution && m.t.seconds_since(m.initialised_at) >= settings_.min_float_s_before_fix) {
    m.resolve(settings_, report);
  }
  m.fixed_valid = report.fix_applied;
  return report;
}

}  // namespace visors::nav
