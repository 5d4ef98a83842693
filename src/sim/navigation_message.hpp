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

namespace visors::sim {

/// The GPS time [s] at which subframes 1-3 have all been received whole since `from_gps_s` [s]
/// (GPS seconds since the GPS epoch: frames start at multiples of 30 s).
double ephemeris_decoded_at(double from_gps_s);

}  // namespace visors::sim
