#include <gtest/gtest.h>

#include <algorithm>

#include "visors/sim/host_application.hpp"

namespace {

using visors::gnc::Mode;
using visors::sim::fdir_response;
using visors::sim::FdirResponse;
using visors::sim::FdirTrigger;
using visors::sim::kFdirPolicy;

// The host's FDIR policy (Guffanti et al., AAS 23-149, 2023, sec. 4.1, FDIR): one rule per
// trigger.
TEST(FdirPolicy, EachTriggerHasExactlyOneRule) {
  for (FdirTrigger trigger : {FdirTrigger::kSafetyViolation, FdirTrigger::kGncIncapable, FdirTrigger::kNonGncFault,
                              FdirTrigger::kUnableToAct}) {
    EXPECT_EQ(std::count_if(kFdirPolicy.begin(), kFdirPolicy.end(), [&](const auto& rule) { return rule.trigger == trigger; }), 1);
  }
}

// Paper: a passive-safety violation commands the escape, whatever the mode.
TEST(FdirPolicy, SafetyViolationEscapesInEveryMode) {
  for (Mode mode : {Mode::kStandby, Mode::kTransferToScience, Mode::kScience, Mode::kTransferToStandby}) {
    EXPECT_EQ(fdir_response(FdirTrigger::kSafetyViolation, mode), FdirResponse::kEscape);
  }
}

// Paper: a non-GNC fault in science (or the transfer to it) returns the formation to standby...
TEST(FdirPolicy, NonGncFaultInScienceReturnsToStandby) {
  EXPECT_EQ(fdir_response(FdirTrigger::kNonGncFault, Mode::kScience), FdirResponse::kTransferToStandby);
  EXPECT_EQ(fdir_response(FdirTrigger::kNonGncFault, Mode::kTransferToScience), FdirResponse::kTransferToStandby);
}

// ...and otherwise switches roles.
TEST(FdirPolicy, NonGncFaultOutsideScienceSwitchesRoles) {
  EXPECT_EQ(fdir_response(FdirTrigger::kNonGncFault, Mode::kStandby), FdirResponse::kRoleSwitch);
  EXPECT_EQ(fdir_response(FdirTrigger::kNonGncFault, Mode::kTransferToStandby), FdirResponse::kRoleSwitch);
}

// A spacecraft that cannot act cannot fly the return itself: the roles switch first.
TEST(FdirPolicy, UnableToActInScienceSwitchesThenReturns) {
  EXPECT_EQ(fdir_response(FdirTrigger::kUnableToAct, Mode::kScience), FdirResponse::kRoleSwitchThenStandby);
  EXPECT_EQ(fdir_response(FdirTrigger::kUnableToAct, Mode::kStandby), FdirResponse::kRoleSwitch);
}

// Paper: GNC incapable on the active spacecraft hands the formation to the other.
TEST(FdirPolicy, GncIncapableSwitchesRoles) {
  EXPECT_EQ(fdir_response(FdirTrigger::kGncIncapable, Mode::kScience), FdirResponse::kRoleSwitch);
}

// GNC incapable's persistence (GncIncapablePersistence): 60 s once capable, 600 s at the cold start.
using visors::sim::GncIncapablePersistence;

bool due_after(GncIncapablePersistence& p, double from_s, double to_s) {
  bool due = false;
  for (double t = from_s; t <= to_s; t += 1.0) due = p.due(true, t);
  return due;
}

TEST(GncIncapablePersistence, ColdStartIsNotAFaultAfterAMinute) {
  GncIncapablePersistence p;
  EXPECT_FALSE(due_after(p, 0.0, 150.0));  // the real sky's first fix: 70-150 s
}

TEST(GncIncapablePersistence, ColdStartThatNeverEndsHandsOverAfterTenMinutes) {
  GncIncapablePersistence p;
  EXPECT_TRUE(due_after(p, 0.0, 600.0));
}

TEST(GncIncapablePersistence, OnceCapableAMinuteIsEnough) {
  GncIncapablePersistence p;
  (void)p.due(false, 0.0);
  EXPECT_TRUE(due_after(p, 1.0, 61.0));
}

TEST(GncIncapablePersistence, CapableAgainRestartsTheCount) {
  GncIncapablePersistence p;
  (void)p.due(false, 0.0);
  (void)due_after(p, 1.0, 50.0);
  (void)p.due(false, 51.0);
  EXPECT_FALSE(due_after(p, 52.0, 100.0));
}

}  // namespace
