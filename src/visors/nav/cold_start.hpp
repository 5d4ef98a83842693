#pragma once
// The navigation filter's cold start on board: both spacecraft's states and receiver clocks from
// their receivers' code alone, before any filter exists. A point solution of each receiver
// (nav/point_positioning.hpp), another kGapS later; the velocity is their chord plus half the
// two-body acceleration times the gap (the chord is the mean velocity over the gap: 42 m/s off
// without the correction at 10 s), the centre of mass the phase centre minus the antenna's lever
// arm in the known attitude. A pair more than 3 kGapS apart (an outage between them) starts over.
// Allocation-free.

#include <optional>

#include "visors/core/earth_frames.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/gnss/ephemeris_source.hpp"
#include "visors/nav/gps_observations.hpp"
#include "visors/nav/gps_range_model.hpp"
#include "visors/nav/point_positioning.hpp"

namespace visors::nav {

struct ColdStartSolution {
  core::GpsTime t;
  core::StateVector dsc_gcrf, osc_gcrf;  // centres of mass [m, m/s]
  double dsc_clock_m = 0.0, osc_clock_m = 0.0;
};

class ColdStart {
 public:
  static constexpr double kGapS = 10.0;  // between the two point solutions [s]

  /// One joint epoch (both receivers' epochs at the same time tag, and each antenna's geometry
  /// in its attitude then): the solution once two joint point solutions kGapS apart exist.
  std::optional<ColdStartSolution> add(const GpsReceiverEpoch& dsc, const GpsReceiverEpoch& osc, const AntennaGeometry& dsc_antenna,
                                       const AntennaGeometry& osc_antenna, const gnss::EphemerisSource& ephemerides,
                                       core::OnboardEarthFrame& frame);

 private:
  bool have_first_ = false;
  core::GpsTime t_first_;
  PointSolution first_[2];
};

}  // namespace visors::nav
