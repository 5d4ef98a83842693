#pragma once
// The flight component's modes (Guffanti et al., AAS 23-149, 2023, sec. 3;
// docs/architecture.md#modes): manual -> standby (command) -> transfer to science (command) ->
// science (N observation attempts) -> transfer to standby (autonomous) -> standby; escape from any
// mode on a passive-safety violation, exiting to manual. The two transfer directions are separate
// modes so that telemetry and the delta-v budget can tell them apart (the paper's delta-v budget,
// in its appendix, lists them separately).

#include <cstdint>
#include <optional>
#include <string_view>

namespace visors::gnc {

enum class Mode : std::uint8_t { kManual, kStandby, kTransferToScience, kScience, kTransferToStandby, kEscape };

inline constexpr int kModeCount = 6;

/// "manual", "standby", "transfer_to_science", "science", "transfer_to_standby", "escape".
std::string_view to_string(Mode mode);
/// The inverse of to_string; nullopt for any other text.
std::optional<Mode> mode_from_string(std::string_view text);

}  // namespace visors::gnc
