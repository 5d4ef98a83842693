#include "visors/gnss/constellation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss {

namespace {

double wrap_pi(double angle) { return std::remainder(angle, 2.0 * kGpsPi); }

// Start of the GPS week holding t [s since the GPS epoch].
double week_start_s(core::GpsTime t) { return static_cast<double>(t.week()) * 604800.0; }

}  // namespace

BroadcastEphemeris propagate_to_epoch(const BroadcastEphemeris& record, core::GpsTime new_toe) {
  const double shift = new_toe.seconds_since(record.toe);
  const double a = record.sqrt_a * record.sqrt_a;
  const double n = std::sqrt(kGpsMu / (a * a * a)) + record.delta_n_radps;
  BroadcastEphemeris moved = record;
  moved.toe = new_toe;
  moved.toc = new_toe;
  moved.transmission = new_toe;
  moved.m0_rad = wrap_pi(record.m0_rad + n * shift);
  moved.omega0_rad = wrap_pi(record.omega0_rad + record.omega_dot_radps * shift -
                             kGpsEarthRate * (week_start_s(new_toe) - week_start_s(record.toe)));
  moved.idot_radps = 0.0;
  moved.fit_interval_h = 240.0;
  return moved;
}

core::Result<GpsConstellation> GpsConstellation::from_broadcast(const EphemerisSet& set, core::GpsTime source_time,
                                                                core::GpsTime epoch) {
  GpsConstellation constellation;
  for (int prn = 1; prn <= kMaxGpsPrn; ++prn) {
    if (const BroadcastEphemeris* record = set.nearest(prn, source_time)) {
      constellation.satellites_.push_back(propagate_to_epoch(*record, epoch));
    }
  }
  if (constellation.satellites_.empty()) {
    return core::Error{"source_time", "the navigation data have no usable record"};
  }
  return constellation;
}

core::Result<GpsConstellation> GpsConstellation::from_records(std::span<const BroadcastEphemeris> records) {
  GpsConstellation constellation;
  for (std::size_t k = 0; k < records.size(); ++k) {
    if (auto valid = validate(records[k]); !valid) {
      return core::Error{"records[" + std::to_string(k) + "]." + valid.field(), std::string(core::describe(valid.problem()))};
    }
    for (const auto& other : constellation.satellites_) {
      if (other.prn == records[k].prn) return core::Error{"records[" + std::to_string(k) + "].prn", "PRN given twice"};
    }
    constellation.satellites_.push_back(records[k]);
  }
  std::sort(constellation.satellites_.begin(), constellation.satellites_.end(),
            [](const BroadcastEphemeris& a, const BroadcastEphemeris& b) { return a.prn < b.prn; });
  return constellation;
}

const BroadcastEphemeris* GpsConstellation::satellite(int prn) const {
  for (const auto& s : satellites_) {
    if (s.prn == prn) return &s;
  }
  return nullptr;
}

}  // namespace visors::gnss
