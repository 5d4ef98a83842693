#include "visors/gnc/maneuver_queue.hpp"

#include <algorithm>

namespace visors::gnc {

ManeuverQueue::ManeuverQueue(int capacity) : capacity_(static_cast<std::size_t>(std::max(capacity, 1))) {
  pieces_.reserve(capacity_);
}

core::Outcome<int> ManeuverQueue::add(core::GpsTime epoch, const astro::KeplerianElements& chief_mean_epoch,
                                     std::span<const control::Impulse> impulses, double mass_kg,
                                     const control::BufferSettings& settings) {
  if (next_ > 0) {  // compact: released pieces are gone for good
    pieces_.erase(pieces_.begin(), pieces_.begin() + static_cast<std::ptrdiff_t>(next_));
    next_ = 0;
  }
  int added = 0;
  for (const control::Impulse& impulse : impulses) {
    if (auto ok = buffer_.buffer(chief_mean_epoch, impulse, mass_kg, settings); !ok) return ok;
    const auto& pieces = buffer_.result().pieces;
    if (pieces_.size() + pieces.size() > capacity_) return core::Status{core::Problem::kCapacity, "queue", "more pieces than its capacity"};
    for (const control::Impulse& piece : pieces) {
      pieces_.push_back({epoch + piece.t, piece.dv_rtn});
      ++added;
    }
  }
  // std::sort, not stable_sort: the latter takes a temporary buffer from the heap.
  std::sort(pieces_.begin(), pieces_.end(), [](const QueuedPiece& a, const QueuedPiece& b) { return a.t < b.t; });
  return added;
}

bool ManeuverQueue::due(core::GpsTime now, double spacing_s) const {
  if (empty() || pieces_[next_].t > now) return false;
  return !released_ || now.seconds_since(last_release_) >= spacing_s;
}

QueuedPiece ManeuverQueue::pop(core::GpsTime now) {
  const QueuedPiece piece = pieces_[next_++];
  released_ = true;
  last_release_ = now;
  return piece;
}

}  // namespace visors::gnc
