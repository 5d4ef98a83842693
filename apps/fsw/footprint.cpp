#include "footprint.hpp"

#include <cstdio>
#include <cstring>

#include <malloc.h>

namespace visors::fsw {
namespace {

constexpr std::uint8_t kPattern = 0xA5;

// Fills kPaintedBytes of stack below its own frame with the pattern; returns their lowest address.
// Not inlined, so its array lies below the caller's frame.
[[gnu::noinline]] std::uintptr_t paint_below() {
  volatile std::uint8_t area[kPaintedBytes];
  for (std::size_t i = 0; i < kPaintedBytes; ++i) area[i] = kPattern;
  return reinterpret_cast<std::uintptr_t>(&area[0]);
}

}  // namespace

std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

std::size_t peak_resident() {
  std::FILE* status = std::fopen("/proc/self/status", "r");
  if (status == nullptr) return 0;
  char line[256];
  std::size_t kib = 0;
  while (std::fgets(line, sizeof line, status) != nullptr) {
    if (std::strncmp(line, "VmHWM:", 6) == 0) {
      unsigned long long value = 0;
      if (std::sscanf(line + 6, "%llu", &value) == 1) kib = static_cast<std::size_t>(value);
    }
  }
  std::fclose(status);
  return kib * 1024;
}

void StackGauge::paint(const void* top) {
  top_ = reinterpret_cast<std::uintptr_t>(top);
  bottom_ = paint_below();
}

std::size_t StackGauge::high_water() const {
  const auto* byte = reinterpret_cast<const volatile std::uint8_t*>(bottom_);
  std::size_t untouched = 0;
  while (untouched < kPaintedBytes && byte[untouched] == kPattern) ++untouched;
  const std::uintptr_t deepest = bottom_ + untouched;
  return deepest < top_ ? top_ - deepest : 0;
}

}  // namespace visors::fsw
