#pragma once
// The geometric range of one GPS satellite from one receiver's antenna phase centre, as the
// navigation filter predicts it, with its partial derivatives with respect to that receiver's
// filter states (docs/algorithms/gnss-measurements.md#range-model): the common core of the GRAPHIC
// and SDCP measurement models (nav/gps_measurement_model.hpp).
//
// Instants. The filter's epoch t is the measurements' time tag taken as GPS time. The receiver
// time-tags its measurements with its own clock, so they were taken at the true reception
// instant t_r = t - c dt / c (c dt: the receiver clock offset state); the satellite transmitted
// at t_tx = t_r - rho / c. 1 us of clock offset is 7.6 mm of LEO motion, so t_r is modelled,
// not t.
//
// Geometry, inertial (GCRF):
//   R(t_r) = r(t) + v(t) (t_r - t) + C_body->gcrf (arp + pco + p)   receiver antenna phase centre
//   S(t_tx) = T_itrf->gcrf(t) R3(omega_E (t - t_tx)) s_itrf(t_tx)     satellite, broadcast ephemeris,
//        rotated by the Earth's turn from t_tx to t (the Sagnac rotation R3(omega_E tau) plus the
//        turn over t_r - t: the same as the ITRF -> GCRF matrix of t_r with R3(omega_E tau));
//   rho = |S(t_tx) - R(t_r)|, iterated on tau (three iterations converge below 1e-12 s).
// The acceleration over t_r - t (< ~1 ms: < 4 um) is neglected.
//
// Partials, exact for this model (light time included): differentiating
// rho = |S(t_r - rho/c) - R(t_r)| gives d rho (1 + e.V_s/c) = e.(V_s - V_r) dt_r - e.dR, with e the
// unit line of sight receiver -> satellite and V_s, V_r the inertial velocities, so
//   d rho/d r = -e'/D,  d rho/d v = -e' (t_r - t)/D,  d rho/d p = -e' C/D,
//   d rho/d(c dt) = -e.(V_s - V_r)/(c D)  (through t_r: the range rate over c, up to 2.5e-5),
//   with D = 1 + e.V_s/c (about 1 +- 1.3e-5: the usual d rho/d r = -e' is off by that much).
// SI units here; the filter scales them to its state units (nav/navigation_state.hpp).

#include <Eigen/Core>

#include "visors/core/earth_frames.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"

namespace visors::nav {

/// One receiver's part of the filter state, SI, at the filter epoch.
struct ReceiverEstimate {
  Eigen::Vector3d r_gcrf_m = Eigen::Vector3d::Zero();    // centre of mass [m]
  Eigen::Vector3d v_gcrf_mps = Eigen::Vector3d::Zero();  // [m/s]
  double clock_m = 0.0;                                  // c dt, receiver time minus GPS time [m]
  Eigen::Vector3d pco_error_body_m = Eigen::Vector3d::Zero();  // p [m]
};

/// The receiver antenna's known geometry at the epoch.
struct AntennaGeometry {
  Eigen::Matrix3d body_to_gcrf = Eigen::Matrix3d::Identity();  // attitude C_body->gcrf
  Eigen::Vector3d arp_body_m = Eigen::Vector3d::Zero();        // antenna reference point from the CoM [m]
  Eigen::Vector3d pco_body_m = Eigen::Vector3d::Zero();        // nominal phase-centre offset from the ARP [m]
  Eigen::Vector3d boresight_body = Eigen::Vector3d::UnitZ();   // antenna boresight (unit), for the elevation
};

struct RangePrediction {
  double range_m = 0.0;            // rho [m]
  double satellite_clock_m = 0.0;  // c dt_sat(t_tx) of an L1 C/A user (relativity and T_GD included) [m]
  Eigen::Vector3d line_of_sight_gcrf = Eigen::Vector3d::UnitX();  // e, receiver -> satellite
  Eigen::Vector3d satellite_gcrf_m = Eigen::Vector3d::Zero();     // S(t_tx) [m]
  Eigen::Vector3d antenna_gcrf_m = Eigen::Vector3d::Zero();       // R(t_r) [m]
  core::GpsTime reception_time;    // t_r
  core::GpsTime transmission_time; // t_tx
  // Partials of rho (SI): [-], [s], [-] (body), [-].
  Eigen::RowVector3d d_position = Eigen::RowVector3d::Zero();
  Eigen::RowVector3d d_velocity = Eigen::RowVector3d::Zero();
  Eigen::RowVector3d d_pco_error = Eigen::RowVector3d::Zero();
  double d_clock = 0.0;
};

/// The lever from the centre of mass to the antenna phase centre the estimate implies, GCRF:
/// C_body->gcrf (arp + pco + p) [m]. The phase centre at the epoch t itself (the time tag) is
/// r + this; predict_range moves it to the reception instant.
Eigen::Vector3d phase_centre_lever_gcrf_m(const ReceiverEstimate& receiver, const AntennaGeometry& antenna);

/// rho and its partials for the epoch t (time tag) from the receiver estimate, its antenna and
/// the satellite's broadcast ephemeris; `frame` gives ITRF <-> GCRF at t. Allocation-free.
RangePrediction predict_range(core::GpsTime t, const ReceiverEstimate& receiver, const AntennaGeometry& antenna,
                              const gnss::BroadcastEphemeris& ephemeris, core::OnboardEarthFrame& frame);

}  // namespace visors::nav
