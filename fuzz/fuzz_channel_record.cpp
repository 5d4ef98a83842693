// libFuzzer target of the flight component's binary records (gnc/channel_record.hpp): any input,
// decoded as every channel, must be refused with a reason or accepted; an accepted record must be
// canonical (encoding what it decodes to gives back its bytes) and must then pass the sequence
// gate once and be refused the second time. Random bytes almost never carry a valid CRC-32C, so
// each input is also sealed as a record of each channel (magic, channel, version, size and
// checksum written over it) to drive the payload checks. Built with clang only (CMake option
// VISORS_FUZZ); run by scripts/fuzz.sh. Sanitizers (address, undefined) catch any read outside
// the input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "visors/gnc/channel_record.hpp"
#include "visors/gnc/crc32c.hpp"

namespace {

using namespace visors::gnc;

template <class Message>
void check(std::span<const std::uint8_t> in) {
  Message message{};
  RecordHeader header;
  const RecordStatus status = decode(in, message, header);
  if (static_cast<int>(status) >= kRecordStatuses) std::abort();  // a reason outside the list
  if (status != RecordStatus::kAccepted) return;
  RecordBuffer again{};
  const std::size_t n = encode(message, header.sequence, again);
  if (n != header.size || n > in.size()) std::abort();
  for (std::size_t i = 0; i < n; ++i) {
    if (again[i] != in[i]) std::abort();  // not canonical
  }
  SequenceGate gate;
  if (gate.admit(header) != RecordStatus::kAccepted || gate.admit(header) != RecordStatus::kOutOfOrder) std::abort();
}

// The input as a record of `channel`: its bytes (zero-padded or cut), the frame fields and the
// checksum written over them; then checked as `Message`.
template <class Message>
void check_sealed(std::span<const std::uint8_t> in, Channel channel) {
  RecordBuffer record{};
  const std::size_t size = record_size(channel);
  for (std::size_t i = 0; i < size && i < in.size(); ++i) record[i] = in[i];
  record[0] = 'V';
  record[1] = 'G';
  record[2] = static_cast<std::uint8_t>(channel);
  record[3] = kRecordVersion;
  record[4] = static_cast<std::uint8_t>(size);
  record[5] = static_cast<std::uint8_t>(size >> 8);
  const std::uint32_t crc = crc32c(std::span<const std::uint8_t>(record).first(size - kChecksumBytes));
  for (std::size_t i = 0; i < 4; ++i) record[size - 4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
  check<Message>(std::span<const std::uint8_t>(record).first(size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> in(data, size);
  check<TimeAtTone>(in);
  check<NavigationSolution>(in);
  check<CrosslinkMessage>(in);
  check<GroundCommand>(in);
  check<PropulsionTelemetry>(in);
  check<GpsMessage>(in);
  check<LaserRange>(in);
  check<ManeuverCommand>(in);
  check<ObservationCommand>(in);
  check<Telemetry>(in);
  check<NavigationTelemetry>(in);
  check_sealed<TimeAtTone>(in, Channel::kTimeAtTone);
  check_sealed<NavigationSolution>(in, Channel::kNavigation);
  check_sealed<CrosslinkMessage>(in, Channel::kCrosslink);
  check_sealed<GroundCommand>(in, Channel::kGroundCommand);
  check_sealed<PropulsionTelemetry>(in, Channel::kPropulsion);
  check_sealed<GpsMessage>(in, Channel::kGps);
  check_sealed<LaserRange>(in, Channel::kLaserRange);
  check_sealed<ManeuverCommand>(in, Channel::kManeuver);
  check_sealed<ObservationCommand>(in, Channel::kObservation);
  check_sealed<Telemetry>(in, Channel::kTelemetry);
  check_sealed<NavigationTelemetry>(in, Channel::kNavigationTelemetry);
  return 0;
}
