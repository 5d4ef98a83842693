#pragma once
// Two jobs of one simulation step run side by side: the calling thread runs the first while a
// persistent worker thread runs the second (the two spacecraft's flight components, which share
// no mutable state: each owns its filter, models and Earth frame). Ground side only; the flight
// code knows nothing of it.
//
// Hand-off: an atomic flag the worker waits on (C++20 atomic wait, a futex on Linux) after a
// short spin, so a step's hand-off costs well under a microsecond when the worker is awake and a
// few microseconds when it slept; nothing is allocated per step. An exception thrown by the second
// job is carried back and rethrown by run() in the calling thread.
//
// Without a worker (created with parallel = false, or a single-core host) run() calls both jobs in
// order on the calling thread: the results are the same bit for bit either way, since the jobs
// are independent.

#include <atomic>
#include <exception>
#include <thread>
#include <type_traits>

namespace visors::sim {

class PairedWorker {
 public:
  explicit PairedWorker(bool parallel);
  ~PairedWorker();
  PairedWorker(const PairedWorker&) = delete;
  PairedWorker& operator=(const PairedWorker&) = delete;

  [[nodiscard]] bool parallel() const { return worker_.joinable(); }

  /// Runs first() here and second() on the worker; returns when both are done. Rethrows what
  /// second() threw (after first() finished).
  template <class First, class Second>
  void run(First&& first, Second&& second) {
    if (!parallel()) {
      first();
      second();
      return;
    }
    using Job = std::remove_reference_t<Second>;
    job_ = [](void* job) { (*static_cast<Job*>(job))(); };
    job_argument_ = &second;
    hand_over();
    first();
    wait_done();
  }

 private:
  enum State : int { kIdle, kWork, kDone, kStop };
  void hand_over();
  void wait_done();
  void loop();

  void (*job_)(void*) = nullptr;
  void* job_argument_ = nullptr;
  std::exception_ptr failure_;
  std::atomic<int> state_{kIdle};
  std::thread worker_;
};

}  // namespace visors::sim
