#include "visors/sim/paired_worker.hpp"

#include <utility>

namespace visors::sim {
namespace {

// Polls before blocking, a few microseconds (a pause is ~40-140 cycles): the two components'
// steps last ~100-200 us each and usually end within microseconds of each other, and a futex
// sleep and wake-up costs about that much. Not longer: on a host with other work (ctest -j2, a
// Monte Carlo campaign) a long spin takes a core from it.
constexpr int kSpins = 100;

// Waits until `state` differs from `value`, spinning first; returns the new value.
int wait_while(const std::atomic<int>& state, int value) {
  for (int i = 0; i < kSpins; ++i) {
    const int now = state.load(std::memory_order_acquire);
    if (now != value) return now;
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();  // lets the other hyper-thread run while this one polls
#endif
  }
  for (;;) {
    state.wait(value, std::memory_order_acquire);
    const int now = state.load(std::memory_order_acquire);
    if (now != value) return now;
  }
}

}  // namespace

PairedWorker::PairedWorker(bool parallel) {
  if (parallel && std::thread::hardware_concurrency() >= 2) worker_ = std::thread([this] { loop(); });
}

PairedWorker::~PairedWorker() {
  if (!worker_.joinable()) return;
  state_.store(kStop, std::memory_order_release);
  state_.notify_one();
  worker_.join();
}

void PairedWorker::hand_over() {
  state_.store(kWork, std::memory_order_release);
  state_.notify_one();
}

void PairedWorker::wait_done() {
  (void)wait_while(state_, kWork);
  state_.store(kIdle, std::memory_order_relaxed);
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void PairedWorker::loop() {
  for (int state = kIdle;;) {
    state = wait_while(state_, state);
    if (state == kStop) return;
    if (state != kWork) continue;  // kIdle after the caller collected the previous job
    try {
      job_(job_argument_);
    } catch (...) {
      failure_ = std::current_exception();
    }
    state_.store(kDone, std::memory_order_release);
    state_.notify_one();
    state = kDone;
  }
}

}  // namespace visors::sim
