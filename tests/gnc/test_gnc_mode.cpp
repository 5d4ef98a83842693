#include <gtest/gtest.h>

#include "visors/gnc/gnc_mode.hpp"

namespace {

using visors::gnc::Mode;

// Names are those of docs/run-directory.md (the report and the event log rely on them).
TEST(GncMode, NamesRoundTrip) {
  for (int i = 0; i < visors::gnc::kModeCount; ++i) {
    const auto mode = static_cast<Mode>(i);
    EXPECT_EQ(visors::gnc::mode_from_string(visors::gnc::to_string(mode)), mode);
  }
}

TEST(GncMode, TransferToScienceName) { EXPECT_EQ(visors::gnc::to_string(Mode::kTransferToScience), "transfer_to_science"); }

TEST(GncMode, UnknownNameIsRejected) { EXPECT_FALSE(visors::gnc::mode_from_string("Science").has_value()); }

}  // namespace
