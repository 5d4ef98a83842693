#pragma once
// Raw-observable GPS receiver of one spacecraft (ground side of the simulator): single-frequency
// L1 C/A pseudorange, carrier phase, Doppler and C/N0 at each epoch (1 Hz in the simulator), as the
// receiver gives them to the flight computer (gnss::GpsMeasurementEpoch), with the truth behind
// every number for tests and the truth file.
//
// Measurement model (the standard undifferenced observation equations, e.g. Teunissen &
// Montenbruck (eds.), Springer Handbook of Global Navigation Satellite Systems, 2017; RINEX 3 sign
// conventions), at the epoch's time tag t:
//   P   = rho + c (dt_r - dt^j) + I + e_P,                                    e_P ~ N(0, code_sigma_m)
//   Phi = (rho + c (dt_r - dt^j) - I) / lambda + N + phi_r - phi^j + e_Phi / lambda,  e_Phi ~ N(0, phase_sigma_m)
//   D   = -(d/dt)(rho + c dt_r - c dt^j - I) / lambda + e_D,                 e_D ~ N(0, doppler_sigma_hz)
// i.e. -lambda D is the rate, with respect to the time tag, of the noise-free phase range lambda
// Phi (positive D when the satellite approaches): every term of the phase has its rate in the
// Doppler, so -lambda D(t_k) agrees with the phase's central difference over the neighbouring
// epochs to the noise and the difference's truncation (h^2/6 of the third derivative).
// rho: geometric range from the receiver's antenna phase centre at the true reception time
//      t_r = t - dt_r to the satellite at the transmission time t_r - tau, solved by
//      iterating tau = |R3(w_E tau) r^j(t_r - tau) - r_r(t_r)| / c in Earth-fixed axes (the
//      Earth's rotation during the light time; three iterations converge below 1e-12 s);
//      the epoch's time tag is the true time of the pose it is given, the signal is received
//      dt_r earlier (the phase centre is carried back along its Earth-fixed velocity: exact to
//      1e-9 m for dt_r < 1 ms). Its rate is the exact derivative of that light-time solution,
//      d rho / dt_r = e.(v^j - v_r) / (1 + e.v^j_inertial / c) (e the unit line of sight, v^j and
//      v^j_inertial the satellite's Earth-fixed and inertial velocities in the reception-time
//      axes, v_r the phase centre's Earth-fixed velocity: the centre of mass's plus the attitude
//      rotation's, ReceiverPose::angular_velocity_itrf), times dt_r / dt = 1 - d(dt_r)/dt;
// dt_r: receiver clock, c dt_r(t) a continuous function of the time tag, linear between epochs:
//      over [t_k, t_{k+1}) its rate (frequency offset) is f_k ~ N(0, clock_step_sigma_m /
//      epoch_interval_s), drawn at epoch k, so the offset is a random walk of clock_step_sigma_m
//      per epoch at the nominal interval, from N(0, initial_clock_sigma_m) at the first epoch.
//      Its rate AT an epoch, where the slope changes, is the mean of the two adjacent slopes,
//      (f_{k-1} + f_k) / 2 (the symmetric derivative; what a frequency measured over any window
//      centred on the epoch within the neighbouring intervals gives; f_{-1} is drawn in create(),
//      the clock ran before the first epoch). With equal intervals h this is exactly the central
//      difference (c dt_r(t_{k+1}) - c dt_r(t_{k-1})) / 2h, so code, phase and Doppler see the
//      same clock;
// dt^j: the satellite's true L1 clock (GpsSatelliteTruth) at the transmission time, so the
//      broadcast clock error appears in the measurements like the orbit error does; its rate is
//      the true clock drift (a_f1 + 2 a_f2 dt + the relativistic term's rate) times
//      d(t_r - tau)/dt = (1 - d tau/dt_r)(1 - d(dt_r)/dt);
// I:   the topside Klobuchar delay (gnss::klobuchar_topside_delay_m, continuous), on code,
//      advance on phase, for the geometry at reception and the local time of the time tag; its
//      rate is the central difference over +/-0.1 s (receiver and satellite moved along their
//      Earth-fixed velocities, the time tag with them; truncation below 1e-6 m/s, and within
//      0.1 s of a kink of the model's clamps a mean of the two slopes);
// N:   an integer drawn when a satellite is acquired (again at each re-acquisition) and changed by
//      a cycle slip; phi_r, phi^j: constant fractional receiver and satellite phase offsets, so
//      only double differences are integer (as with a real receiver).
// Antenna: the phase centre is phase_center_offset_m along the TRUE boresight from the antenna
// reference point antenna_body_m, plus the drawn calibration error phase_center_error_body_m
// (sim/spacecraft_geometry.hpp); the true boresight is body +Z tilted by two angles drawn
// N(0, mounting_sigma_rad) (about body X, then Y) once per receiver.
// Tracking: a satellite is visible when its elevation above the antenna plane (true boresight)
// is at least the mask and the ray clears the Earth's surface by occultation_altitude_m (grazing
// height of the segment, spherical Earth of WGS-84 equatorial radius). At most `channels`
// satellites are tracked: a tracked satellite keeps its channel while visible; free channels take
// the highest visible ones. Lost and re-acquired means a new ambiguity and the loss-of-lock flag.
// Realism options (off by default; docs/cli/gnss-sim.md): cycle slips without the LLI flag,
// half-cycle ambiguities (LLI bit 1) at acquisition, elevation-dependent noise (sigma / sin(el),
// el floored at 5 deg, C/N0 = 50 + 20 log10 sin(el) then, so sigma ~ 10^(-C/N0 / 20)), first-order
// Gauss-Markov code and phase multipath per channel (scaled by the same elevation factor, restarted
// at each acquisition), and data gaps (records missing, tracking continues unless > 30 s).
// Not modelled: carrier phase wind-up (both spacecraft fly the same attitude profile),
// (options off) C/N0 = 35 + 15 sin(elevation above the antenna plane) dB-Hz is reported,
// relativistic path delay (Shapiro, < 2 cm, common to both spacecraft).
// Defaults and their sources: docs/requirements.md#gps-receiver-and-sensors ("paper" below:
// Guffanti et al., AAS 23-149, 2023; sec. 5 is its navigation test set-up, Table 1(a) its
// geometry uncertainties).

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/gps_measurement.hpp"
#include "visors/gnss/klobuchar.hpp"
#include "visors/sim/gps_satellite_truth.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

struct GpsReceiverSettings {
  double elevation_mask_rad = 5.0 * core::kDegToRad;  // above the antenna plane (paper, sec. 5)
  int channels = 12;                                  // project choice, at most gnss::kMaxGpsChannels
  double code_sigma_m = 0.20;                         // pseudorange thermal noise (paper, sec. 5) [m]
  double phase_sigma_m = 0.002;                       // carrier-phase thermal noise (paper, sec. 5) [m]
  double doppler_sigma_hz = 0.05;                     // [Hz]
  double clock_step_sigma_m = 1.0;                    // receiver clock random walk per epoch (paper, sec. 5) [m]
  double epoch_interval_s = 1.0;                      // nominal epoch interval, for the clock's rate
                                                      // (gnss-sim: time.step_s) [s]
  double initial_clock_sigma_m = 300.0;               // initial receiver clock offset, 1 us [m]
  double phase_center_offset_m = 0.0854;              // along the boresight (paper, Table 1(a)) [m]
  double mounting_sigma_rad = 30.0 * core::kArcsecToRad;  // boresight tilt per axis (paper, Table 1(a))
  Eigen::Vector3d antenna_body_m = Eigen::Vector3d(0.0, 0.0, 0.1);  // antenna reference point [m]
  /// The true phase centre's error against its calibration, body frame [m]: drawn per run with
  /// the spacecraft's geometry (not a scenario key; zero by default).
  Eigen::Vector3d phase_center_error_body_m = Eigen::Vector3d::Zero();
  double occultation_altitude_m = 100e3;              // rays must clear the Earth by this [m]
  double cycle_slip_probability = 0.0;                // per channel and epoch
  int max_slip_cycles = 10;                           // a slip is +/- 1..max cycles
  // Realism options, all off by default (then the output and the random draws are unchanged):
  double unflagged_slip_fraction = 0.0;    // fraction of cycle slips written without LLI bit 0
  double half_cycle_slip_probability = 0.0;  // per acquisition: phase carries an extra half cycle
  double half_cycle_resolve_s = 30.0;      // ... flagged with LLI bit 1 until resolved after this [s]
  bool elevation_dependent_noise = false;  // code/phase sigmas x 1/sin(el), el >= 5 deg; C/N0 with it
  double code_multipath_m = 0.0;           // Gauss-Markov multipath, steady-state sigma at zenith [m]
  double phase_multipath_m = 0.0;          // [m]
  double multipath_tau_s = 60.0;           // its correlation time [s]
  double data_gap_probability = 0.0;       // per receiver and epoch: a gap in the records starts
  double data_gap_s = 10.0;                // its length [s]; > 30 s: all channels re-acquire after it
  bool ionosphere = true;
  gnss::KlobucharCoefficients klobuchar;              // the truth ionosphere's coefficients
  gnss::TopsideIonosphere topside;

  /// Ok, or the offending field by name.
  [[nodiscard]] core::Result<bool> validate() const;
};

/// Where the receiver is at an epoch (true values from the truth world).
struct ReceiverPose {
  core::GpsTime t;                  // true GPS time of the pose = the epoch's time tag
  core::StateVector com_itrf;       // centre of mass, Earth-fixed [m, m/s]
  Eigen::Matrix3d body_to_itrf = Eigen::Matrix3d::Identity();
  Eigen::Vector3d com_body_m = Eigen::Vector3d::Zero();  // true centre of mass in the body frame [m]
  /// The body's angular velocity relative to the Earth-fixed frame, ITRF axes [rad/s]: moves the
  /// phase centre about the centre of mass (~2e-4 m/s at the orbit rate), which the Doppler sees.
  Eigen::Vector3d angular_velocity_itrf = Eigen::Vector3d::Zero();
};

/// The truth behind one channel's measurements (the model in the file comment). Rates are with
/// respect to the time tag, so -lambda D = range_rate + receiver clock rate - satellite_clock_rate
/// - ionosphere_rate + e_D.
struct GpsChannelTruth {
  int prn = 0;
  double range_m = 0.0;              // rho
  double satellite_clock_m = 0.0;    // c dt^j (true L1 clock) at the transmission time
  double ionosphere_m = 0.0;         // I
  std::int64_t ambiguity_cycles = 0;  // N
  double satellite_phase_cycles = 0.0;  // phi^j
  double elevation_antenna_rad = 0.0;
  Eigen::Vector3d line_of_sight_itrf = Eigen::Vector3d::Zero();  // receiver -> satellite (unit)
  double range_rate_mps = 0.0;            // d rho / dt
  double satellite_clock_rate_mps = 0.0;  // d(c dt^j) / dt
  double ionosphere_rate_mps = 0.0;       // dI / dt
  double half_cycle_cycles = 0.0;         // unresolved half cycle in the phase (0 or 0.5)
  bool slipped = false;                   // new ambiguity at this epoch (acquisition, slip, flagged or not)
  double code_multipath_m = 0.0;          // multipath in the pseudorange (elevation-scaled) [m]
  double phase_multipath_m = 0.0;         // multipath in the phase range [m]
};

struct GpsReceiverEpoch {
  gnss::GpsMeasurementEpoch measurement;
  std::array<GpsChannelTruth, gnss::kMaxGpsChannels> truth{};  // same order as the channels
  double receiver_clock_m = 0.0;       // c dt_r at the time tag
  double receiver_clock_rate_mps = 0.0;  // d(c dt_r) / dt at the time tag (mean of the adjacent slopes)
  double receiver_phase_cycles = 0.0;  // phi_r
  Eigen::Vector3d apc_itrf_m = Eigen::Vector3d::Zero();  // phase centre at the reception time [m]
  int visible = 0;                     // satellites passing the visibility test (tracked or not)
  bool recorded = true;                // false in a data gap: no observation record is written
};

class GpsReceiver {
 public:
  /// Validates the settings and draws the mounting tilts, the phase offset and the initial clock.
  static core::Result<GpsReceiver> create(const GpsReceiverSettings& settings, RandomStream rng);

  /// The measurements at pose.t (epochs in increasing time; the clock advances along its current
  /// slope and draws the next slope first). Allocation-free; the returned reference is valid until
  /// the next call.
  const GpsReceiverEpoch& measure(const ReceiverPose& pose, const GpsSatelliteTruth& satellites);

  /// Every channel freed: the next epoch re-acquires what is visible, each with a new ambiguity
  /// and the loss-of-lock flag (after an outage of the receiver).
  void reacquire_all();
  /// The receiver steers its clock: c dt_r jumps by jump_m [m] before the next epoch (code and
  /// phase both move by it; the ambiguities stay).
  void jump_clock(double jump_m) { clock_m_ += jump_m; }

  [[nodiscard]] const GpsReceiverSettings& settings() const { return settings_; }
  /// The true boresight (unit, body frame) and phase centre (body frame) [m].
  [[nodiscard]] const Eigen::Vector3d& boresight_body() const { return boresight_body_; }
  [[nodiscard]] Eigen::Vector3d phase_center_body_m() const {
    return settings_.antenna_body_m + settings_.phase_center_offset_m * boresight_body_ + settings_.phase_center_error_body_m;
  }

 private:
  struct Track {
    int prn = 0;  // 0: free channel
    std::int64_t ambiguity = 0;
    core::GpsTime lock_start;
    core::GpsTime acquired;          // acquisition time (restarts the multipath)
    bool half_cycle = false;         // unresolved half cycle in the phase
    bool pending_lli = false;        // a flag raised in a data gap, written at the next record
    double code_multipath = 0.0;     // Gauss-Markov states (unscaled) [m]
    double phase_multipath = 0.0;
    core::GpsTime multipath_time;
  };
  struct Candidate {
    std::size_t index = 0;  // into the satellites
    double elevation = 0.0;
    bool visible = false;
  };

  struct LocalAxes;  // geodetic position and local axes (gps_receiver.cpp)
  struct Reception;  // the antenna at the true reception time (gps_receiver.cpp)

  GpsReceiver(const GpsReceiverSettings& settings, RandomStream rng) : settings_(settings), rng_(std::move(rng)) {}
  RandomStream& prn_rng(int prn) { return prn_rng_[static_cast<std::size_t>(prn)]; }
  std::int64_t draw_ambiguity(int prn);  // from that PRN's stream

  // The steps of measure(), in order.
  void step_clock(core::GpsTime t);
  [[nodiscard]] Reception reception(const ReceiverPose& pose) const;
  std::size_t screen_visibility(const Reception& rx, const GpsSatelliteTruth& satellites);
  [[nodiscard]] const Candidate* candidate_of(int prn, std::size_t count, const GpsSatelliteTruth& satellites) const;
  void assign_channels(core::GpsTime t, std::size_t count, const GpsSatelliteTruth& satellites);
  bool lost_lock(Track& track, core::GpsTime t, bool& flagged);
  void step_multipath(Track& track, core::GpsTime t);
  void step_gap(core::GpsTime t);
  [[nodiscard]] double ionosphere_m(const LocalAxes& at, const Eigen::Vector3d& e, core::GpsTime t) const;
  [[nodiscard]] double ionosphere_rate_mps(const Reception& rx, const Eigen::Vector3d& r_satellite,
                                           const Eigen::Vector3d& v_satellite, core::GpsTime t) const;
  void measure_channel(Track& track, const Candidate& c, const Reception& rx, core::GpsTime t,
                       const GpsSatelliteTruth& satellites);

  GpsReceiverSettings settings_;
  RandomStream rng_;  // the receiver's own draws: mounting, phase offset, clock, data gaps
  /// One stream per PRN (index: the PRN), seeded from rng_ at creation, for each channel's draws
  /// (ambiguity, slips, half cycles, multipath, noise): a satellite acquired a step earlier or
  /// later, or not at all, leaves every other satellite's draws as they were, so that two runs
  /// that differ in one setting differ only where that setting acts (paired comparisons).
  std::vector<RandomStream> prn_rng_;
  Eigen::Vector3d boresight_body_ = Eigen::Vector3d::UnitZ();
  double clock_m_ = 0.0;       // c dt_r at the last epoch [m]
  double clock_rate_mps_ = 0.0;  // its slope from the last epoch on (before the first: f_-1) [m/s]
  core::GpsTime last_epoch_;
  bool first_epoch_ = true;
  bool gap_active_ = false;       // data gap (settings.data_gap_*)
  bool reacquire_after_gap_ = false;
  core::GpsTime gap_until_;
  std::array<Track, gnss::kMaxGpsChannels> tracks_{};
  std::array<Candidate, 64> candidates_{};
  GpsReceiverEpoch epoch_;
};

}  // namespace visors::sim
