// core::Status and core::Outcome: the flight layers' allocation-free verdicts (core/status.hpp).
// References: the contract the header states (names joined by '.', outermost scope first, the
// problem's description when no detail is given) and the allocation rule it exists for.
#include <gtest/gtest.h>

#include <string>

#include "support/allocation_counter.hpp"
#include "visors/core/status.hpp"

namespace {

using visors::core::Outcome;
using visors::core::Problem;
using visors::core::Result;
using visors::core::Status;

TEST(Status, DefaultIsOk) { EXPECT_TRUE(Status{}.ok()); }

TEST(Status, AProblemIsNotOk) { EXPECT_FALSE((Status{Problem::kNotFinite, "r"}.ok())); }

TEST(Status, WithoutADetailTheMessageIsTheProblemsDescription) {
  EXPECT_EQ((Status{Problem::kNotFinite, "r"}.message()), visors::core::describe(Problem::kNotFinite));
}

TEST(Status, ADetailIsTheMessage) {
  EXPECT_EQ((Status{Problem::kOutOfRange, "e", "must be in [0, 1)"}.message()), "must be in [0, 1)");
}

TEST(Status, WithinNamesTheEnclosingInputFirst) {
  const Status s = Status{Problem::kOutOfRange, "e"}.within("chief").within("navigation");
  EXPECT_EQ(s.path(), "navigation.chief.e");
}

TEST(Status, WithinKeepsTheProblemAndTheField) {
  const Status s = Status{Problem::kSingular, "i", "equatorial"}.within("chief");
  EXPECT_EQ(s.problem(), Problem::kSingular);
  EXPECT_STREQ(s.field(), "i");
}

TEST(Status, WithinLeavesOkOk) { EXPECT_TRUE(Status{}.within("chief").ok()); }

TEST(Status, AnEmptyFieldNamesTheScopeAlone) {
  EXPECT_EQ((Status{Problem::kCapacity, ""}.within("queue").path()), "queue");
}

TEST(Status, AsAnErrorItCarriesThePathAndTheMessage) {
  const auto e = Status{Problem::kOutOfRange, "e", "must be in [0, 1)"}.within("chief").error();
  EXPECT_EQ(e.describe(), "chief.e: must be in [0, 1)");
}

// The reason the type exists: a failure, scoped twice, allocates nothing (malloc counted at the C
// level, tests/support/allocation_counter.hpp).
TEST(Status, AScopedFailureAllocatesNothing) {
  Status s;
  const long allocations = visors::test::count_allocations([&] {
    s = Status{Problem::kOutOfRange, "e", "must be in [0, 1)"}.within("chief").within("navigation");
  });
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(allocations, 0);
}

TEST(Status, TheCounterSeesAnErrorsText) {  // the control: composing the Error does allocate
  const Status s = Status{Problem::kOutOfRange, "e"}.within("a_scope_name_longer_than_sso_buffers");
  std::string text;
  const long allocations = visors::test::count_allocations([&] { text = s.error().describe(); });
  EXPECT_GT(allocations, 0);
}

Outcome<double> half(double x) {
  if (!(x >= 0.0)) return Status{Problem::kOutOfRange, "x", "must be >= 0"};
  return 0.5 * x;
}

TEST(Outcome, HoldsTheValue) { EXPECT_EQ(*half(4.0), 2.0); }

TEST(Outcome, HoldsTheFailure) { EXPECT_EQ(half(-1.0).status().problem(), Problem::kOutOfRange); }

TEST(Outcome, AnOkOutcomesStatusIsOk) { EXPECT_TRUE(half(1.0).status().ok()); }

TEST(Outcome, BecomesAResultForTheGround) {
  const Result<double> r = half(-1.0);
  EXPECT_EQ(r.error().describe(), "x: must be >= 0");
}

TEST(Outcome, BecomesAResultWithItsValue) {
  const Result<double> r = half(3.0);
  EXPECT_EQ(r.value(), 1.5);
}

}  // namespace
