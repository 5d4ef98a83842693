#pragma once
// Each channel's record payload, defined once: its fields in wire order with their encoding,
// unit and meaning (the vocabulary: gnc/record_fields.hpp). The encoder and decoder
// (gnc/channel_record.hpp), the record sizes, the layout table docs/record-layout.md
// (gnc/files/record_layout.hpp, checked by a test) and the per-channel golden bytes
// (tests/gnc/golden/) all come from these lists. The values' validity (finite, in range, not
// stale) is the messages' own (gnc/messages.hpp validate); the lists say only how they travel.
//
// A change of a list changes the wire format: raise kRecordVersion (gnc/record_header.hpp),
// update the sizes pinned at the end of this file, regenerate the golden bytes and the table.

#include <cstddef>
#include <string_view>
#include <tuple>

#include "visors/gnc/messages.hpp"
#include "visors/gnc/record_fields.hpp"
#include "visors/gnc/record_header.hpp"

namespace visors::gnc {

/// The record of a message type: its channel, a title, its payload's field list.
template <class Message>
struct RecordSchema;

namespace record_schema {

using namespace record;  // NOLINT: the schema's vocabulary

using Epoch = gnss::GpsMeasurementEpoch;
using GpsChannel = gnss::GpsChannelMeasurement;
using Ephemeris = gnss::BroadcastEphemeris;

// The GPS message's channels in use and its broadcast record.
using GpsChannelCount = Count<"channel_count", At<&GpsMessage::epoch, &Epoch::channel_count>, AtMost<gnss::kMaxGpsChannels>,
                              "receiver channels in use">;
using EphemerisFields = Sequence<
    I32<"prn", At<&Ephemeris::prn>, "satellite">, I32<"iode", At<&Ephemeris::iode>, "issue of data, ephemeris">,
    I32<"iodc", At<&Ephemeris::iodc>, "issue of data, clock">, I32<"health", At<&Ephemeris::health>, "SV health, 0 healthy">,
    Time<"toc", At<&Ephemeris::toc>, "clock reference time">, Time<"toe", At<&Ephemeris::toe>, "ephemeris reference time">,
    Time<"transmission", At<&Ephemeris::transmission>, "transmission time of the message">,
    F64<"af0_s", At<&Ephemeris::af0_s>, "s", "clock bias">, F64<"af1_sps", At<&Ephemeris::af1_sps>, "s/s", "clock drift">,
    F64<"af2_sps2", At<&Ephemeris::af2_sps2>, "s/s^2", "clock drift rate">,
    F64<"sqrt_a", At<&Ephemeris::sqrt_a>, "m^0.5", "root of the semi-major axis">,
    F64<"eccentricity", At<&Ephemeris::eccentricity>, "", "eccentricity">,
    F64<"i0_rad", At<&Ephemeris::i0_rad>, "rad", "inclination at toe">,
    F64<"omega0_rad", At<&Ephemeris::omega0_rad>, "rad", "longitude of the ascending node at weekly epoch">,
    F64<"omega_rad", At<&Ephemeris::omega_rad>, "rad", "argument of perigee">,
    F64<"m0_rad", At<&Ephemeris::m0_rad>, "rad", "mean anomaly at toe">,
    F64<"delta_n_radps", At<&Ephemeris::delta_n_radps>, "rad/s", "mean motion difference">,
    F64<"idot_radps", At<&Ephemeris::idot_radps>, "rad/s", "inclination rate">,
    F64<"omega_dot_radps", At<&Ephemeris::omega_dot_radps>, "rad/s", "right ascension rate">,
    F64<"cuc_rad", At<&Ephemeris::cuc_rad>, "rad", "latitude correction, cosine">,
    F64<"cus_rad", At<&Ephemeris::cus_rad>, "rad", "latitude correction, sine">,
    F64<"crc_m", At<&Ephemeris::crc_m>, "m", "radius correction, cosine">,
    F64<"crs_m", At<&Ephemeris::crs_m>, "m", "radius correction, sine">,
    F64<"cic_rad", At<&Ephemeris::cic_rad>, "rad", "inclination correction, cosine">,
    F64<"cis_rad", At<&Ephemeris::cis_rad>, "rad", "inclination correction, sine">,
    F64<"tgd_s", At<&Ephemeris::tgd_s>, "s", "group delay">, F64<"ura_m", At<&Ephemeris::ura_m>, "m", "user range accuracy">,
    F64<"fit_interval_h", At<&Ephemeris::fit_interval_h>, "h", "fit interval">>;

// The crosslink's navigation part (CrosslinkNavigation) and its counts.
using CrosslinkEpochCount = Count<"epoch.count", At<&CrosslinkMessage::navigation, &CrosslinkNavigation::epoch, &CrosslinkEpoch::count>,
                                  AtMostIf<gnss::kMaxGpsChannels, "has_epoch", At<&CrosslinkMessage::navigation, &CrosslinkNavigation::has_epoch>>,
                                  "observations in the epoch">;
using CrosslinkImpulseCount = Count<"impulse_count", At<&CrosslinkMessage::navigation, &CrosslinkNavigation::impulse_count>,
                                    AtMost<kCrosslinkImpulses>, "executed impulses that follow, newest first">;
using CrosslinkNavigationFields = Sequence<
    Flag<"has_epoch", At<&CrosslinkNavigation::has_epoch>, "the sender's receiver epoch follows">, CrosslinkImpulseCount,
    Flag<"has_range", At<&CrosslinkNavigation::has_range>, "the OSC's newest rangefinder measurement follows">,
    CrosslinkEpochCount, Padding<4>,
    IfFlag<"has_epoch", At<&CrosslinkMessage::navigation, &CrosslinkNavigation::has_epoch>,
           Part<"epoch", At<&CrosslinkNavigation::epoch>, Time<"t", At<&CrosslinkEpoch::t>, "the receiver's time tag">,
                Slots<"observations", gnss::kMaxGpsChannels, At<&CrosslinkEpoch::observations>, CrosslinkEpochCount,
                      U8<"prn", At<&CrosslinkObservation::prn>, "satellite">,
                      TwoBits<"flags", At<&CrosslinkObservation::loss_of_lock>, At<&CrosslinkObservation::half_cycle>,
                              "bit 0 loss of lock, bit 1 half-cycle ambiguity">,
                      Padding<6>, F64<"code_m", At<&CrosslinkObservation::code_m>, "m", "L1 C/A pseudorange">,
                      F64<"phase_cycles", At<&CrosslinkObservation::phase_cycles>, "cycles", "L1 carrier phase">>>,
           Quaternion<"q_body_to_gcrf", At<&CrosslinkNavigation::q_body_to_gcrf>, "the sender's attitude at epoch.t">>,
    Slots<"impulses", kCrosslinkImpulses, At<&CrosslinkNavigation::impulses>, CrosslinkImpulseCount,
          Time<"t", At<&ExecutedImpulse::t>, "when executed">,
          Vector3<"dv_gcrf_mps", At<&ExecutedImpulse::dv_gcrf_mps>, "m/s", "commanded (quantised) delta-v, GCRF">>,
    IfFlag<"has_range", At<&CrosslinkMessage::navigation, &CrosslinkNavigation::has_range>,
           Part<"range", At<&CrosslinkNavigation::range>, Time<"t", At<&LaserRange::t>, "measurement time">,
                F64<"range_m", At<&LaserRange::range_m>, "m", "OSC rangefinder to the DSC's target point">>>>;

// The navigation telemetry's double differences, combinations and counters.
using DdCount = Count<"dd_count", At<&NavigationTelemetry::dd_count>, AtMost<kTelemetryDoubleDifferences>,
                      "double differences of the fix">;
using CombinationCount = Count<"combination_count", At<&NavigationTelemetry::combination_count>, AtMostCountOf<DdCount>,
                               "integer combinations of a partial fix">;
using NavigationCounterFields = Part<
    "counters", At<&NavigationTelemetry::counters>,
    I64<"epochs_joint", At<&NavigationCounters::epochs_joint>, "epochs processed with both receivers">,
    I64<"epochs_alone", At<&NavigationCounters::epochs_alone>, "epochs processed with the own receiver only">,
    I64<"epochs_refused", At<&NavigationCounters::epochs_refused>, "epochs the filter refused">,
    I64<"epochs_fixed", At<&NavigationCounters::epochs_fixed>, "updates with a fixed solution">,
    I64<"wrong_fixes_refused", At<&NavigationCounters::wrong_fixes_refused>, "fixes refused by validation">,
    I64<"impulses_applied", At<&NavigationCounters::impulses_applied>, "impulses taken into the filter">,
    I64<"impulses_late", At<&NavigationCounters::impulses_late>, "impulses that arrived after their epoch">,
    I64<"laser_used", At<&NavigationCounters::laser_used>, "rangefinder measurements used">,
    I64<"laser_rejected", At<&NavigationCounters::laser_rejected>, "rangefinder measurements rejected">,
    I64<"clock_jumps", At<&NavigationCounters::clock_jumps>, "receiver clock jumps taken into the clock states">,
    Slots<"ephemerides", kEphemerisStatuses, At<&NavigationCounters::ephemerides>, All<kEphemerisStatuses>,
          I64<"", At<>, "broadcast records by acceptance status (stored .. inconsistent)">>>;

}  // namespace record_schema

template <>
struct RecordSchema<TimeAtTone> {
  static constexpr Channel kChannel = Channel::kTimeAtTone;
  static constexpr std::string_view kTitle = "time at tone";
  using Payload = record::Sequence<record::Quaternion<"q_body_to_gcrf", record::At<&TimeAtTone::q_body_to_gcrf>,
                                                      "attitude, body to GCRF (Hamilton)">>;
};

template <>
struct RecordSchema<NavigationSolution> {
  static constexpr Channel kChannel = Channel::kNavigation;
  static constexpr std::string_view kTitle = "navigation solution";
  using Payload = record::Sequence<
      record::State<"chief_gcrf", record::At<&NavigationSolution::chief_gcrf>, "DSC, GCRF">,
      record::State<"deputy_gcrf", record::At<&NavigationSolution::deputy_gcrf>, "OSC, GCRF">,
      record::SymmetricUpper<6, "relative_covariance_rtn", record::At<&NavigationSolution::relative_covariance_rtn>,
                             "m^2, m^2/s, m^2/s^2", "covariance of [dr_rtn; dv_rtn], deputy relative to chief">>;
};

template <>
struct RecordSchema<CrosslinkMessage> {
  static constexpr Channel kChannel = Channel::kCrosslink;
  static constexpr std::string_view kTitle = "crosslink";
  using M = CrosslinkMessage;
  using Payload = record::Sequence<
      record::Enumerated<"sender", record::At<&M::sender>, Spacecraft, 2, "0 DSC, 1 OSC">,
      record::Enumerated<"mode", record::At<&M::mode>, Mode, kModeCount, "the sender's mode (gnc_mode.hpp order)">,
      record::Flag<"sender_active", record::At<&M::sender_active>, "the sender maneuvers">,
      record::Flag<"has_observation", record::At<&M::has_observation>, "the next observation is scheduled">,
      record::I32<"observations_done", record::At<&M::observations_done>, "">,
      record::I32<"observations_planned", record::At<&M::observations_planned>, "">,
      record::I32<"observation_index", record::At<&M::observation_index>, "1-based attempt number">,
      record::Time<"slew_start", record::At<&M::slew_start>, "">,
      record::Time<"observation_start", record::At<&M::observation_start>, "">,
      record::Time<"observation_end", record::At<&M::observation_end>, "">,
      record::Part<"navigation", record::At<&M::navigation>, record_schema::CrosslinkNavigationFields>>;
};

template <>
struct RecordSchema<GroundCommand> {
  static constexpr Channel kChannel = Channel::kGroundCommand;
  static constexpr std::string_view kTitle = "ground command";
  using Payload = record::Sequence<
      record::Enumerated<"kind", record::At<&GroundCommand::kind>, GroundCommand::Kind, 7,
                         "0 to_manual, 1 to_standby, 2 start_science, 3 transfer_to_standby, 4 escape, 5 make_active, "
                         "6 make_passive">,
      record::Padding<3>, record::I32<"observations", record::At<&GroundCommand::observations>, "start_science only">>;
};

template <>
struct RecordSchema<PropulsionTelemetry> {
  static constexpr Channel kChannel = Channel::kPropulsion;
  static constexpr std::string_view kTitle = "propulsion telemetry";
  using Payload = record::Sequence<
      record::Vector3<"dv_body_mps", record::At<&PropulsionTelemetry::dv_body_mps>, "m/s", "as executed (commanded, quantised)">,
      record::F64<"mass_kg", record::At<&PropulsionTelemetry::mass_kg>, "kg", "after the impulse">,
      record::Flag<"executed", record::At<&PropulsionTelemetry::executed>, "0: the command was refused">, record::Padding<7>>;
};

template <>
struct RecordSchema<GpsMessage> {
  static constexpr Channel kChannel = Channel::kGps;
  static constexpr std::string_view kTitle = "GPS";
  using Payload = record::Sequence<
      record_schema::GpsChannelCount,
      record::Flag<"has_ephemeris", record::At<&GpsMessage::has_ephemeris>, "a broadcast record follows the channels">,
      record::Padding<6>,
      record::Part<
          "epoch", record::At<&GpsMessage::epoch>,
          record::Slots<"channels", gnss::kMaxGpsChannels, record::At<&record_schema::Epoch::channels>,
                        record_schema::GpsChannelCount, record::U8<"prn", record::At<&record_schema::GpsChannel::prn>, "satellite">,
                        record::TwoBits<"flags", record::At<&record_schema::GpsChannel::loss_of_lock>,
                                        record::At<&record_schema::GpsChannel::half_cycle_ambiguity>,
                                        "bit 0 loss of lock, bit 1 half-cycle ambiguity">,
                        record::Padding<6>,
                        record::F64<"pseudorange_m", record::At<&record_schema::GpsChannel::pseudorange_m>, "m", "L1 C/A code">,
                        record::F64<"carrier_phase_cycles", record::At<&record_schema::GpsChannel::carrier_phase_cycles>,
                                    "cycles", "L1 carrier phase">,
                        record::F64<"doppler_hz", record::At<&record_schema::GpsChannel::doppler_hz>, "Hz",
                                    "positive when approaching">,
                        record::F64<"cn0_dbhz", record::At<&record_schema::GpsChannel::cn0_dbhz>, "dB-Hz", "carrier to noise density">,
                        record::F64<"lock_time_s", record::At<&record_schema::GpsChannel::lock_time_s>, "s", "continuous tracking">>>,
      record::IfFlag<"has_ephemeris", record::At<&GpsMessage::has_ephemeris>,
                     record::Part<"ephemeris", record::At<&GpsMessage::ephemeris>, record_schema::EphemerisFields>>>;
  /// Not on the wire: the epoch's time tag is the record's.
  static void complete(GpsMessage& m) { m.epoch.t = m.t; }
};

template <>
struct RecordSchema<LaserRange> {
  static constexpr Channel kChannel = Channel::kLaserRange;
  static constexpr std::string_view kTitle = "laser range";
  using Payload = record::Sequence<
      record::F64<"range_m", record::At<&LaserRange::range_m>, "m", "OSC rangefinder to the DSC's target point">>;
};

template <>
struct RecordSchema<ManeuverCommand> {
  static constexpr Channel kChannel = Channel::kManeuver;
  static constexpr std::string_view kTitle = "maneuver command";
  using Payload = record::Sequence<
      record::Vector3<"dv_body_mps", record::At<&ManeuverCommand::dv_body_mps>, "m/s", "for the thrusters, body frame">,
      record::Vector3<"dv_rtn_mps", record::At<&ManeuverCommand::dv_rtn_mps>, "m/s",
                      "the same impulse in the chief's RTN frame, own spacecraft's view">>;
};

template <>
struct RecordSchema<ObservationCommand> {
  static constexpr Channel kChannel = Channel::kObservation;
  static constexpr std::string_view kTitle = "observation command";
  using Payload = record::Sequence<record::I32<"index", record::At<&ObservationCommand::index>, "1-based attempt number">,
                                   record::Padding<4>, record::Time<"slew_start", record::At<&ObservationCommand::slew_start>, "">,
                                   record::Time<"start", record::At<&ObservationCommand::start>, "">,
                                   record::Time<"end", record::At<&ObservationCommand::end>, "">>;
};

template <>
struct RecordSchema<Telemetry> {
  static constexpr Channel kChannel = Channel::kTelemetry;
  static constexpr std::string_view kTitle = "telemetry";
  using M = Telemetry;
  using Payload = record::Sequence<
      record::Enumerated<"mode", record::At<&M::mode>, Mode, kModeCount, "gnc_mode.hpp order">,
      record::Flag<"active", record::At<&M::active>, "this spacecraft maneuvers">,
      record::Flag<"estimate_valid", record::At<&M::estimate_valid>, "">,
      record::Flag<"safety_checked", record::At<&M::safety_checked>, "a passive-safety check has been made">,
      record::Flag<"star_tracker_power", record::At<&M::star_tracker_power>, "">,
      record::Flag<"lrf_power", record::At<&M::lrf_power>, "">,
      record::Flag<"gnc_incapable", record::At<&M::gnc_incapable>, "">,
      record::Flag<"passive_safety_violated", record::At<&M::passive_safety_violated>, "">,
      record::Vector6<"roe_mean_m", record::At<&M::roe_mean_m>, "m", "a * mean ROE">,
      record::F64<"safety_margin_m", record::At<&M::safety_margin_m>, "m", "last check: min separation - q sigma">,
      record::Vector6<"roe_target_m", record::At<&M::roe_target_m>, "m", "a * mean ROE aimed at (0 outside science)">,
      record::I32<"observations_done", record::At<&M::observations_done>, "">,
      record::I32<"pending_pieces", record::At<&M::pending_pieces>, "buffered impulses not yet commanded">,
      record::I64<"plans", record::At<&M::plans>, "planner calls that produced a plan">,
      record::I64<"planning_failures", record::At<&M::planning_failures>, "">,
      record::Slots<"rejected.by_reason", kRejectionReasons, record::At<&M::rejected, &InputRejections::by_reason>,
                    record::All<kRejectionReasons>,
                    record::I64<"", record::At<>, "inputs refused, by RejectionReason (input_rejections.hpp; 0 unused)">>,
      record::Slots<"rejected.by_channel", kChannels + 1, record::At<&M::rejected, &InputRejections::by_channel>,
                    record::All<kChannels + 1>, record::I64<"", record::At<>, "the same by channel (0: unknown)">>,
      record::Flag<"navigation_valid", record::At<&M::navigation_valid>, "on-board navigation solution in use">,
      record::Flag<"navigation_fixed", record::At<&M::navigation_fixed>, "its last update was fixed">,
      record::Flag<"drag_valid", record::At<&M::drag_valid>, "the differential drag estimate is valid">, record::Padding<5>,
      record::Time<"navigation_update", record::At<&M::navigation_update>, "">,
      record::F64<"differential_drag_mps2", record::At<&M::differential_drag_mps2>, "m/s^2",
                  "along-track acceleration, deputy minus chief">>;
};

template <>
struct RecordSchema<NavigationTelemetry> {
  static constexpr Channel kChannel = Channel::kNavigationTelemetry;
  static constexpr std::string_view kTitle = "navigation telemetry";
  using M = NavigationTelemetry;
  using Payload = record::Sequence<
      record::Flag<"has_solution", record::At<&M::has_solution>, "the filter has started">,
      record::Flag<"valid", record::At<&M::valid>, "the solution meets the validity sigmas">,
      record::Flag<"fixed", record::At<&M::fixed>, "from a fixed update">,
      record::Flag<"fix_applied", record::At<&M::fix_applied>, "a fix was applied at update_t">,
      record::Flag<"full_fix", record::At<&M::full_fix>, "every double difference fixed">, record_schema::DdCount,
      record::U8<"dd_reference_prn", record::At<&M::dd_reference_prn>, "the double differences' reference satellite">,
      record_schema::CombinationCount, record::Time<"update_t", record::At<&M::update_t>, "the last epoch updated with">,
      record::State<"dsc_gcrf", record::At<&M::dsc_gcrf>, "estimated DSC centre of mass, GCRF">,
      record::State<"osc_gcrf", record::At<&M::osc_gcrf>, "estimated OSC centre of mass, GCRF">,
      record::Vector3<"p_dsc_body_m", record::At<&M::p_dsc_body_m>, "m", "DSC phase-centre offset error, body">,
      record::Vector3<"p_osc_body_m", record::At<&M::p_osc_body_m>, "m", "OSC phase-centre offset error, body">,
      record::Vector3<"empirical_dsc_rtn_mps2", record::At<&M::empirical_dsc_rtn_mps2>, "m/s^2", "DSC empirical acceleration, its RTN">,
      record::Vector3<"empirical_osc_rtn_mps2", record::At<&M::empirical_osc_rtn_mps2>, "m/s^2", "OSC empirical acceleration, its RTN">,
      record::Vector3<"relative_sigma_rtn_m", record::At<&M::relative_sigma_rtn_m>, "m", "1-sigma relative position, chief RTN">,
      record::Slots<"dd", kTelemetryDoubleDifferences, record::At<&M::dd>, record_schema::DdCount,
                    record::U8<"prn", record::At<&FixedDoubleDifference::prn>, "satellite against the reference">,
                    record::Padding<7>,
                    record::I64<"integer_cycles", record::At<&FixedDoubleDifference::integer_cycles>, "the fixed integer of a full fix">,
                    record::F64<"fixed_cycles", record::At<&FixedDoubleDifference::fixed_cycles>, "cycles",
                                "the double difference of the fixed solution">>,
      record::Slots<"combinations", kTelemetryDoubleDifferences, record::At<&M::combinations>, record_schema::CombinationCount,
                    record::Slots<"dd_coefficients", kTelemetryDoubleDifferences, record::At<&FixedCombination::dd_coefficients>,
                                  record_schema::DdCount, record::I32<"", record::At<>, "coefficient of dd[j]">>,
                    record::Padding<4>,
                    record::I64<"integer_cycles", record::At<&FixedCombination::integer_cycles>, "the combination's integer">>,
      record_schema::NavigationCounterFields>;
};

/// Every message with a record, in channel order.
using RecordMessages = std::tuple<TimeAtTone, NavigationSolution, CrosslinkMessage, GroundCommand, PropulsionTelemetry, GpsMessage,
                                  LaserRange, ManeuverCommand, ObservationCommand, Telemetry, NavigationTelemetry>;
static_assert(std::tuple_size_v<RecordMessages> == kChannels, "one message per channel");

/// The payload's size of a message's record [bytes], from its field list.
template <class Message>
inline constexpr std::size_t kPayloadBytes = RecordSchema<Message>::Payload::kBytes;

// The sizes of version 3 of the format (docs/record-layout.md): a list that changes one of them
// changes the wire format (see the file comment).
static_assert(kPayloadBytes<TimeAtTone> == 32);
static_assert(kPayloadBytes<NavigationSolution> == 264);
static_assert(kPayloadBytes<CrosslinkMessage> == 456);
static_assert(kPayloadBytes<GroundCommand> == 8);
static_assert(kPayloadBytes<PropulsionTelemetry> == 40);
static_assert(kPayloadBytes<GpsMessage> == 792);
static_assert(kPayloadBytes<LaserRange> == 8);
static_assert(kPayloadBytes<ManeuverCommand> == 48);
static_assert(kPayloadBytes<ObservationCommand> == 32);
static_assert(kPayloadBytes<Telemetry> == 480);
static_assert(kPayloadBytes<NavigationTelemetry> == 1240);

}  // namespace visors::gnc
