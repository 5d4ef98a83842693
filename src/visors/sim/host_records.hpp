#pragma once
// The step's input records of one spacecraft as its host application writes them: each message
// encoded with the host's next sequence number of its channel (gnc/channel_record.hpp), crosslink
// records forwarded as received. Kept by the simulation from step to step, so its storage is
// reused rather than allocated every step.

#include <array>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "visors/gnc/channel_record.hpp"

namespace visors::sim {

template <class Message>
constexpr gnc::Channel channel_for() {
  if constexpr (std::is_same_v<Message, gnc::TimeAtTone>) return gnc::Channel::kTimeAtTone;
  else if constexpr (std::is_same_v<Message, gnc::NavigationSolution>) return gnc::Channel::kNavigation;
  else if constexpr (std::is_same_v<Message, gnc::GroundCommand>) return gnc::Channel::kGroundCommand;
  else if constexpr (std::is_same_v<Message, gnc::PropulsionTelemetry>) return gnc::Channel::kPropulsion;
  else if constexpr (std::is_same_v<Message, gnc::GpsMessage>) return gnc::Channel::kGps;
  else return gnc::Channel::kLaserRange;
}

class HostRecords {
 public:
  /// Per channel, the sequence number of the next record the host writes.
  using Sequences = std::array<std::uint32_t, gnc::kChannels + 1>;

  /// Encodes `message` with its channel's next sequence number (incremented).
  template <class Message>
  void add(Sequences& sequence, const Message& message) {
    gnc::OutputRecords::Record& r = records_.emplace_back();
    r.size = gnc::encode(message, sequence[static_cast<std::size_t>(channel_for<Message>())]++, r.bytes);
  }
  void forward(const gnc::OutputRecords::Record& record) { records_.push_back(record); }
  void clear() { records_.clear(); }
  /// Views of the records added since clear(), valid until the next add, forward or clear.
  std::span<const gnc::RecordView> views() {
    views_.clear();
    for (const auto& r : records_) views_.push_back(r.view());
    return views_;
  }

 private:
  std::vector<gnc::OutputRecords::Record> records_;
  std::vector<gnc::RecordView> views_;
};

}  // namespace visors::sim
