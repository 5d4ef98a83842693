#include "visors/gnc/record_interface.hpp"

#include <utility>

namespace visors::gnc {

namespace {

// Decodes `record` as a Message; admitted through the gate and with valid values (messages.hpp
// validate, at the step's time t), it replaces `slot`: the newest VALID record of a channel is
// used, so a record of garbage values cannot displace a good one of the same step. A refused value
// is counted in `rejected` (of the channel).
template <class Message>
RecordStatus decode_into(RecordView record, core::GpsTime t, SequenceGate& gate, std::optional<Message>& slot,
                         std::int64_t& rejected) {
  Message message;
  RecordHeader header;
  if (const RecordStatus s = decode(record, message, header); s != RecordStatus::kAccepted) return s;
  if (const RecordStatus s = gate.admit(header); s != RecordStatus::kAccepted) return s;
  if (validate(message, t).ok()) slot = message;
  else ++rejected;
  return RecordStatus::kAccepted;
}

void add(RejectionCounters& to, const RejectionCounters& from) {
  to.time_at_tone += from.time_at_tone;
  to.navigation += from.navigation;
  to.crosslink += from.crosslink;
  to.command += from.command;
  to.propulsion += from.propulsion;
  to.gps += from.gps;
  to.laser_range += from.laser_range;
}

}  // namespace

core::Result<RecordInterface> RecordInterface::create(const GncConfig& config, std::optional<OnboardNavigation> navigation) {
  auto component = FlightComponent::create(config, std::move(navigation));
  if (!component.ok()) return component.error();
  return RecordInterface(std::move(component).value());
}

void RecordInterface::accept(RecordView record, GncInputs& in) {
  RecordStatus status = RecordStatus::kUnknownChannel;
  const std::optional<Channel> channel = channel_of(record);
  if (record.size() < kHeaderBytes) status = RecordStatus::kTruncated;
  else if (record[0] != kRecordMagic[0] || record[1] != kRecordMagic[1]) status = RecordStatus::kBadMagic;
  else if (channel) {
    switch (*channel) {
      case Channel::kTimeAtTone: status = decode_into(record, in.t, gate_, in.time_at_tone, rejected_.time_at_tone); break;
      case Channel::kNavigation: status = decode_into(record, in.t, gate_, in.navigation, rejected_.navigation); break;
      case Channel::kCrosslink: status = decode_into(record, in.t, gate_, in.crosslink, rejected_.crosslink); break;
      case Channel::kGroundCommand: status = decode_into(record, in.t, gate_, in.command, rejected_.command); break;
      case Channel::kPropulsion: status = decode_into(record, in.t, gate_, in.propulsion, rejected_.propulsion); break;
      case Channel::kGps: status = decode_into(record, in.t, gate_, in.gps, rejected_.gps); break;
      case Channel::kLaserRange: status = decode_into(record, in.t, gate_, in.laser_range, rejected_.laser_range); break;
      case Channel::kManeuver:
      case Channel::kObservation:
      case Channel::kTelemetry:
      case Channel::kNavigationTelemetry: status = RecordStatus::kWrongChannel; break;  // outputs, not inputs
    }
  }
  if (status != RecordStatus::kAccepted) count(refused_, status);
}

const OutputRecords& RecordInterface::step(core::GpsTime t, std::span<const RecordView> inputs) {
  GncInputs in;
  in.t = t;
  for (const RecordView record : inputs) accept(record, in);
  GncOutputs out = component_.step_validated(in);  // validated record by record above
  out.telemetry.records = refused_;
  add(out.telemetry.rejected, rejected_);
  encode_outputs(out);
  return out_;
}

std::optional<core::GpsTime> RecordInterface::tone(std::span<const RecordView> inputs) const {
  for (const RecordView record : inputs) {
    if (channel_of(record) != Channel::kTimeAtTone) continue;
    TimeAtTone message;
    RecordHeader header;
    if (decode(record, message, header) == RecordStatus::kAccepted && gate_.would_admit(header)) return header.t;
  }
  return std::nullopt;
}

void RecordInterface::encode_outputs(const GncOutputs& out) {
  const auto write = [this](const auto& message, Channel channel, OutputRecords::Record& record) {
    record.size = encode(message, sequence_[static_cast<std::size_t>(channel)]++, record.bytes);
  };
  out_.maneuver.size = out_.observation.size = out_.crosslink.size = out_.navigation.size = 0;
  if (out.maneuver) write(*out.maneuver, Channel::kManeuver, out_.maneuver);
  if (out.observation) write(*out.observation, Channel::kObservation, out_.observation);
  if (out.crosslink) write(*out.crosslink, Channel::kCrosslink, out_.crosslink);
  write(out.telemetry, Channel::kTelemetry, out_.telemetry);
  if (out.navigation) write(*out.navigation, Channel::kNavigationTelemetry, out_.navigation);
}

}  // namespace visors::gnc
