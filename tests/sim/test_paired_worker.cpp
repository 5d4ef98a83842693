// sim/paired_worker: both jobs run, the second on the worker thread when parallel, in order on the
// calling thread otherwise; an exception of the second job reaches the caller; many hand-offs in
// a row lose none.
#include "visors/sim/paired_worker.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

namespace visors::sim {
namespace {

bool two_cores() { return std::thread::hardware_concurrency() >= 2; }

TEST(PairedWorker, RunsBothJobs) {
  PairedWorker worker(true);
  int a = 0, b = 0;
  worker.run([&] { a = 1; }, [&] { b = 2; });
  EXPECT_EQ(a + b, 3);
}

TEST(PairedWorker, RunsTheSecondJobOnAnotherThreadWhenParallel) {
  if (!two_cores()) GTEST_SKIP() << "one core: no worker thread is started";
  PairedWorker worker(true);
  std::thread::id second;
  worker.run([] {}, [&] { second = std::this_thread::get_id(); });
  EXPECT_NE(second, std::this_thread::get_id());
}

TEST(PairedWorker, RunsBothJobsInOrderOnTheCallerWhenNotParallel) {
  PairedWorker worker(false);
  std::thread::id second;
  int order = 0, first_at = -1, second_at = -1;
  worker.run([&] { first_at = order++; }, [&] { second_at = order++, second = std::this_thread::get_id(); });
  EXPECT_EQ(second, std::this_thread::get_id());
  EXPECT_LT(first_at, second_at);
}

TEST(PairedWorker, RethrowsWhatTheSecondJobThrew) {
  PairedWorker worker(true);
  EXPECT_THROW(worker.run([] {}, [] { throw std::runtime_error("second"); }), std::runtime_error);
}

TEST(PairedWorker, KeepsWorkingAfterAnException) {
  PairedWorker worker(true);
  EXPECT_THROW(worker.run([] {}, [] { throw std::runtime_error("second"); }), std::runtime_error);
  int b = 0;
  worker.run([] {}, [&] { b = 1; });
  EXPECT_EQ(b, 1);
}

// 20,000 hand-offs, each job's effect seen by the caller after run() returns (a lost wake-up
// would hang; a missing barrier would lose increments).
TEST(PairedWorker, ManyHandOffsLoseNothing) {
  PairedWorker worker(true);
  long a = 0, b = 0;
  for (int i = 0; i < 20000; ++i) worker.run([&] { ++a; }, [&] { b += 2; });
  EXPECT_EQ(a, 20000);
  EXPECT_EQ(b, 40000);
}

}  // namespace
}  // namespace visors::sim
