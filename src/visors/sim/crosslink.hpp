#pragma once
// Inter-satellite link of the simulator: a fixed delay and independent message loss.
//
// Each message sent at t_send is delivered by the first receive(t) with t >= t_send + delay_s;
// receive returns the due messages in the order they were sent. Loss is decided at send time by
// one uniform draw per message (dropped when u < drop_probability), so which messages are lost
// depends only on the seed and the send sequence, not on how often the receiver polls. A dropped
// message is never delivered. The link is one-directional; a two-way link is two of them.

#include <cassert>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

/// Defaults (docs/requirements.md#gps-receiver-and-sensors): the delay of
/// Guffanti et al., AAS 23-149, 2023 ("paper"), sec. 5; no loss nominally, the faults' scenarios
/// set one.
struct CrosslinkSettings {
  double delay_s = 0.5;           // transport delay [s] (paper, sec. 5)
  double drop_probability = 0.0;  // probability that a message is lost [-] (project choice)

  /// Ok, or the offending field by name.
  [[nodiscard]] core::Result<bool> validate() const {
    if (!std::isfinite(delay_s) || delay_s < 0.0) return core::Error{"delay_s", "must be finite and >= 0 s"};
    if (!(drop_probability >= 0.0 && drop_probability <= 1.0)) {
      return core::Error{"drop_probability", "must be in [0, 1]"};
    }
    return true;
  }
};

template <class Message>
class Crosslink {
 public:
  /// Validates the settings; `rng` decides the losses.
  static core::Result<Crosslink> create(const CrosslinkSettings& settings, RandomStream rng) {
    if (auto ok = settings.validate(); !ok) return ok.error();
    return Crosslink(settings, std::move(rng));
  }

  /// Queues `message` sent at t_s [s] (finite), unless the loss draw drops it.
  void send(double t_s, const Message& message) {
    assert(std::isfinite(t_s));
    ++sent_;
    if (rng_.uniform() < settings_.drop_probability) {
      ++dropped_;
      return;
    }
    in_flight_.push_back({t_s + settings_.delay_s, message});
  }

  /// Every queued message with t_send + delay_s <= t_s [s], in send order; removes them.
  std::vector<Message> receive(double t_s) {
    std::vector<Message> due;
    std::vector<InFlight> waiting;
    for (InFlight& m : in_flight_) {
      if (m.arrival_s <= t_s) {
        due.push_back(std::move(m.message));
      } else {
        waiting.push_back(std::move(m));
      }
    }
    in_flight_ = std::move(waiting);
    return due;
  }

  [[nodiscard]] std::size_t sent_count() const { return sent_; }
  [[nodiscard]] std::size_t dropped_count() const { return dropped_; }
  [[nodiscard]] std::size_t in_flight_count() const { return in_flight_.size(); }
  [[nodiscard]] const CrosslinkSettings& settings() const { return settings_; }

 private:
  struct InFlight {
    double arrival_s;  // t_send + delay [s]
    Message message;
  };

  Crosslink(const CrosslinkSettings& settings, RandomStream rng) : settings_(settings), rng_(std::move(rng)) {}

  CrosslinkSettings settings_;
  RandomStream rng_;
  std::vector<InFlight> in_flight_;
  std::size_t sent_ = 0;
  std::size_t dropped_ = 0;
};

}  // namespace visors::sim
