#include "visors/baseline/baseline_processor.hpp"

#include <array>
#include <cmath>

#include <Eigen/Cholesky>

#include "visors/baseline/double_difference_system.hpp"
#include "visors/baseline/signal_model.hpp"
#include "visors/baseline/single_difference.hpp"
#include "visors/core/constants.hpp"

namespace visors::baseline {
namespace {

using Signals = std::array<std::optional<SatelliteSignal>, kMaxPrn + 1>;  // by PRN

struct EpochPair {
  const ReceiverEpoch* rover = nullptr;
  const ReceiverEpoch* base = nullptr;
};

// Rover and base epochs whose time tags agree within the tolerance (both lists in time order).
std::vector<EpochPair> pair_epochs(const ReceiverObservables& rover, const ReceiverObservables& base, double tolerance_s,
                                   BaselineResult& result) {
  std::vector<EpochPair> pairs;
  std::size_t i = 0, j = 0;
  while (i < rover.epochs.size() && j < base.epochs.size()) {
    const double dt = rover.epochs[i].t.seconds_since(base.epochs[j].t);
    if (std::abs(dt) <= tolerance_s) {
      pairs.push_back({&rover.epochs[i++], &base.epochs[j++]});
    } else if (dt < 0.0) {
      ++i, ++result.rover_unpaired;
    } else {
      ++j, ++result.base_unpaired;
    }
  }
  result.rover_unpaired += static_cast<int>(rover.epochs.size() - i);
  result.base_unpaired += static_cast<int>(base.epochs.size() - j);
  return pairs;
}

bool valid_prn(int prn) { return prn >= 1 && prn <= kMaxPrn; }

Signals model_signals(const BaselineInputs& in, const ReceiverEpoch& epoch, const ReceiverSite& site) {
  Signals signals;
  for (const auto& s : epoch.satellites) {
    if (!valid_prn(s.prn) || !std::isfinite(s.code_m[0])) continue;
    signals[static_cast<std::size_t>(s.prn)] = model_signal(in.ephemerides, in.ionosphere, s.prn, epoch.t, s.code_m[0], site);
  }
  return signals;
}

const SatelliteObservables* find(const ReceiverEpoch& epoch, int prn) {
  for (const auto& s : epoch.satellites) {
    if (s.prn == prn) return &s;
  }
  return nullptr;
}

PositionEstimate estimate(const Eigen::Vector3d& r, const Eigen::Matrix3d& cov, const ReceiverSite& base) {
  PositionEstimate e;
  e.valid = r.allFinite() && cov.allFinite();
  e.r_ecef_m = r;
  e.baseline_enu_m = base.enu_from_ecef * (r - base.r_ecef_m);
  e.sigma_enu_m = (base.enu_from_ecef * cov * base.enu_from_ecef.transpose()).diagonal().cwiseMax(0.0).cwiseSqrt();
  return e;
}

// The single differences of the satellites both receivers see above the mask, computed at the
// rover position `r`; the others are counted by reason when `result` is given.
std::vector<SingleDifference> single_differences(const BaselineInputs& in, const EpochPair& pair, const Signals& base,
                                                 const Eigen::Vector3d& r, const BaselineSettings& settings,
                                                 BaselineResult* result) {
  const auto count = [&](const char* reason) {
    if (result != nullptr) ++result->rejected_counts[reason];
  };
  const Signals rover = model_signals(in, *pair.rover, make_site(r));
  const double mask = settings.elevation_mask_deg * core::kDegToRad;
  std::vector<SingleDifference> sds;
  for (const auto& ro : pair.rover->satellites) {
    if (!valid_prn(ro.prn)) continue;
    const SatelliteObservables* bo = find(*pair.base, ro.prn);
    const auto& rs = rover[static_cast<std::size_t>(ro.prn)];
    const auto& bs = base[static_cast<std::size_t>(ro.prn)];
    if (bo == nullptr) { count("not_at_base"); continue; }
    if (!rs || !bs) { count(std::isfinite(ro.code_m[0]) && std::isfinite(bo->code_m[0]) ? "no_ephemeris" : "no_code"); continue; }
    if (rs->elevation_rad < mask || bs->elevation_rad < mask) { count("below_elevation_mask"); continue; }
    sds.push_back(single_difference(ro, *rs, *bo, *bs, settings));
  }
  return sds;
}

// DD pseudorange least squares for the rover position, from r0 (Gauss-Newton, <= 8 iterations,
// until the correction is below 1 mm). nullopt with fewer than 4 satellites.
std::optional<std::pair<Eigen::Vector3d, Eigen::Matrix3d>> code_solution(const BaselineInputs& in, const EpochPair& pair,
                                                                         const Signals& base, Eigen::Vector3d r,
                                                                         const BaselineSettings& settings) {
  const auto any = [](int, int) { return true; };
  for (int iteration = 0; iteration < 8; ++iteration) {
    const auto sds = single_differences(in, pair, base, r, settings, nullptr);
    const auto system = build_dd_system(sds, make_groups(sds, Observable::kCode, any), false);
    if (system.rows.size() < 3) return std::nullopt;
    const Eigen::LDLT<Eigen::MatrixXd> r_ldlt(system.R);
    const Eigen::Matrix3d normal = system.H.transpose() * r_ldlt.solve(system.H);
    const Eigen::Vector3d rhs = system.H.transpose() * r_ldlt.solve(system.y);
    const Eigen::LDLT<Eigen::Matrix3d> n_ldlt(normal);
    if (n_ldlt.info() != Eigen::Success || !(n_ldlt.vectorD().array() > 0.0).all()) return std::nullopt;
    const Eigen::Vector3d dr = n_ldlt.solve(rhs);
    r += dr;
    if (!r.allFinite()) return std::nullopt;
    if (dr.norm() < 1e-3) return std::pair{r, Eigen::Matrix3d(n_ldlt.solve(Eigen::Matrix3d::Identity()))};
  }
  return std::nullopt;
}

// Cycle-slip tests on the raw observables of each receiver (processor comment).
class SlipDetector {
 public:
  explicit SlipDetector(const BaselineSettings& settings) : settings_(settings) {}

  /// The reason each frequency's phase of `prn` must be reinitialised at t (nullptr: none).
  std::array<const char*, kFrequencies> check(core::GpsTime t, const SatelliteObservables& rover,
                                              const SatelliteObservables& base) {
    std::array<const char*, kFrequencies> reason{};
    const bool dual = settings_.frequencies == FrequencySet::kL1L2;
    for (int receiver = 0; receiver < 2; ++receiver) {
      const SatelliteObservables& o = receiver == 0 ? rover : base;
      Track& track = tracks_[static_cast<std::size_t>(receiver)][static_cast<std::size_t>(o.prn)];
      const bool gap = track.seen && t.seconds_since(track.last) > settings_.max_gap_s;
      for (std::size_t f = 0; f < kFrequencies; ++f) {
        if (o.loss_of_lock[f] && reason[f] == nullptr) reason[f] = "loss_of_lock";
        if (gap && reason[f] == nullptr) reason[f] = "gap";
      }
      const double gf = dual ? wavelength_m(0) * o.phase_cyc[0] - wavelength_m(1) * o.phase_cyc[1]
                             : std::numeric_limits<double>::quiet_NaN();
      if (!gap && std::isfinite(gf) && std::isfinite(track.gf) && std::abs(gf - track.gf) > settings_.slip_geometry_free_m) {
        for (auto& r : reason) {
          if (r == nullptr) r = "geometry_free_jump";
        }
      }
      track = {t, gf, true};
    }
    return reason;
  }

 private:
  struct Track {
    core::GpsTime last;
    double gf = std::numeric_limits<double>::quiet_NaN();
    bool seen = false;
  };
  BaselineSettings settings_;
  std::array<std::array<Track, kMaxPrn + 1>, 2> tracks_{};
};

// Starts new ambiguity slots, reinitialises slipped ones, releases those unused for max_gap_s.
class SlotManager {
 public:
  explicit SlotManager(const BaselineSettings& settings) : settings_(settings), slips_(settings) {}

  void update(core::GpsTime t, const EpochPair& pair, const std::vector<SingleDifference>& sds, BaselineFilter& filter,
              BaselineResult& result) {
    const int used = settings_.frequencies == FrequencySet::kL1 ? 1 : 2;
    for (const auto& sd : sds) {
      const auto verdict = slips_.check(t, *find(*pair.rover, sd.prn), *find(*pair.base, sd.prn));
      for (int f = 0; f < used; ++f) {
        const auto fi = static_cast<std::size_t>(f);
        if (!std::isfinite(sd.phase_m[fi]) || !std::isfinite(sd.code_m[fi])) continue;
        last_used_[fi][static_cast<std::size_t>(sd.prn)] = t;
        const bool active = filter.ambiguity_active(f, sd.prn);
        if (active && verdict[fi] == nullptr) continue;
        filter.reset_ambiguity(f, sd.prn, (sd.phase_m[fi] - sd.code_m[fi]) / wavelength_m(f));
        if (active) {
          ++result.rejected_counts[verdict[fi]];
          result.events.push_back({t, sd.prn, f, verdict[fi]});
        }
      }
    }
    release_stale(t, used, filter);
  }

 private:
  void release_stale(core::GpsTime t, int used, BaselineFilter& filter) {
    for (int f = 0; f < used; ++f) {
      for (int prn = 1; prn <= kMaxPrn; ++prn) {
        const core::GpsTime last = last_used_[static_cast<std::size_t>(f)][static_cast<std::size_t>(prn)];
        if (filter.ambiguity_active(f, prn) && t.seconds_since(last) > settings_.max_gap_s) {
          filter.release_ambiguity(f, prn);
        }
      }
    }
  }

  BaselineSettings settings_;
  SlipDetector slips_;
  std::array<std::array<core::GpsTime, kMaxPrn + 1>, kFrequencies> last_used_{};
};

std::string iar_label(const FilterEpochResult& fr, AmbiguityMode mode) {
  if (mode == AmbiguityMode::kOff) return "off";
  if (fr.wrong_fix_refused) return "wrong_fix_refused";
  if (fr.ambiguities == 0) return "no_ambiguities";
  if (fr.fix.outcome == nav::FixOutcome::kFloat) return "float:" + std::string(nav::to_string(fr.fix.reason));
  return std::string(nav::to_string(fr.fix.outcome));
}

EpochRecord record_epoch(core::GpsTime t, const FilterEpochResult& fr, const PositionEstimate& code, int satellites,
                         const ReceiverSite& base, const BaselineSettings& settings) {
  EpochRecord e;
  e.t = t;
  e.code = code;
  e.satellites = satellites;
  e.phase_rows = fr.phase_rows;
  e.ambiguities = fr.ambiguities;
  e.fixed = fr.fix_accepted ? fr.fix.fixed : 0;
  e.ratio = fr.fix.ratio;
  e.success_rate = fr.fix.success_rate;
  e.iar = iar_label(fr, settings.ambiguity_mode);
  if (fr.float_ok) e.floating = estimate(fr.r_float_m, fr.cov_float_m2, base);
  if (fr.fix_accepted) {
    e.status = fr.fix.outcome == nav::FixOutcome::kFixed ? SolutionStatus::kFix : SolutionStatus::kPartial;
    e.solution = estimate(fr.r_fixed_m, fr.cov_fixed_m2, base);
  } else if (e.floating.valid) {
    e.status = SolutionStatus::kFloat;
    e.solution = e.floating;
  } else if (code.valid) {
    e.status = SolutionStatus::kCode;
    e.solution = code;
  }
  return e;
}

}  // namespace

core::Result<BaselineResult> process_baseline(const BaselineInputs& in, const BaselineSettings& settings) {
  auto filter_result = BaselineFilter::create(settings);
  if (!filter_result) return filter_result.error();
  BaselineFilter filter = std::move(filter_result).value();
  BaselineResult result;
  result.rover_epochs = static_cast<int>(in.rover.epochs.size());
  result.base_epochs = static_cast<int>(in.base.epochs.size());
  const ReceiverSite base_site = make_site(in.base_ecef_m);
  SlotManager slots(settings);
  Eigen::Vector3d r_guess = in.base_ecef_m;  // a start 3 km off converges in 3 iterations
  for (const EpochPair& pair : pair_epochs(in.rover, in.base, settings.epoch_tolerance_s, result)) {
    const core::GpsTime t = pair.rover->t;
    const Signals base = model_signals(in, *pair.base, base_site);
    const auto code = code_solution(in, pair, base, filter.initialised() ? filter.rover_position() : r_guess, settings);
    PositionEstimate code_estimate;
    if (code) code_estimate = estimate(code->first, code->second, base_site);
    if (code && (settings.position_model == PositionModel::kKinematic || !filter.initialised())) {
      filter.set_position(code->first, settings.kinematic_position_sigma_m);
      r_guess = code->first;
    }
    if (!filter.initialised() || (settings.position_model == PositionModel::kKinematic && !code)) {
      ++result.rejected_counts["epoch_without_code_solution"];
      EpochRecord none;
      none.t = t;
      result.epochs.push_back(std::move(none));
      continue;
    }
    filter.predict(t);
    const auto sds = single_differences(in, pair, base, filter.rover_position(), settings, &result);
    slots.update(t, pair, sds, filter, result);
    const FilterEpochResult fr = filter.update(sds);
    for (const auto& r : fr.rejected) {
      ++result.rejected_counts[r.reason];
      result.events.push_back({t, r.prn, r.frequency, r.reason});
    }
    result.epochs.push_back(record_epoch(t, fr, code_estimate, static_cast<int>(sds.size()), base_site, settings));
    if (fr.float_ok) result.final_float = result.epochs.back().floating;
    if (result.epochs.back().status == SolutionStatus::kFix) result.final_fixed = result.epochs.back().solution;
  }
  return result;
}

}  // namespace visors::baseline
