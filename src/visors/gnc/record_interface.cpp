#include "visors/gnc/record_interface.hpp"

#include <utility>

namespace visors::gnc {

namespace {

// Decodes `record` as a Message; admitted through the gate and with valid values (messages.hpp
// validate, at the step's time t), it replaces `slot`: the newest VALID record of a channel is
// used, so a record of garbage values cannot displace a good one of the same step. A refused value
// is counted in `rejected` by its problem and the channel.
template <class Message>
RecordStatus decode_into(RecordView record, core::GpsTime t, SequenceGate& gate, std::optional<Message>& slot,
                         InputRejections& rejected) {
  Message message;
  RecordHeader header;
  if (const RecordStatus s = decode(record, message, header); s != RecordStatus::kAccepted) return s;
  if (const RecordStatus s = gate.admit(header); s != RecordStatus::kAccepted) return s;
  if (const core::Status valid = validate(message, t); valid.ok()) slot = message;
  else rejected.count(rejection_reason(valid.problem()), RecordSchema<Message>::kChannel);
  return RecordStatus::kAccepted;
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
      case Channel::kTimeAtTone: status = decode_into(record, in.t, gate_, in.time_at_tone, rejected_); break;
      case Channel::kNavigation: status = decode_into(record, in.t, gate_, in.navigation, rejected_); break;
      case Channel::kCrosslink: status = decode_into(record, in.t, gate_, in.crosslink, rejected_); break;
      case Channel::kGroundCommand: status = decode_into(record, in.t, gate_, in.command, rejected_); break;
      case Channel::kPropulsion: status = decode_into(record, in.t, gate_, in.propulsion, rejected_); break;
      case Channel::kGps: status = decode_into(record, in.t, gate_, in.gps, rejected_); break;
      case Channel::kLaserRange: status = decode_into(record, in.t, gate_, in.laser_range, rejected_); break;
      case Channel::kManeuver:
      case Channel::kObservation:
      case Channel::kTelemetry:
      case Channel::kNavigationTelemetry: status = RecordStatus::kWrongChannel; break;  // outputs, not inputs
    }
  }
  if (status != RecordStatus::kAccepted) rejected_.count(rejection_reason(status), channel ? static_cast<int>(*channel) : 0);
}

const OutputRecords& RecordInterface::step(core::GpsTime t, std::span<const RecordView> inputs) {
  GncInputs in;
  in.t = t;
  for (const RecordView record : inputs) accept(record, in);
  GncOutputs out = component_.step_validated(in);  // validated record by record above
  out.telemetry.rejected += rejected_;
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
