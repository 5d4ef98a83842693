#include "visors/sim/gnss_simulation.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "visors/core/files/output_file.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/gnss/constellation.hpp"
#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "visors/gnss/files/rinex_obs_file.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "visors/sim/adcs_model.hpp"
#include "visors/sim/attitude_profile.hpp"
#include "visors/sim/drag_area.hpp"
#include "visors/sim/formation_initial_state.hpp"
#include "visors/sim/formation_keeping.hpp"
#include "visors/sim/gnss_operations.hpp"
#include "visors/sim/gps_receiver.hpp"
#include "visors/sim/gps_satellite_truth.hpp"
#include "visors/sim/gps_world.hpp"
#include "visors/sim/navigation_message.hpp"
#include "visors/sim/propulsion.hpp"
#include "visors/sim/sky_truth.hpp"
#include "visors/sim/spacecraft_geometry.hpp"
#include "visors/sim/truth_dynamics.hpp"

namespace visors::sim {

namespace {

core::Result<core::files::OutputFile> open_output(const std::filesystem::path& path) {
  core::files::OutputFile f = core::files::open_output_file(path);
  if (!f) return core::Error{path.string(), "cannot open for writing"};
  return f;
}

struct Craft {
  std::string name;
  TruthDynamics truth;
  core::StateVector x_gcrf;
  DragArea drag = DragArea::visors_6u();
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // true, body to GCRF at the epoch
  Eigen::Quaterniond reported_attitude = Eigen::Quaterniond::Identity();  // the ADCS's report at the epoch
  std::optional<AdcsModel> adcs;  // its control error and the error of what it reports
  std::optional<SpacecraftGeometry> geometry;
  std::optional<GpsReceiver> receiver;
  std::optional<gnss::files::Rinex3ObservationWriter> rinex;
  std::optional<Propulsion> propulsion;  // only when the craft maneuvers ([gnss.maneuvers])
  double visible_sum = 0.0, tracked_sum = 0.0;
  std::int64_t acquisitions = 0;
  std::int64_t maneuvers = 0;  // executed pieces
  std::array<std::size_t, gnss::kMaxGpsPrn + 1> next_data_set{};  // per PRN: after the last set decoded
  std::int64_t data_sets_decoded = 0;
};

core::Result<bool> set_up(Craft& c, const CampaignScenario& s, const SpacecraftSettings& nominal, const core::StateVector& x0,
                          const gnss::KlobucharCoefficients& ionosphere) {
  RandomStream ballistics(s.seed, c.name + ".ballistics");  // the same draw as `visors run`
  const SpacecraftSettings sc = draw_true_spacecraft(nominal, ballistics);
  auto truth = make_truth_dynamics(s, sc, c.name);
  if (!truth.ok()) return truth.error();
  c.truth = std::move(truth).value();
  c.x_gcrf = x0;
  RandomStream geometry_rng(s.seed, c.name + ".geometry");  // the same draw as `visors run`
  c.geometry.emplace(SpacecraftGeometry::draw(s.geometry, geometry_rng));
  auto adcs = AdcsModel::create(s.adcs, RandomStream(s.seed, c.name + ".adcs"));  // the same stream as `visors run`
  if (!adcs.ok()) return core::Error{"attitude." + adcs.error().field, adcs.error().message};
  c.adcs.emplace(std::move(adcs).value());
  GpsReceiverSettings settings = s.gnss.receiver;
  settings.klobuchar = ionosphere;
  settings.epoch_interval_s = s.step_s;  // clock_step_sigma_m is per epoch
  settings.phase_center_error_body_m = c.geometry->phase_center_error_body_m();
  auto receiver = GpsReceiver::create(settings, RandomStream(s.seed, c.name + ".gps"));
  if (!receiver.ok()) return core::Error{"gnss.receiver." + receiver.error().field, receiver.error().message};
  c.receiver.emplace(std::move(receiver).value());
  const std::string& flown = s.gnss.maneuvers.spacecraft;
  if (flown == "both" || flown == c.name) {  // the same model and stream as `visors run`
    auto propulsion = Propulsion::create(s.propulsion, sc.mass_kg, sc.propellant_kg, RandomStream(s.seed, c.name + ".propulsion"));
    if (!propulsion.ok()) return core::Error{c.name + "." + propulsion.error().field, propulsion.error().message};
    // Checked here rather than at the first piece (the propulsion would refuse every piece).
    const double impulse_ns = sc.mass_kg * s.gnss.maneuvers.dv_mps;
    if (impulse_ns > s.propulsion.max_impulse_ns || impulse_ns < s.propulsion.min_impulse_ns) {
      return core::Error{"gnss.maneuvers.dv_mps", c.name + ": the impulse mass_kg x dv_mps = " + std::to_string(impulse_ns) +
                                                      " N s is outside the propulsion's range [" +
                                                      std::to_string(s.propulsion.min_impulse_ns) + ", " +
                                                      std::to_string(s.propulsion.max_impulse_ns) + "] N s"};
    }
    c.propulsion.emplace(std::move(propulsion).value());
  }
  return true;
}

// One truth.csv row (columns: gnss_simulation.hpp).
void write_truth_row(std::FILE* f, double t_s, const Craft& c, const GpsReceiverEpoch& e) {
  const auto& r = c.x_gcrf.r;
  const auto& v = c.x_gcrf.v;
  const auto& q = c.attitude;
  std::fprintf(f, "%.3f,%s,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.4f,%.4f,%.4f,%.4f,%d,%d,%.6f,%.10f,%.10f,%.10f,%.10f\n", t_s,
               c.name.c_str(), r.x(), r.y(), r.z(), v.x(), v.y(), v.z(), e.apc_itrf_m.x(), e.apc_itrf_m.y(), e.apc_itrf_m.z(),
               e.receiver_clock_m, e.visible, e.measurement.channel_count, e.receiver_clock_rate_mps, q.w(), q.x(), q.y(),
               q.z());
}

// The channels_truth.csv rows of one epoch (columns: gnss_simulation.hpp).
void write_channel_rows(std::FILE* f, double t_s, const Craft& c, const GpsReceiverEpoch& e) {
  for (int k = 0; k < e.measurement.channel_count; ++k) {
    const GpsChannelTruth& t = e.truth[static_cast<std::size_t>(k)];
    std::fprintf(f, "%.3f,%s,%d,%.4f,%.4f,%.4f,%lld,%.6f,%.6f,%.4f,%.6f,%.6f,%.6f,%.1f,%d,%.4f,%.4f,%d\n", t_s,
                 c.name.c_str(), t.prn, t.range_m, t.satellite_clock_m, t.ionosphere_m,
                 static_cast<long long>(t.ambiguity_cycles), t.satellite_phase_cycles, e.receiver_phase_cycles,
                 t.elevation_antenna_rad / core::kDegToRad, t.range_rate_mps, t.satellite_clock_rate_mps,
                 t.ionosphere_rate_mps, t.half_cycle_cycles, t.slipped ? 1 : 0, t.code_multipath_m, t.phase_multipath_m,
                 e.recorded ? 1 : 0);
  }
}

core::Result<bool> write_resolved_scenario(const CampaignScenario& s, const std::filesystem::path& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) return core::Error{out_dir.string(), "cannot create the output directory: " + ec.message()};
  std::ofstream scenario_file(out_dir / "scenario.toml");
  scenario_file << campaign_to_toml(s);
  if (!scenario_file) return core::Error{(out_dir / "scenario.toml").string(), "cannot write"};
  return true;
}

// brdc.rnx: the broadcast ephemerides the receivers decode (with the broadcast errors).
core::Result<bool> write_broadcast_navigation(const CampaignScenario& s, const GpsWorld& world,
                                              const std::filesystem::path& out_dir) {
  gnss::files::NavigationFile broadcast;
  broadcast.version = 3.05;
  broadcast.ionosphere = world.nav.ionosphere;
  broadcast.leap_seconds = s.t0.gps_minus_utc();
  broadcast.records.assign(world.satellites->broadcast_records().begin(), world.satellites->broadcast_records().end());
  return gnss::files::write_rinex3_navigation(out_dir / "brdc.rnx", broadcast, "visors gnss-sim");
}

// <name>.rnx: the craft's RINEX 3 observation file, its header from the nominal antenna.
core::Result<bool> open_rinex_observations(Craft& c, const CampaignScenario& s, const std::filesystem::path& out_dir) {
  gnss::files::ObservationHeader header;
  header.program = "visors gnss-sim";
  header.marker_name = c.name == "dsc" ? "DSC" : "OSC";
  header.comments = {"VISORS " + header.marker_name + " simulated L1 C/A receiver",
                     "truth: channels_truth.csv, truth.csv; orbits: brdc.rnx"};
  header.approx_position_m = core::gcrf_to_itrf_matrix(s.t0, core::EarthOrientation{}) * c.x_gcrf.r;
  header.antenna_delta_xyz_m = s.gnss.receiver.antenna_body_m;  // nominal reference point, body frame
  header.antenna_boresight_xyz = Eigen::Vector3d::UnitZ();       // nominal boresight
  header.interval_s = s.step_s;
  header.first_observation = s.t0;
  auto writer = gnss::files::Rinex3ObservationWriter::open(out_dir / (c.name + ".rnx"), header);
  if (!writer.ok()) return writer.error();
  c.rinex.emplace(std::move(writer).value());
  return true;
}

// truth.csv and channels_truth.csv, with their header lines; what the flight software would have
// been given besides the RINEX files (attitude_reported.csv, ephemeris_decoded.csv).
struct TruthFiles {
  core::files::OutputFile truth;
  core::files::OutputFile channels;
  core::files::OutputFile maneuvers;
  core::files::OutputFile lrf;
  core::files::OutputFile attitude_reported;
  core::files::OutputFile ephemeris_decoded;
};

core::Result<TruthFiles> open_truth_files(const std::filesystem::path& out_dir) {
  auto truth_csv = open_output(out_dir / "truth.csv");
  if (!truth_csv.ok()) return truth_csv.error();
  auto channels_csv = open_output(out_dir / "channels_truth.csv");
  if (!channels_csv.ok()) return channels_csv.error();
  std::fprintf(truth_csv->get(),
               "t_s,spacecraft,x_gcrf_m,y_gcrf_m,z_gcrf_m,vx_gcrf_mps,vy_gcrf_mps,vz_gcrf_mps,x_apc_itrf_m,y_apc_itrf_m,"
               "z_apc_itrf_m,receiver_clock_m,visible,tracked,receiver_clock_rate_mps,qw_body_to_gcrf,qx_body_to_gcrf,"
               "qy_body_to_gcrf,qz_body_to_gcrf\n");
  std::fprintf(channels_csv->get(),
               "t_s,spacecraft,prn,range_m,satellite_clock_m,ionosphere_m,ambiguity_cycles,satellite_phase_cycles,"
               "receiver_phase_cycles,elevation_antenna_deg,range_rate_mps,satellite_clock_rate_mps,ionosphere_rate_mps,"
               "half_cycle_cycles,new_ambiguity,code_multipath_m,phase_multipath_m,recorded\n");
  auto maneuvers_csv = open_output(out_dir / "maneuvers.csv");
  if (!maneuvers_csv.ok()) return maneuvers_csv.error();
  auto lrf_csv = open_output(out_dir / "lrf.csv");
  if (!lrf_csv.ok()) return lrf_csv.error();
  std::fprintf(maneuvers_csv->get(),
               "t_s,spacecraft,dv_cmd_x_gcrf_mps,dv_cmd_y_gcrf_mps,dv_cmd_z_gcrf_mps,dv_x_gcrf_mps,dv_y_gcrf_mps,"
               "dv_z_gcrf_mps\n");
  std::fprintf(lrf_csv->get(), "t_s,range_m,true_range_m\n");
  auto attitude_csv = open_output(out_dir / "attitude_reported.csv");
  if (!attitude_csv.ok()) return attitude_csv.error();
  std::fprintf(attitude_csv->get(), "t_s,spacecraft,qw_body_to_gcrf,qx_body_to_gcrf,qy_body_to_gcrf,qz_body_to_gcrf\n");
  auto decoded_csv = open_output(out_dir / "ephemeris_decoded.csv");
  if (!decoded_csv.ok()) return decoded_csv.error();
  std::fprintf(decoded_csv->get(), "t_s,spacecraft,prn,toe_week,toe_sow,iode\n");
  return TruthFiles{std::move(truth_csv).value(),    std::move(channels_csv).value(), std::move(maneuvers_csv).value(),
                    std::move(lrf_csv).value(),      std::move(attitude_csv).value(), std::move(decoded_csv).value()};
}

// Formation keeping ([gnss.maneuvers] keeping = true): the tangential correction of each piece of
// the current burst, per craft (0 = DSC, 1 = OSC), from sim::along_track_correction at the burst's
// first commanded piece.
struct KeepingBurst {
  int burst = -1;                                 // the burst these are for; -1: none yet
  std::array<double, 2> dv_t_per_piece_mps{0.0, 0.0};  // wanted, the craft's T axis [m/s]
  std::int64_t clamped_pieces = 0;                // pieces whose correction was cut to fit
};

// The two spacecraft set up with their receivers, and the output files opened: the set-up of the
// run, in the order its errors are reported.
struct GnssRun {
  GpsWorld world;
  DataSetsByPrn data_sets;  // the broadcast records of each PRN (sim/navigation_message.hpp)
  std::array<Craft, 2> crafts;
  std::optional<TruthFiles> files;
  std::optional<AttitudeProfile> profile;  // the commanded attitude, with the observation windows (attitude = "campaign")
  GnssOperations operations;
  KeepingBurst keeping;                    // the current burst's corrections (keeping = true)
};

// The operations planned as the flight software plans them (the slew lead from its own rate and
// settling, gnc.science), and the commanded attitude flying their windows at the ADCS's own slew
// rate ([attitude] slew_rate_deg_s), as `visors run`'s truth.
core::Result<bool> plan_attitude(GnssRun& run, const CampaignScenario& s, double last_epoch_s) {
  AttitudeSettings planned;
  planned.slew_rate_radps = s.gnc.science.slew_rate_radps;
  planned.settling_s = s.gnc.science.slew_settle_s;
  auto planning = AttitudeProfile::create(planned);
  if (!planning.ok()) return core::Error{"gnc.science." + planning.error().field, planning.error().message};
  auto operations = plan_gnss_operations(s, *planning, last_epoch_s);
  if (!operations.ok()) return operations.error();
  run.operations = std::move(operations).value();
  AttitudeSettings flown;
  flown.slew_rate_radps = s.adcs.slew_rate_radps;
  flown.calibration = s.calibration_yaw;
  auto profile = AttitudeProfile::create(flown);
  if (!profile.ok()) return core::Error{"attitude.slew_rate_deg_s", profile.error().message};
  run.profile.emplace(std::move(profile).value());
  for (const ObservationWindow& w : run.operations.windows) {
    if (auto ok = run.profile->schedule(w); !ok) return core::Error{"gnss.observations." + ok.error().field, ok.error().message};
  }
  return true;
}

core::Result<bool> set_up_run(GnssRun& run, const CampaignScenario& s, const std::filesystem::path& out_dir,
                              double last_epoch_s) {
  auto world = load_gps_world(s, s.gnss.duration_s);
  if (!world.ok()) return world.error();
  run.world = std::move(world).value();
  run.data_sets = data_sets_by_prn(run.world.satellites->broadcast_records());
  const auto initial = initial_formation_state(s);
  if (!initial.ok()) return initial.error();
  const gnss::KlobucharCoefficients ionosphere = run.world.nav.ionosphere.value_or(gnss::KlobucharCoefficients{});
  if (auto ok = plan_attitude(run, s, last_epoch_s); !ok) return ok.error();
  std::array<Craft, 2>& crafts = run.crafts;
  crafts[0].name = "dsc";
  crafts[1].name = "osc";
  if (auto ok = set_up(crafts[0], s, s.dsc, initial->dsc_gcrf, ionosphere); !ok) return ok.error();
  if (auto ok = set_up(crafts[1], s, s.osc, initial->osc_gcrf, ionosphere); !ok) return ok.error();
  if (s.gnss.rinex) {
    if (auto ok = write_broadcast_navigation(s, run.world, out_dir); !ok) return ok.error();
    for (Craft& c : crafts) {
      if (auto ok = open_rinex_observations(c, s, out_dir); !ok) return ok.error();
    }
  }
  auto files = open_truth_files(out_dir);
  if (!files.ok()) return files.error();
  run.files.emplace(std::move(files).value());
  return true;
}

// The commanded attitude of [gnss] attitude: a fixed target ("nominal", "observation") or the
// attitude profile with the observation windows ("campaign"); the Sun line is the commanded
// target's apparent direction (sim/sky_truth.hpp). The bus holds it turned by its ADCS's control
// error (Craft::adcs).
struct AttitudeModel {
  enum class Kind { kNominal, kObservation, kCampaign } kind = Kind::kNominal;
  const AttitudeProfile* profile = nullptr;  // kCampaign only
  SkyTruth* sky = nullptr;                   // the truth's sky (a cache: not const)
  core::GpsTime t0;                          // t_s = 0

  // Body to GCRF at t_s [s] for the state (r, v) at t_s.
  [[nodiscard]] Eigen::Quaterniond at(double t_s, const Eigen::Vector3d& r, const Eigen::Vector3d& v) const {
    const Eigen::Vector3d sun_unit = sky->target_unit_gcrf(t0 + t_s, {r, v});
    switch (kind) {
      case Kind::kObservation:
        return AttitudeProfile::observation_body_to_gcrf(r, v, sun_unit);
      case Kind::kCampaign:
        return profile->body_to_gcrf(t_s, r, v, sun_unit);
      case Kind::kNominal:
        break;
    }
    return AttitudeProfile::nominal_body_to_gcrf(r, v, sun_unit);
  }

  // The body's angular velocity (GCRF axes) [rad/s] (sim/gps_world.hpp attitude_rate_gcrf).
  [[nodiscard]] Eigen::Vector3d angular_velocity_gcrf(double t_s, const core::StateVector& x) const {
    return attitude_rate_gcrf([&](double t, const Eigen::Vector3d& r, const Eigen::Vector3d& v) { return at(t, r, v); },
                              t_s, x);
  }
};

// The epoch's attitudes, as `visors run` steps them: the ADCS's errors advanced to t_s (one step
// an epoch, from the same stream "<craft>.adcs": the run's draws), the true attitude (the
// commanded one turned by the control error; it also sets the drag area of the truth forces) and
// the ADCS's report of it (turned by the determination error).
void update_attitude(Craft& c, double t_s, const AttitudeModel& attitude) {
  c.adcs->step(t_s);
  c.attitude = c.adcs->true_attitude(attitude.at(t_s, c.x_gcrf.r, c.x_gcrf.v));
  c.reported_attitude = c.adcs->reported_attitude(c.attitude);
  c.truth.forces->set_drag_area(c.drag.projected_area_m2(air_velocity_body_unit(c.x_gcrf, c.attitude)));
}

// The receiver's pose at t: the true attitude of the epoch, the commanded attitude's angular
// velocity (as `visors run`: the control error's own motion is not in the antenna's velocity), and
// the centre of mass in ITRF.
ReceiverPose receiver_pose(const Craft& c, const EpochFrame& frame, core::GpsTime t, double t_s, const AttitudeModel& attitude) {
  return sim::receiver_pose(frame, t, c.x_gcrf, c.attitude, attitude.angular_velocity_gcrf(t_s, c.x_gcrf),
                            c.geometry->com_body_m());
}

// The craft's epoch counted into its statistics and written to the RINEX and truth files.
core::Result<bool> record_epoch(Craft& c, const GpsReceiverEpoch& epoch, double t_s, const TruthFiles& files) {
  c.visible_sum += epoch.visible;
  c.tracked_sum += epoch.measurement.channel_count;
  for (int j = 0; j < epoch.measurement.channel_count && epoch.recorded; ++j) {
    if (epoch.measurement.channels[static_cast<std::size_t>(j)].loss_of_lock) ++c.acquisitions;
  }
  if (c.rinex && epoch.recorded) {  // nothing written in a data gap
    // No receiver clock offset in the epoch records: a real receiver does not know its own
    // (it is in truth.csv).
    const auto written = c.rinex->write(gnss::files::to_observation_epoch(epoch.measurement));
    if (!written.ok()) return written.error();
  }
  write_truth_row(files.truth.get(), t_s, c, epoch);
  write_channel_rows(files.channels.get(), t_s, c, epoch);
  const Eigen::Quaterniond& q = c.reported_attitude;
  std::fprintf(files.attitude_reported.get(), "%.3f,%s,%.10f,%.10f,%.10f,%.10f\n", t_s, c.name.c_str(), q.w(), q.x(), q.y(),
               q.z());
  return true;
}

// The broadcast data sets the craft's receiver passes on at this epoch (sim/navigation_message.hpp:
// the set in force, decoded since the lock, each once; as `visors run` decodes them, except that
// its one-record GPS message passes one a step): ephemeris_decoded.csv rows. Only at a recorded
// epoch: in a data gap nothing reaches the flight software.
void record_decoded_data_sets(Craft& c, const GpsReceiverEpoch& epoch, core::GpsTime t, double t_s, const GnssRun& run,
                              double half_refresh_s) {
  if (!epoch.recorded) return;
  const auto records = run.world.satellites->broadcast_records();
  for (int k = 0; k < epoch.measurement.channel_count; ++k) {
    const gnss::GpsChannelMeasurement& channel = epoch.measurement.channels[static_cast<std::size_t>(k)];
    const auto prn = static_cast<std::size_t>(channel.prn);
    const auto set = newly_decoded_data_set(records, run.data_sets[prn], t, half_refresh_s, channel.lock_time_s,
                                            c.next_data_set[prn]);
    if (!set) continue;
    c.next_data_set[prn] = *set + 1;
    ++c.data_sets_decoded;
    const gnss::BroadcastEphemeris& e = records[run.data_sets[prn][*set]];
    std::fprintf(run.files->ephemeris_decoded.get(), "%.3f,%s,%d,%d,%.6f,%d\n", t_s, c.name.c_str(), e.prn, e.toe.week(),
                 e.toe.seconds_of_week(), e.iode);
  }
}

// One maneuver piece executed on the craft's truth at the piece's time (the craft's state is
// there): the commanded RTN dv in GCRF (the true RTN frame), in the body frame of the true
// attitude (the commanded one at the piece's time turned by the ADCS's control error of the last
// epoch: the error is drawn once a step), executed by the propulsion model with its errors, back
// to GCRF with the same attitude, added to the velocity; a maneuvers.csv row (columns:
// gnss_simulation.hpp).
core::Result<bool> execute_piece(Craft& c, const GnssManeuverPiece& piece,
                                 const AttitudeModel& attitude, std::FILE* f) {
  const Eigen::Quaterniond q = c.adcs->true_attitude(attitude.at(piece.t_s, c.x_gcrf.r, c.x_gcrf.v));
  const Eigen::Vector3d dv_cmd_gcrf = core::gcrf_to_rtn_matrix(c.x_gcrf).transpose() * piece.dv_rtn_mps;
  auto executed = c.propulsion->execute(piece.t_s, q.conjugate() * dv_cmd_gcrf);
  if (!executed.ok()) {
    // The schedule is checked before the run (spacing, burst length), so what is left is the
    // size of the command (impulse range, propellant).
    const std::string field = executed.error().field == "t_s" ? "gnss.maneuvers.pieces_per_burst" : "gnss.maneuvers.dv_mps";
    return core::Error{field, c.name + " propulsion refused the piece at t = " + std::to_string(piece.t_s) +
                                  " s: " + executed.error().describe()};
  }
  const Eigen::Vector3d dv_gcrf = q * executed->dv_executed_body_mps;
  c.x_gcrf.v += dv_gcrf;
  ++c.maneuvers;
  std::fprintf(f, "%.3f,%s,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f\n", piece.t_s, c.name.c_str(), dv_cmd_gcrf.x(), dv_cmd_gcrf.y(),
               dv_cmd_gcrf.z(), dv_gcrf.x(), dv_gcrf.y(), dv_gcrf.z());
  return true;
}

// Formation keeping: the per-piece tangential corrections of the burst whose first commanded
// piece is pieces[first] (the crafts' states are at at_s[k] <= its time). The law reads the TRUE
// states of both spacecraft at that instant (a copy of the other craft's truth is propagated
// there, so that the truth's own steps are those of a run without keeping) and the tangential
// part of the random pieces still to fly in the burst's pair; the deputy-equivalent dv_T (da and
// dlambda, plus the relative eccentricity's share: sim/formation_keeping.hpp) is flown by the
// OSC (+), the DSC (-: a chief impulse changes da with the opposite sign) or half by each ("both").
core::Result<std::array<double, 2>> plan_keeping_burst(GnssRun& run, const CampaignScenario& s, std::size_t first,
                                                       const std::array<double, 2>& at_s) {
  const std::vector<GnssManeuverPiece>& pieces = run.operations.pieces;
  const GnssManeuverPiece& head = pieces[first];
  // The random pieces still to fly in the burst's pair (this burst, and the second of the pair
  // when this is the first): the law targets the da after the pair, so the random pair flies as
  // without keeping and the correction is the keeping alone. The correction goes on this burst's.
  const int pair_last = head.burst % 2 == 0 ? head.burst + 1 : head.burst;
  std::array<int, 2> count{0, 0};
  std::array<double, 2> random_t_mps{0.0, 0.0};
  for (std::size_t i = first; i < pieces.size() && pieces[i].burst <= pair_last; ++i) {
    const auto k = static_cast<std::size_t>(pieces[i].craft);
    if (pieces[i].burst == head.burst) ++count[k];
    random_t_mps[k] += pieces[i].dv_rtn_mps(1);
  }
  std::array<core::StateVector, 2> x_gcrf;
  for (std::size_t k = 0; k < 2; ++k) {
    Craft& c = run.crafts[k];
    x_gcrf[k] = c.x_gcrf;
    if (at_s[k] < head.t_s) {
      auto there = c.truth.propagator->propagate_to(s.t0 + at_s[k], c.x_gcrf, s.t0 + head.t_s);
      if (!there.ok()) return core::Error{c.name + " truth", there.error().describe()};
      x_gcrf[k] = *there;
    }
  }
  const double planned_mps = random_t_mps[1] - random_t_mps[0];  // deputy-equivalent
  const astro::RelativeOrbitalElements target = s.initial_roe_m / s.chief_mean.a;
  const auto law = along_track_correction(x_gcrf[0], x_gcrf[1], target, planned_mps, s.gnc.gravity);
  if (!law.ok()) return core::Error{"gnss.maneuvers.keeping", law.error().describe()};
  const double dv_t_mps = law->dv_t_deputy_mps + eccentricity_tangential_dv_mps(*law, target, s.gnss.maneuvers.bursts_per_orbit);
  const double share = count[0] > 0 && count[1] > 0 ? 0.5 : 1.0;
  std::array<double, 2> per_piece{0.0, 0.0};
  if (count[0] > 0) per_piece[0] = -share * dv_t_mps / count[0];
  if (count[1] > 0) per_piece[1] = share * dv_t_mps / count[1];
  return per_piece;
}

// The burst's tangential correction added to a piece's random command (its T axis), fitted into
// the propulsion's impulse range at the craft's current mass: clamped so that |piece| stays under
// the maximum impulse (the random part is kept whole; the remainder is not carried over, the next
// burst's law sees what is left), and kept out of the band where the total would round below the
// minimum impulse (a correction smaller than the minimum is fine: the total is what is executed).
void add_keeping_correction(KeepingBurst& keeping, const Craft& c, const PropulsionSettings& propulsion,
                            GnssManeuverPiece& piece) {
  const double mass_kg = c.propulsion->mass_kg();
  const double max_dv_mps = propulsion.max_impulse_ns / mass_kg * (1.0 - 1e-9);  // round-off on the boundary
  const double min_dv_mps = (propulsion.min_impulse_ns + propulsion.quantum_ns) / mass_kg;
  const double wanted_mps = keeping.dv_t_per_piece_mps[static_cast<std::size_t>(piece.craft)];
  const double fitted_mps = fit_tangential_correction(piece.dv_rtn_mps, wanted_mps, min_dv_mps, max_dv_mps);
  if (std::abs(fitted_mps - wanted_mps) > 1e-12) ++keeping.clamped_pieces;
  piece.dv_rtn_mps(1) += fitted_mps;
}

// Both spacecraft one step ahead along their truth dynamics, from the epoch t_s to t_s + step_s,
// with the maneuver pieces of [t_s, t_s + step_s) executed at their times (so an epoch's truth
// row is the state before a piece fired at that very epoch). `next_piece` walks the plan.
core::Result<bool> propagate_crafts(GnssRun& run, const CampaignScenario& s, double t_s, const AttitudeModel& attitude,
                                    std::size_t& next_piece) {
  const double end_s = t_s + s.step_s;
  std::array<double, 2> at_s{t_s, t_s};  // where each craft's state is
  const auto advance = [&](int k, double to_s) -> core::Result<bool> {
    Craft& c = run.crafts[static_cast<std::size_t>(k)];
    auto next = c.truth.propagator->propagate_to(s.t0 + at_s[static_cast<std::size_t>(k)], c.x_gcrf, s.t0 + to_s);
    if (!next.ok()) return core::Error{c.name + " truth", next.error().describe()};
    c.x_gcrf = *next;
    at_s[static_cast<std::size_t>(k)] = to_s;
    return true;
  };
  const std::vector<GnssManeuverPiece>& pieces = run.operations.pieces;
  for (; next_piece < pieces.size() && pieces[next_piece].t_s < end_s; ++next_piece) {
    const GnssManeuverPiece& piece = pieces[next_piece];
    if (piece.t_s > at_s[static_cast<std::size_t>(piece.craft)]) {
      if (auto ok = advance(piece.craft, piece.t_s); !ok) return ok.error();
    }
    Craft& c = run.crafts[static_cast<std::size_t>(piece.craft)];
    GnssManeuverPiece commanded = piece;
    if (s.gnss.maneuvers.keeping) {
      if (run.keeping.burst != piece.burst) {
        auto burst = plan_keeping_burst(run, s, next_piece, at_s);
        if (!burst.ok()) return burst.error();
        run.keeping = KeepingBurst{piece.burst, *burst, run.keeping.clamped_pieces};
      }
      add_keeping_correction(run.keeping, c, s.propulsion, commanded);
    }
    if (auto ok = execute_piece(c, commanded, attitude, run.files->maneuvers.get()); !ok) return ok.error();
  }
  for (int k = 0; k < 2; ++k) {
    if (auto ok = advance(k, end_s); !ok) return ok.error();
  }
  return true;
}

// A lrf.csv row at the epoch t_s (the crafts' states and attitudes are at t_s): the range between
// the true payload points r + C (payload - centre of mass), OSC to DSC, with the bias and the noise.
void write_lrf_row(std::FILE* f, double t_s, const std::array<Craft, 2>& crafts, const GnssLrfSettings& lrf,
                   RandomStream& rng) {
  const auto payload = [](const Craft& c) {
    return Eigen::Vector3d(c.x_gcrf.r + c.attitude * c.geometry->payload_from_com_body_m());
  };
  const double truth = (payload(crafts[1]) - payload(crafts[0])).norm();
  const double measured = truth + lrf.bias_m + rng.normal(lrf.sigma_m);
  std::fprintf(f, "%.3f,%.6f,%.6f\n", t_s, measured, truth);
}

core::Result<bool> close_rinex(std::array<Craft, 2>& crafts) {
  for (Craft& c : crafts) {
    if (c.rinex) {
      if (auto closed = c.rinex->close(); !closed.ok()) return closed.error();
    }
  }
  return true;
}

nlohmann::json run_summary(const CampaignScenario& s, const GnssRun& run, std::int64_t steps, double wall,
                           double measure_wall_s) {
  const double epochs = static_cast<double>(steps + 1);
  nlohmann::json summary;
  summary["epochs"] = steps + 1;
  summary["duration_s"] = s.gnss.duration_s;
  summary["satellites"] = run.world.satellites->truth().size();
  summary["wall_s"] = wall;
  summary["receiver_us_per_epoch_two_spacecraft"] = 1e6 * measure_wall_s / epochs;
  summary["observations"] = nlohmann::json::array();
  for (const ObservationWindow& w : run.operations.windows) {
    summary["observations"].push_back({{"slew_start_s", w.slew_start_s}, {"start_s", w.start_s}, {"end_s", w.end_s}});
  }
  summary["observation_period_s"] = run.operations.period_s;
  summary["maneuvers"] = {{"dsc", run.crafts[0].maneuvers}, {"osc", run.crafts[1].maneuvers}};
  summary["maneuver_pieces_skipped"] = run.operations.skipped_pieces;
  if (s.gnss.maneuvers.keeping) summary["keeping_clamped_pieces"] = run.keeping.clamped_pieces;
  summary["lrf_measurements"] = run.operations.lrf_epochs.size();
  summary["t0"] = {{"iso", s.t0.format(core::TimeScale::kGps, 3)}, {"week", s.t0.week()}, {"seconds_of_week", s.t0.seconds_of_week()}};
  const auto vector = [](const Eigen::Vector3d& x) { return nlohmann::json::array({x.x(), x.y(), x.z()}); };
  for (const Craft& c : run.crafts) {
    summary["receivers"][c.name] = {{"mean_visible", c.visible_sum / epochs},
                                    {"mean_tracked", c.tracked_sum / epochs},
                                    {"acquisitions_and_slips", c.acquisitions},
                                    {"data_sets_decoded", c.data_sets_decoded},
                                    {"phase_center_body_m", vector(c.receiver->phase_center_body_m())},
                                    {"center_of_mass_body_m", vector(c.geometry->com_body_m())},
                                    {"boresight_body", vector(c.receiver->boresight_body())}};
  }
  return summary;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

core::Result<GnssRunResult> run_gnss_simulation(const CampaignScenario& s, const std::filesystem::path& out_dir,
                                                const std::function<void(const RunProgress&)>& progress) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (auto ok = write_resolved_scenario(s, out_dir); !ok) return ok.error();
  const auto steps = static_cast<std::int64_t>(std::floor(s.gnss.duration_s / s.step_s + 1e-9));
  GnssRun run;
  if (auto ok = set_up_run(run, s, out_dir, static_cast<double>(steps) * s.step_s); !ok) return ok.error();
  const GpsSatelliteTruth& satellites = *run.world.satellites;

  SkyTruth sky(s.target_offset_rad);
  AttitudeModel attitude{AttitudeModel::Kind::kNominal, nullptr, &sky, s.t0};
  if (s.gnss.attitude == "observation") attitude.kind = AttitudeModel::Kind::kObservation;
  if (s.gnss.attitude == "campaign") {
    attitude.kind = AttitudeModel::Kind::kCampaign;
    attitude.profile = &*run.profile;
  }
  std::size_t next_piece = 0, next_lrf = 0;
  const std::vector<std::int64_t>& lrf_epochs = run.operations.lrf_epochs;
  RandomStream lrf_rng(s.seed, "osc.lrf");
  double measure_wall_s = 0.0;
  for (std::int64_t k = 0; k <= steps; ++k) {
    const double t_s = static_cast<double>(k) * s.step_s;
    const core::GpsTime t = s.t0 + t_s;
    const EpochFrame frame = epoch_frame(run.world, t);
    for (Craft& c : run.crafts) {
      update_attitude(c, t_s, attitude);
      const ReceiverPose pose = receiver_pose(c, frame, t, t_s, attitude);
      const auto measure_start = std::chrono::steady_clock::now();
      const GpsReceiverEpoch& epoch = c.receiver->measure(pose, satellites);
      measure_wall_s += seconds_since(measure_start);
      if (auto ok = record_epoch(c, epoch, t_s, *run.files); !ok) return ok.error();
      record_decoded_data_sets(c, epoch, t, t_s, run, 0.5 * s.gnss.broadcast_errors.refresh_s);
    }
    if (next_lrf < lrf_epochs.size() && lrf_epochs[next_lrf] == k) {
      write_lrf_row(run.files->lrf.get(), t_s, run.crafts, s.gnss.lrf, lrf_rng);
      ++next_lrf;
    }
    if (progress && k % 60 == 0) progress({t_s, s.gnss.duration_s, seconds_since(wall_start)});
    if (k == steps) break;
    if (auto ok = propagate_crafts(run, s, t_s, attitude, next_piece); !ok) return ok.error();
  }

  if (auto ok = close_rinex(run.crafts); !ok) return ok.error();
  const nlohmann::json summary = run_summary(s, run, steps, seconds_since(wall_start), measure_wall_s);
  std::ofstream summary_file(out_dir / "summary.json");
  summary_file << summary.dump(2) << "\n";
  if (!summary_file) return core::Error{(out_dir / "summary.json").string(), "cannot write"};
  return GnssRunResult{summary, out_dir};
}

}  // namespace visors::sim
