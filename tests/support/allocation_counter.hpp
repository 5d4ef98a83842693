#pragma once
// Replaces the global operator new/delete of a test executable with counting versions, so a test
// can prove that a flight-code step allocates nothing (CONTRIBUTING "Memory"). Include this header
// in exactly ONE source file per test executable (the replacements are ordinary definitions).

#include <atomic>
#include <cstdlib>
#include <new>

namespace visors::test {

inline std::atomic<long> g_allocations{0};
inline std::atomic<bool> g_counting_allocations{false};

/// Number of heap allocations made while calling `f()`.
template <typename F>
long count_allocations(F&& f) {
  g_allocations = 0;
  g_counting_allocations = true;
  f();
  g_counting_allocations = false;
  return g_allocations.load();
}

}  // namespace visors::test

void* operator new(std::size_t size) {
  if (visors::test::g_counting_allocations.load()) ++visors::test::g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return ::operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (visors::test::g_counting_allocations.load()) ++visors::test::g_allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return ::operator new(size, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
