// The allocation counter sees every way of allocating: operator new and each C allocation
// function, and allocations glibc makes for a caller (strdup). Each call is made through a
// volatile function pointer, so the compiler can neither tell which function runs nor drop an
// allocation whose memory is never used.
#include <gtest/gtest.h>

#include <malloc.h>  // memalign, valloc, pvalloc

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

#include "allocation_counter.hpp"

namespace ringlet::test {
namespace {

template <class F>
F opaque(F f) {
  volatile F v = f;
  return v;
}

TEST(AllocationCounter, CountsOperatorNewOnce) {
  AllocationCounter counter;
  void* p = opaque<void* (*)(std::size_t)>(&::operator new)(40);
  const std::uint64_t n = counter.count();
  ::operator delete(p);
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsAlignedOperatorNewOnce) {
  AllocationCounter counter;
  void* p = opaque<void* (*)(std::size_t, std::align_val_t)>(&::operator new)(40, std::align_val_t{64});
  const std::uint64_t n = counter.count();
  ::operator delete(p, std::align_val_t{64});
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsMalloc) {
  AllocationCounter counter;
  void* p = opaque(&std::malloc)(24);
  const std::uint64_t n = counter.count();
  std::free(p);
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsCalloc) {
  AllocationCounter counter;
  void* p = opaque(&std::calloc)(3, 8);
  const std::uint64_t n = counter.count();
  std::free(p);
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsRealloc) {
  void* p = std::malloc(8);
  ASSERT_NE(p, nullptr);
  AllocationCounter counter;
  void* q = opaque(&std::realloc)(p, 4096);
  const std::uint64_t n = counter.count();
  std::free(q != nullptr ? q : p);
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsPosixMemalign) {
  AllocationCounter counter;
  void* p = nullptr;
  const int rc = opaque(&posix_memalign)(&p, 64, 100);
  const std::uint64_t n = counter.count();
  std::free(p);
  EXPECT_EQ(rc, 0);
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsAlignedAlloc) {
  AllocationCounter counter;
  void* p = opaque(&std::aligned_alloc)(64, 128);
  const std::uint64_t n = counter.count();
  std::free(p);
  EXPECT_EQ(n, 1U);
}

TEST(AllocationCounter, CountsMemalignVallocPvalloc) {
  AllocationCounter counter;
  void* a = opaque(&memalign)(32, 10);
  void* b = opaque(&valloc)(10);
  void* c = opaque(&pvalloc)(10);
  const std::uint64_t n = counter.count();
  std::free(a);
  std::free(b);
  std::free(c);
  EXPECT_EQ(n, 3U);
}

TEST(AllocationCounter, CountsWhatTheCLibraryAllocatesForTheCaller) {
  AllocationCounter counter;
  char* copy = opaque(&strdup)("whiteboard");
  const std::uint64_t n = counter.count();
  ASSERT_NE(copy, nullptr);
  EXPECT_STREQ(copy, "whiteboard");
  std::free(copy);
  EXPECT_GE(n, 1U);
}

TEST(AllocationCounter, FreeingIsNotAnAllocation) {
  void* p = std::malloc(16);
  AllocationCounter counter;
  opaque(&std::free)(p);
  EXPECT_EQ(counter.count(), 0U);
}

}  // namespace
}  // namespace ringlet::test
