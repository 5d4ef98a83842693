#pragma once
// The sensors of the closed-loop campaign as the truth sees them (ground side of the simulator):
// each spacecraft's GPS receiver in its true pose, the broadcast records it has decoded
// (sim/navigation_message.hpp), its host computer's time at tone (sim/host_clock.hpp), the OSC's
// laser rangefinder between the true payload points, and, for `[navigation] mode = "ideal"`, the
// ideal navigation's solution. What they measure goes to the host application as messages; the
// truth of each receiver's phase goes to the navigation score.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "visors/core/earth_frames.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/gps_receiver.hpp"
#include "visors/sim/gps_world.hpp"
#include "visors/sim/host_clock.hpp"
#include "visors/sim/ideal_navigation.hpp"
#include "visors/sim/navigation_message.hpp"
#include "visors/sim/navigation_score.hpp"
#include "visors/sim/random_stream.hpp"
#include "visors/sim/truth_world.hpp"

namespace visors::sim {

/// One spacecraft's sensors.
struct SpacecraftSensors {
  std::optional<GpsReceiver> receiver;  // [navigation] mode = "cdgps"
  /// Per PRN, the next broadcast data set the receiver has not passed on yet.
  std::array<std::size_t, gnss::kMaxGpsPrn + 1> next_ephemeris{};
  std::optional<HostClock> clock;             // when its computer's time at tone really happens
  std::optional<IdealNavigation> navigation;  // [navigation] mode = "ideal"
};

class Sensors {
 public:
  /// Each spacecraft's sensors (streams "<name>.gps", "<name>.clock", "<name>.navigation",
  /// "osc.lrf"); with `gps` (cdgps mode) the receivers, with the phase-centre errors the truth
  /// drew. Errors name the scenario field.
  static core::Result<Sensors> create(const CampaignScenario& scenario, const TruthWorld& truth, std::optional<GpsWorld> gps);

  [[nodiscard]] bool has_gps() const { return gps_.has_value(); }
  /// The Earth's orientation at t (identity without GPS).
  [[nodiscard]] EpochFrame frame(core::GpsTime t);

  /// Spacecraft k's receiver epoch at t (t_s since t0) in its true pose and the broadcast record
  /// it decoded by then; the channels' phase truth goes to `score`. Nothing in a data gap.
  std::optional<gnc::GpsMessage> measure_gps(std::size_t k, const TruthSpacecraft& truth, const EpochFrame& frame,
                                             core::GpsTime t, double t_s, NavigationScore& score);
  /// The OSC's rangefinder at step `step` (t_s since t0) when powered (file comment of
  /// sensors.cpp); nothing between its samples.
  std::optional<gnc::LaserRange> measure_range(const TruthWorld& truth, core::GpsTime t, double t_s, std::int64_t step,
                                               bool powered);
  /// The ideal navigation's solution of spacecraft k at t; dt_s since its previous one.
  gnc::NavigationSolution ideal_solution(std::size_t k, core::GpsTime t, const TruthWorld& truth, double dt_s);

  /// The tone of spacecraft k's computer at t_s: disciplined while its receiver has a solution.
  void tone(std::size_t k, double t_s, bool receiver_solution) { craft_[k].clock->tone(t_s, receiver_solution); }
  [[nodiscard]] const HostClock& clock(std::size_t k) const { return *craft_[k].clock; }
  [[nodiscard]] GpsReceiver& receiver(std::size_t k) { return *craft_[k].receiver; }
  [[nodiscard]] const GpsReceiver& receiver(std::size_t k) const { return *craft_[k].receiver; }

 private:
  Sensors(const CampaignScenario& scenario, std::optional<GpsWorld> gps);
  void decode_ephemeris(std::size_t k, core::GpsTime t, gnc::GpsMessage& message);

  GnssLrfSettings lrf_;
  double step_s_ = 1.0;
  double half_refresh_s_ = 0.0;  // half the broadcast data sets' refresh interval [s]
  std::array<SpacecraftSensors, 2> craft_;  // dsc, osc
  std::optional<GpsWorld> gps_;
  /// Per PRN, the indices of its broadcast data sets in GpsSatelliteTruth::broadcast_records(),
  /// in t_oe order.
  DataSetsByPrn sets_by_prn_;
  core::InterpolatedEarthFrame earth_frame_;
  RandomStream lrf_rng_;
};

}  // namespace visors::sim
