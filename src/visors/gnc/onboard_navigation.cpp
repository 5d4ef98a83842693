#include "visors/gnc/onboard_navigation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "visors/core/rtn_frame.hpp"

namespace visors::gnc {

namespace {

nav::Craft craft_of(Spacecraft s) { return s == Spacecraft::kDsc ? nav::Craft::kDsc : nav::Craft::kOsc; }

// The covariance of [r_osc - r_dsc; v_osc - v_dsc] from P (state units: velocity in
// kVelocityUnit), in the chief's RTN axes [m^2, m^2/s^2].
Eigen::Matrix<double, 6, 6> relative_covariance_rtn(const nav::NavMatrix& P, const core::StateVector& chief) {
  using nav::Craft;
  namespace st = nav::state;
  static_assert(st::velocity(Craft::kDsc) == st::position(Craft::kDsc) + 3, "r, v adjacent");
  const int d = st::position(Craft::kDsc);
  const int o = st::position(Craft::kOsc);
  // [r; v]_osc - [r; v]_dsc in state units, then in SI and the chief's RTN axes.
  const Eigen::Matrix<double, 6, 6> C = P.block<6, 6>(o, o) - P.block<6, 6>(o, d) - P.block<6, 6>(d, o) + P.block<6, 6>(d, d);
  Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Zero();
  const Eigen::Matrix3d R = core::gcrf_to_rtn_matrix(chief);
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = st::kVelocityUnit * R;
  const Eigen::Matrix<double, 6, 6> out = T * C * T.transpose();
  return 0.5 * (out + out.transpose());
}

// A partial fix's integer combinations (messages.hpp FixedCombination), when all its double
// differences fit the record.
void fixed_combinations(const nav::CdgpsEpochReport& report, NavigationTelemetry& out) {
  out.combination_count = 0;
  if (report.double_differences > kTelemetryDoubleDifferences) return;
  const int count = std::clamp(report.fixed_combinations, 0, out.dd_count);
  for (int i = 0; i < count; ++i) {
    FixedCombination& c = out.combinations[static_cast<std::size_t>(i)];
    const auto& coefficients = report.combination_coefficients[static_cast<std::size_t>(i)];
    for (int j = 1; j <= out.dd_count; ++j) {
      c.dd_coefficients[static_cast<std::size_t>(j - 1)] = coefficients[static_cast<std::size_t>(j)];
    }
    c.integer_cycles = report.combination_integers[static_cast<std::size_t>(i)];
  }
  out.combination_count = count;
}

// The double differences of `report`'s fix (its reference, then the others), each with the
// full fix's integer and the fixed solution's value from the filter's SDCP slots (messages.hpp
// FixedDoubleDifference).
void fixed_double_differences(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& report, NavigationTelemetry& out) {
  const nav::CdgpsFilter::SlotList slots = filter.sdcp_slots();
  const auto fixed_sd = [&](int prn) {
    for (int i = 0; i < slots.count; ++i) {
      if (slots.prn[static_cast<std::size_t>(i)] == prn) return filter.x_fixed()(slots.state[static_cast<std::size_t>(i)]);
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  out.full_fix = report.fix.outcome == nav::FixOutcome::kFixed;
  out.dd_reference_prn = report.dd_prns[0];
  out.dd_count = std::clamp(report.double_differences, 0, kTelemetryDoubleDifferences);
  const double reference = fixed_sd(report.dd_prns[0]);
  for (int j = 1; j <= out.dd_count; ++j) {
    FixedDoubleDifference& d = out.dd[static_cast<std::size_t>(j - 1)];
    d.prn = report.dd_prns[static_cast<std::size_t>(j)];
    d.integer_cycles = out.full_fix ? report.dd_integer_cycles[static_cast<std::size_t>(j)] : 0;
    d.fixed_cycles = fixed_sd(d.prn) - reference;
  }
  fixed_combinations(report, out);
}

}  // namespace

static_assert(static_cast<int>(gnss::EphemerisStore::AcceptStatus::kInconsistent) == kEphemerisStatuses - 1,
              "one ephemeris counter per acceptance status");

core::Status OnboardNavigationSettings::validate() const {
  if (const core::Status ok = nav::check(filter); !ok) return ok.within("filter");
  if (!antenna_arp_body_m.allFinite()) return core::Status{core::Problem::kNotFinite, "antenna_arp_body_m", "must be finite"};
  if (!std::isfinite(antenna_pco_m)) return core::Status{core::Problem::kNotFinite, "antenna_pco_m", "must be finite"};
  if (!lrf_lever_body_m.allFinite()) return core::Status{core::Problem::kNotFinite, "lrf_lever_body_m", "must be finite"};
  if (!(lrf_sigma_m > 0.0) || !std::isfinite(lrf_sigma_m)) return core::Status{core::Problem::kOutOfRange, "lrf_sigma_m", "must be finite and > 0"};
  if (!std::isfinite(lrf_bias_m)) return core::Status{core::Problem::kNotFinite, "lrf_bias_m", "must be finite"};
  if (!(peer_wait_s >= 0.0 && peer_wait_s <= 10.0)) return core::Status{core::Problem::kOutOfRange, "peer_wait_s", "must be in [0, 10] s"};
  if (!(coast_after_s >= 1.0 && coast_after_s <= 60.0)) return core::Status{core::Problem::kOutOfRange, "coast_after_s", "must be in [1, 60] s"};
  if (!(valid_position_sigma_m > 0.0) || !std::isfinite(valid_position_sigma_m)) {
    return core::Status{core::Problem::kOutOfRange, "valid_position_sigma_m", "must be finite and > 0"};
  }
  if (!(valid_velocity_sigma_mps > 0.0) || !std::isfinite(valid_velocity_sigma_mps)) {
    return core::Status{core::Problem::kOutOfRange, "valid_velocity_sigma_mps", "must be finite and > 0"};
  }
  return {};
}

core::Result<OnboardNavigation> OnboardNavigation::create(const OnboardNavigationSettings& settings, Spacecraft self,
                                                          dynamics::ForceModel dsc_model, dynamics::ForceModel osc_model) {
  if (auto ok = settings.validate(); !ok) return ok.error();
  nav::CdgpsSettings filter_settings = settings.filter;
  filter_settings.local = craft_of(self);
  auto filter = nav::CdgpsFilter::create(filter_settings, std::move(dsc_model), std::move(osc_model));
  if (!filter.ok()) return core::Error{"filter." + filter.error().field, filter.error().message};
  return OnboardNavigation(settings, self, std::move(filter).value());
}

OnboardNavigation::OnboardNavigation(const OnboardNavigationSettings& settings, Spacecraft self, nav::CdgpsFilter filter)
    : settings_(settings),
      self_(self),
      local_(craft_of(self)),
      remote_(self == Spacecraft::kDsc ? nav::Craft::kOsc : nav::Craft::kDsc),
      filter_(std::move(filter)),
      frame_(settings.earth_orientation) {}

void OnboardNavigation::add_ephemeris(const gnss::BroadcastEphemeris& record) {
  ++counters_.ephemerides[static_cast<std::size_t>(ephemerides_.accept(record))];
}

void OnboardNavigation::store(std::array<BufferedEpoch, kEpochs>& buffer, const nav::GpsReceiverEpoch& epoch,
                              const Eigen::Matrix3d& body_to_gcrf) {
  BufferedEpoch* slot = &buffer[0];
  for (BufferedEpoch& b : buffer) {
    if (b.filled && b.epoch.t == epoch.t) return;  // a repeat
    if (!b.filled) {
      slot = &b;
      break;
    }
    if (b.epoch.t < slot->epoch.t) slot = &b;  // the oldest is replaced
  }
  slot->filled = true;
  slot->processed = false;
  slot->epoch = epoch;
  slot->body_to_gcrf = body_to_gcrf;
}

void OnboardNavigation::add_own_epoch(const nav::GpsReceiverEpoch& epoch, const Eigen::Quaterniond& q_body_to_gcrf) {
  if (processed_any_ && epoch.t <= last_processed_) return;  // older than what the filter has
  const Eigen::Matrix3d body_to_gcrf = q_body_to_gcrf.toRotationMatrix();
  store(own_, epoch, body_to_gcrf);
  last_own_epoch_ = epoch.t;
  outgoing_.has_epoch = true;
  outgoing_.epoch = crosslink_epoch(epoch);
  outgoing_.q_body_to_gcrf = q_body_to_gcrf;
}

void OnboardNavigation::queue_impulse(core::GpsTime t, nav::Craft craft, const Eigen::Vector3d& dv_gcrf_mps) {
  if (impulse_count_ == kImpulses) {  // full (cannot happen at 46.5 s spacing): the oldest goes now
    apply_impulses_before(impulses_[1].t);
  }
  int k = impulse_count_++;
  for (; k > 0 && impulses_[static_cast<std::size_t>(k - 1)].t > t; --k) {
    impulses_[static_cast<std::size_t>(k)] = impulses_[static_cast<std::size_t>(k - 1)];
  }
  impulses_[static_cast<std::size_t>(k)] = PendingImpulse{t, craft, dv_gcrf_mps};
}

void OnboardNavigation::add_own_impulse(const ExecutedImpulse& impulse) {
  queue_impulse(impulse.t, local_, impulse.dv_gcrf_mps);
  auto& sent = outgoing_.impulses;
  for (int k = kCrosslinkImpulses - 1; k > 0; --k) sent[static_cast<std::size_t>(k)] = sent[static_cast<std::size_t>(k - 1)];
  sent[0] = impulse;
  outgoing_.impulse_count = std::min(outgoing_.impulse_count + 1, kCrosslinkImpulses);
}

void OnboardNavigation::queue_range(const LaserRange& range) {
  if (range_count_ == kRanges) {
    std::move(ranges_.begin() + 1, ranges_.end(), ranges_.begin());  // the oldest goes
    --range_count_;
  }
  ranges_[static_cast<std::size_t>(range_count_++)] = range;
}

void OnboardNavigation::add_laser_range(const LaserRange& range) {
  queue_range(range);
  outgoing_.has_range = true;
  outgoing_.range = range;
}

void OnboardNavigation::add_peer(const CrosslinkNavigation& peer) {
  if (peer.has_epoch && !(processed_any_ && peer.epoch.t <= last_processed_)) {
    store(peer_, receiver_epoch(peer.epoch), peer.q_body_to_gcrf.toRotationMatrix());
  }
  // Oldest first, each once (they are repeated in every message).
  for (int k = peer.impulse_count - 1; k >= 0; --k) {
    const ExecutedImpulse& i = peer.impulses[static_cast<std::size_t>(k)];
    if (have_peer_impulse_ && i.t <= last_peer_impulse_) continue;
    queue_impulse(i.t, remote_, i.dv_gcrf_mps);
    have_peer_impulse_ = true;
    last_peer_impulse_ = i.t;
  }
  if (peer.has_range && !(have_range_ && peer.range.t <= last_peer_range_)) {
    queue_range(peer.range);
    have_range_ = true;
    last_peer_range_ = peer.range.t;
  }
}

OnboardNavigation::BufferedEpoch* OnboardNavigation::next_own_epoch() {
  BufferedEpoch* next = nullptr;
  for (BufferedEpoch& b : own_) {
    if (b.filled && !b.processed && (next == nullptr || b.epoch.t < next->epoch.t)) next = &b;
  }
  return next;
}

OnboardNavigation::BufferedEpoch* OnboardNavigation::peer_epoch(core::GpsTime t) {
  for (BufferedEpoch& b : peer_) {
    if (b.filled && b.epoch.t == t) return &b;
  }
  return nullptr;
}

nav::AntennaGeometry OnboardNavigation::antenna(const Eigen::Matrix3d& body_to_gcrf) const {
  nav::AntennaGeometry a;
  a.body_to_gcrf = body_to_gcrf;
  a.arp_body_m = settings_.antenna_arp_body_m;
  a.pco_body_m = settings_.antenna_pco_m * Eigen::Vector3d::UnitZ();
  a.boresight_body = Eigen::Vector3d::UnitZ();
  return a;
}

void OnboardNavigation::cold_start(const BufferedEpoch& own, const BufferedEpoch& peer) {
  const bool dsc_local = local_ == nav::Craft::kDsc;
  const BufferedEpoch& dsc = dsc_local ? own : peer;
  const BufferedEpoch& osc = dsc_local ? peer : own;
  const auto start =
      cold_.add(dsc.epoch, osc.epoch, antenna(dsc.body_to_gcrf), antenna(osc.body_to_gcrf), ephemerides_, frame_);
  if (!start) return;
  filter_.initialise(start->t, start->dsc_gcrf, start->osc_gcrf, start->dsc_clock_m, start->osc_clock_m);
  last_update_ = start->t;
  // Impulses before the start are in the measured states already.
  const auto first = impulses_.begin();
  impulse_count_ = static_cast<int>(
      std::remove_if(first, first + impulse_count_, [&](const PendingImpulse& i) { return i.t < start->t; }) - first);
}

void OnboardNavigation::apply_impulses_before(core::GpsTime t) {
  int done = 0;
  for (; done < impulse_count_ && impulses_[static_cast<std::size_t>(done)].t < t; ++done) {
    const PendingImpulse& i = impulses_[static_cast<std::size_t>(done)];
    if (!filter_.initialised()) continue;
    const double late_s = filter_.epoch().seconds_since(i.t);
    if (late_s > 0.0) {
      ++counters_.impulses_late;
    } else {
      filter_.predict(i.t);
    }
    if (filter_.apply_impulse(i.craft, i.dv_gcrf_mps, std::max(0.0, late_s))) ++counters_.impulses_applied;
  }
  std::move(impulses_.begin() + done, impulses_.begin() + impulse_count_, impulses_.begin());
  impulse_count_ -= done;
}

void OnboardNavigation::fuse_range(core::GpsTime t, const Eigen::Matrix3d& dsc_body_to_gcrf, const Eigen::Matrix3d& osc_body_to_gcrf) {
  for (int k = 0; k < range_count_; ++k) {
    const LaserRange& r = ranges_[static_cast<std::size_t>(k)];
    if (r.t != t) continue;
    nav::LaserRangeGeometry g;
    g.dsc_body_to_gcrf = dsc_body_to_gcrf;
    g.osc_body_to_gcrf = osc_body_to_gcrf;
    g.dsc_lever_body_m = settings_.lrf_lever_body_m;
    g.osc_lever_body_m = settings_.lrf_lever_body_m;
    g.bias_m = settings_.lrf_bias_m;
    const auto status = filter_.update_laser_range(r.range_m, settings_.lrf_sigma_m, g);
    ++(status == nav::ScalarUpdateStatus::kAccepted ? counters_.laser_used : counters_.laser_rejected);
  }
  // Ranges of this epoch and before are done with.
  const auto first = ranges_.begin();
  range_count_ = static_cast<int>(std::remove_if(first, first + range_count_, [t](const LaserRange& r) { return r.t <= t; }) - first);
}

void OnboardNavigation::process(const BufferedEpoch& own, const BufferedEpoch* peer) {
  const core::GpsTime t = own.epoch.t;
  if (!filter_.initialised()) {
    if (peer != nullptr) cold_start(own, *peer);
    return;
  }
  if (t < filter_.epoch()) return;  // the filter coasted past it
  apply_impulses_before(t);
  filter_.predict(t);
  const bool dsc_local = local_ == nav::Craft::kDsc;
  const Eigen::Matrix3d& own_attitude = own.body_to_gcrf;
  const Eigen::Matrix3d& peer_attitude = peer != nullptr ? peer->body_to_gcrf : own.body_to_gcrf;
  nav::CdgpsEpochInput input;
  input.dsc = dsc_local ? &own.epoch : (peer != nullptr ? &peer->epoch : nullptr);
  input.osc = dsc_local ? (peer != nullptr ? &peer->epoch : nullptr) : &own.epoch;
  input.dsc_antenna = antenna(dsc_local ? own_attitude : peer_attitude);
  input.osc_antenna = antenna(dsc_local ? peer_attitude : own_attitude);
  last_report_ = filter_.update(input, ephemerides_, frame_);
  fixed_current_ = true;
  if (!last_report_.accepted) {
    ++counters_.epochs_refused;
    return;
  }
  last_update_ = t;
  counters_.clock_jumps += last_report_.clock_jumps;
  ++(peer != nullptr ? counters_.epochs_joint : counters_.epochs_alone);
  if (last_report_.fix_applied) ++counters_.epochs_fixed;
  if (last_report_.wrong_fix_refused) ++counters_.wrong_fixes_refused;
  if (settings_.fuse_laser && peer != nullptr) {
    fuse_range(t, dsc_local ? own_attitude : peer_attitude, dsc_local ? peer_attitude : own_attitude);
  }
}

std::optional<NavigationSolution> OnboardNavigation::solve(core::GpsTime now) {
  for (BufferedEpoch* own = next_own_epoch(); own != nullptr; own = next_own_epoch()) {
    BufferedEpoch* peer = peer_epoch(own->epoch.t);
    if (peer == nullptr && now.seconds_since(own->epoch.t) < settings_.peer_wait_s) break;
    process(*own, peer);
    own->processed = true;
    processed_any_ = true;
    last_processed_ = own->epoch.t;
    for (BufferedEpoch& b : peer_) {
      if (b.filled && b.epoch.t <= last_processed_) b.filled = false;
    }
  }
  if (!filter_.initialised()) {
    valid_ = false;
    return std::nullopt;
  }
  if (next_own_epoch() == nullptr && now.seconds_since(last_update_) >= settings_.coast_after_s) {
    apply_impulses_before(now);
    filter_.predict(now);  // a GPS outage: the covariance grows with the dynamics
    fixed_current_ = false;
  }
  solution_ = solution(now);
  const auto& C = solution_->relative_covariance_rtn;
  valid_ = C.topLeftCorner<3, 3>().trace() <= settings_.valid_position_sigma_m * settings_.valid_position_sigma_m &&
           C.bottomRightCorner<3, 3>().trace() <= settings_.valid_velocity_sigma_mps * settings_.valid_velocity_sigma_mps;
  if (!valid_) return std::nullopt;
  return solution_;
}

NavigationSolution OnboardNavigation::solution(core::GpsTime now) {
  const bool use_fixed = last_report_.fix_applied && fixed_current_;
  nav::NavVector x = filter_.forecast(use_fixed ? filter_.x_fixed() : filter_.x(), now);
  const core::GpsTime epoch = filter_.epoch();
  for (int k = 0; k < impulse_count_; ++k) {  // executed since the epoch, not yet in the filter
    const PendingImpulse& i = impulses_[static_cast<std::size_t>(k)];
    if (i.t < epoch || i.t >= now) continue;
    x.segment<3>(nav::state::velocity(i.craft)) += i.dv_gcrf_mps / nav::state::kVelocityUnit;
    x.segment<3>(nav::state::position(i.craft)) += i.dv_gcrf_mps * now.seconds_since(i.t);
  }
  NavigationSolution s;
  s.t = now;
  s.chief_gcrf = nav::CdgpsFilter::centre_of_mass(x, nav::Craft::kDsc);
  s.deputy_gcrf = nav::CdgpsFilter::centre_of_mass(x, nav::Craft::kOsc);
  s.relative_covariance_rtn = relative_covariance_rtn(use_fixed ? filter_.P_fixed() : filter_.P(), s.chief_gcrf);
  return s;
}

NavigationTelemetry OnboardNavigation::telemetry(core::GpsTime now) const {
  NavigationTelemetry out;
  out.t = solution_ ? solution_->t : now;
  out.counters = counters_;
  out.update_t = last_update_;
  out.fix_applied = last_report_.fix_applied;
  if (out.fix_applied) fixed_double_differences(filter_, last_report_, out);
  if (!solution_) return out;
  out.has_solution = true;
  out.valid = valid_;
  out.fixed = fixed();
  out.dsc_gcrf = solution_->chief_gcrf;
  out.osc_gcrf = solution_->deputy_gcrf;
  out.relative_sigma_rtn_m = solution_->relative_covariance_rtn.diagonal().head<3>().cwiseMax(0.0).cwiseSqrt();
  // The phase-centre and empirical states of the solution in use (solution(): fixed or float).
  const nav::NavVector& x = out.fixed ? filter_.x_fixed() : filter_.x();
  namespace st = nav::state;
  out.p_dsc_body_m = st::kPhaseCenterUnit * x.segment<3>(st::phase_center(nav::Craft::kDsc));
  out.p_osc_body_m = st::kPhaseCenterUnit * x.segment<3>(st::phase_center(nav::Craft::kOsc));
  out.empirical_dsc_rtn_mps2 = st::kEmpiricalUnit * x.segment<3>(st::empirical_acceleration(nav::Craft::kDsc));
  out.empirical_osc_rtn_mps2 = st::kEmpiricalUnit * x.segment<3>(st::empirical_acceleration(nav::Craft::kOsc));
  return out;
}

CrosslinkEpoch crosslink_epoch(const nav::GpsReceiverEpoch& epoch) {
  CrosslinkEpoch out;
  out.t = epoch.t;
  out.count = std::clamp(epoch.count, 0, gnss::kMaxGpsChannels);
  for (std::size_t k = 0; k < static_cast<std::size_t>(out.count); ++k) {
    const nav::GpsObservation& o = epoch.observations[k];
    out.observations[k] = CrosslinkObservation{o.prn, o.code_m, o.phase_cycles, o.loss_of_lock, o.half_cycle};
  }
  return out;
}

nav::GpsReceiverEpoch receiver_epoch(const CrosslinkEpoch& epoch) {
  static_assert(gnss::kMaxGpsChannels <= nav::kGpsSlots, "a receiver epoch holds every crosslinked observation");
  nav::GpsReceiverEpoch out;
  out.t = epoch.t;
  out.count = std::clamp(epoch.count, 0, gnss::kMaxGpsChannels);
  for (std::size_t k = 0; k < static_cast<std::size_t>(out.count); ++k) {
    const CrosslinkObservation& o = epoch.observations[k];
    out.observations[k] = nav::GpsObservation{o.prn, o.code_m, o.phase_cycles, o.loss_of_lock, o.half_cycle};
  }
  return out;
}

}  // namespace visors::gnc
