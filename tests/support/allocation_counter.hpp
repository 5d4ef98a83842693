#pragma once
// Counts every heap allocation of a test executable, so a test can prove that a flight-code step
// allocates nothing (CONTRIBUTING "Memory"). Include this header in exactly ONE source file per
// test executable: it defines the C allocation functions themselves.
//
// Why at the C level: Eigen's dynamic matrices allocate with malloc (or posix_memalign), never with
// operator new, so a counter of operator new alone misses them (an outside review found three
// allocations per conic solve that way). The executable's own malloc/calloc/realloc/aligned_alloc/
// posix_memalign/memalign/valloc/pvalloc interpose glibc's for the whole process (libstdc++'s
// operator new calls malloc, so it is counted too, exactly once) and forward to glibc's exported
// __libc_* implementations. A control test in every executable that includes this file proves an
// Eigen dynamic matrix and a `new` are both counted.

#include <atomic>
#include <cerrno>
#include <cstddef>

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* p);
}

namespace visors::test {

inline std::atomic<long> g_allocations{0};
inline std::atomic<bool> g_counting_allocations{false};

inline void note_allocation() {
  if (g_counting_allocations.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}

/// Number of heap allocations (any C or C++ allocation function, reallocations included) made
/// while calling `f()`.
template <typename F>
long count_allocations(F&& f) {
  g_allocations = 0;
  g_counting_allocations = true;
  f();
  g_counting_allocations = false;
  return g_allocations.load();
}

}  // namespace visors::test

extern "C" {

void* malloc(std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_realloc(p, size);
}
void free(void* p) noexcept { __libc_free(p); }
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  visors::test::note_allocation();
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr && size != 0) return ENOMEM;
  *out = p;
  return 0;
}
void* valloc(std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_memalign(4096, size);
}
void* pvalloc(std::size_t size) noexcept {
  visors::test::note_allocation();
  return __libc_memalign(4096, (size + 4095) & ~static_cast<std::size_t>(4095));
}

}  // extern "C"

// The control test, in every executable that counts: the counter must see an Eigen dynamic matrix
// (malloc, possibly aligned) and a plain `new`; if either is missed every "allocates nothing"
// test of the executable is blind.
#include <gtest/gtest.h>

#include <Eigen/Core>

TEST(AllocationCounter, SeesEigenDynamicMatrix) {
  double sum = 0.0;
  const long allocations = visors::test::count_allocations([&] {
    Eigen::MatrixXd m = Eigen::MatrixXd::Constant(50, 50, 1.0);
    sum = m.sum();
  });
  EXPECT_EQ(sum, 2500.0);
  EXPECT_EQ(allocations, 1);
}

// The pointer goes through a volatile, so the compiler cannot elide the new/delete pair.
TEST(AllocationCounter, SeesOperatorNew) {
  static int* volatile sink = nullptr;
  const long allocations = visors::test::count_allocations([&] { sink = new int(7); });
  EXPECT_EQ(*sink, 7);
  delete sink;
  EXPECT_EQ(allocations, 1);
}
