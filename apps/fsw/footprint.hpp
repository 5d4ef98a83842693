#pragma once
// What the flight software process occupies (docs/flight-software-process.md#footprint): the heap
// in use once the component is created, the peak resident memory, and the deepest the stack went
// while it served its steps. Linux and glibc (mallinfo2, /proc/self/status), as on the targets.
//
// The stack is measured by painting: before the steps, a region below the caller's frame is
// filled with a pattern; afterwards the lowest byte that no longer holds it is as deep as any call
// reached. The region (kPaintedBytes) must be deeper than a step goes: a high-water mark equal to
// it says so (the measurement is then a lower bound).

#include <cstddef>
#include <cstdint>

namespace visors::fsw {

inline constexpr std::size_t kPaintedBytes = 512 * 1024;  // [bytes], below the default 8 MiB stack

struct Footprint {
  std::size_t heap_after_creation = 0;  // [bytes] in use (malloc'd and mmap'd), once created
  std::size_t heap_at_end = 0;          // [bytes] in use when the steps are done
  std::size_t peak_resident = 0;        // [bytes] VmHWM: the process's peak resident set
  std::size_t stack_high_water = 0;     // [bytes] below `top` (StackGauge)
};

/// Heap bytes in use now.
std::size_t heap_in_use();
/// The process's peak resident set [bytes] (0 when /proc is not there).
std::size_t peak_resident();

/// Stack painting between paint() and high_water(), both called from the same frame (`top`: the
/// address of a local of that frame).
class StackGauge {
 public:
  void paint(const void* top);
  [[nodiscard]] std::size_t high_water() const;

 private:
  std::uintptr_t top_ = 0, bottom_ = 0;  // the frame's local, the painted region's lowest byte
};

}  // namespace visors::fsw
