#pragma once
// When a GPS receiver has decoded a broadcast data set (IS-GPS-200 sec. 20.3.2: a 1500-bit frame
// of five 6-second subframes every 30 s, aligned to GPS time; the clock and ephemeris are in
// subframes 1-3, which repeat each frame while the data set is broadcast).
//
// A receiver that starts collecting at time a (the later of its lock on the satellite and the
// first broadcast of the data set) needs each of subframes 1, 2 and 3 received whole once after
// a, in any order (the same data set, so frames can be mixed): the data set is decoded at the
// latest of their ends. Starting exactly at a frame's start takes 18 s; just after it, 36 s
// (subframes 2 and 3 of this frame, subframe 1 of the next). The 70 ms signal travel time is
// ignored.
//
// The data sets the simulator broadcasts (sim/gps_satellite_truth.hpp): per satellite, the first
// set is in force from before the run, each next one (t_oe refresh_s later) from its t_oe -
// refresh_s / 2, so that the set in force is the one nearest in t_oe. A receiver passes on the set
// in force once it has decoded it since its lock (lock_time_s before t), and each set once: the
// closed loop (`visors run`, the flight software's GPS message) and `visors gnss-sim`
// (ephemeris_decoded.csv) follow the same rule through newly_decoded_data_set.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::sim {

/// The GPS time [s] at which subframes 1-3 have all been received whole since `from_gps_s` [s]
/// (GPS seconds since the GPS epoch: frames start at multiples of 30 s).
double ephemeris_decoded_at(double from_gps_s);

/// Per PRN, the indices into `records` (GpsSatelliteTruth::broadcast_records: the first sets, then
/// each refresh's) of its data sets, in the order of their t_oe.
using DataSetsByPrn = std::array<std::vector<std::size_t>, gnss::kMaxGpsPrn + 1>;
DataSetsByPrn data_sets_by_prn(std::span<const gnss::BroadcastEphemeris> records);

/// The data set of one satellite (a position in `sets`, its entry of DataSetsByPrn) that a
/// receiver passes on at t, if any: the set in force at t (file comment; half_refresh_s =
/// refresh_s / 2, 0: the first set for ever), unless the receiver has passed it on already (`next`:
/// the position after the last set it passed on, 0 for none) or has not decoded it by t, its
/// subframes 1-3 received whole since the later of its lock (lock_time_s [s] of continuous
/// tracking before t) and the set's first broadcast (ephemeris_decoded_at: 18-36 s).
std::optional<std::size_t> newly_decoded_data_set(std::span<const gnss::BroadcastEphemeris> records,
                                                  std::span<const std::size_t> sets, core::GpsTime t,
                                                  double half_refresh_s, double lock_time_s, std::size_t next);

}  // namespace visors::sim
