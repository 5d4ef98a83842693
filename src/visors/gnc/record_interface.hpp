#pragma once
// The flight component behind its binary channels (docs/architecture.md#binary-records): what a
// host application calls once per step with the records that arrived, and what it gets back as
// records. The simulator drives each component through it, so every message
// of the loop goes through the codec (gnc/channel_record.hpp) every step.
//
// Inputs: any number of records of any channels, in any order, any of them garbage. Each is
// dispatched by its header's channel to its decode(); a structural failure (truncated, bad
// checksum, unknown channel, an output channel, ...) and a record older than the last one
// admitted on its channel (SequenceGate) are refused; the values of an admitted record are
// validated here, once (messages.hpp validate: stale, non-finite, out of range), and both kinds
// of refusal are counted in one set, by reason and channel (Telemetry::rejected,
// gnc/input_rejections.hpp). Of several records of one channel in a step the newest valid one
// is used, so garbage values never displace a good
// record; the component takes them as valid (FlightComponent::step_validated).
// Nothing crashes, nothing allocates (a refused record included), nothing throws.
// Outputs: the step's maneuver, observation, crosslink, telemetry and navigation telemetry, each
// as one record with its channel's own sequence; the telemetry record every step, the navigation
// telemetry every step of a component with on-board navigation.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "visors/core/result.hpp"
#include "visors/gnc/channel_record.hpp"
#include "visors/gnc/flight_component.hpp"

namespace visors::gnc {

/// One record's bytes (a view: the caller keeps them alive for the call).
using RecordView = std::span<const std::uint8_t>;

/// The step's output records; a channel without output has size 0.
struct OutputRecords {
  struct Record {
    std::array<std::uint8_t, kMaxRecordBytes> bytes{};
    std::size_t size = 0;
    [[nodiscard]] RecordView view() const { return {bytes.data(), size}; }
  };
  Record maneuver, observation, crosslink, telemetry;
  Record navigation;  // NavigationTelemetry (Channel::kNavigationTelemetry)
};

class RecordInterface {
 public:
  static core::Result<RecordInterface> create(const GncConfig& config,
                                              std::optional<OnboardNavigation> navigation = std::nullopt);

  /// One step at t with the records that arrived since the last one.
  const OutputRecords& step(core::GpsTime t, std::span<const RecordView> inputs);

  /// The tone of a step (a flight software process steps at it, apps/fsw/): the time tag of the
  /// first time-at-tone record among `inputs` that decodes and that the sequence gate would
  /// admit, whatever its values (an attitude the validation refuses still carries the time).
  /// nullopt without one. Changes nothing.
  [[nodiscard]] std::optional<core::GpsTime> tone(std::span<const RecordView> inputs) const;

  [[nodiscard]] const FlightComponent& component() const { return component_; }
  /// The inputs refused here: records by their bytes, records by their values.
  [[nodiscard]] const InputRejections& rejected() const { return rejected_; }

 private:
  explicit RecordInterface(FlightComponent component) : component_(std::move(component)) {}
  /// Decodes one record into `in` (its channel's slot), or counts why not.
  void accept(RecordView record, GncInputs& in);
  void encode_outputs(const GncOutputs& out);

  FlightComponent component_;
  SequenceGate gate_;
  InputRejections rejected_;  // records refused by their bytes or their values
  std::array<std::uint32_t, kChannels + 1> sequence_{};  // of the outputs, per channel
  OutputRecords out_;
};

}  // namespace visors::gnc
