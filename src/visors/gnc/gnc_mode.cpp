#include "visors/gnc/gnc_mode.hpp"

#include <array>

namespace visors::gnc {

namespace {
constexpr std::array<std::string_view, kModeCount> kNames{"manual", "standby", "transfer_to_science",
                                                          "science", "transfer_to_standby", "escape"};
}  // namespace

std::string_view to_string(Mode mode) { return kNames[static_cast<std::size_t>(mode)]; }

std::optional<Mode> mode_from_string(std::string_view text) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == text) return static_cast<Mode>(i);
  }
  return std::nullopt;
}

}  // namespace visors::gnc
