// Counts every heap allocation of the test process: operator new (every form) and the C
// allocation functions (malloc, calloc, realloc, posix_memalign, aligned_alloc, memalign, valloc,
// pvalloc), because libraries such as OpenCV allocate with posix_memalign, not operator new.
//
// Two ways, chosen at compile time:
// - Plain builds (GCC or clang, native or aarch64 under qemu): this object file defines the C
//   functions itself. The dynamic linker binds every caller in the process (libstdc++, OpenCV,
//   glibc's own internal calls) to the executable's definition first; each counts and forwards to
//   glibc's allocator under its internal names (__libc_malloc...), which glibc exports for
//   exactly this, so there is no dlsym(RTLD_NEXT) and no bootstrapping problem (dlsym itself
//   calls calloc). The memory is glibc's, so glibc's free releases it.
// - AddressSanitizer / ThreadSanitizer builds: the sanitizer runtime owns malloc (its own
//   allocator, its interceptors); defining malloc here would bypass it and break its free. There
//   the sanitizer's allocation hook counts instead (__sanitizer_install_malloc_and_free_hooks):
//   ASan runs it on every allocation, operator new and every C function alike. TSan runs it for
//   malloc, calloc, realloc and operator new only, not for the aligned C functions
//   (posix_memalign, aligned_alloc, memalign, valloc, pvalloc): in TSan builds this file defines
//   those five, counts, and forwards to TSan's own implementation (__interceptor_<name>, which
//   the runtime's weak <name> aliases; a definition in the executable takes precedence).
#include "allocation_counter.hpp"

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define RINGLET_COUNT_WITH_SANITIZER_HOOK 1
#elif defined(__SANITIZE_THREAD__)
#define RINGLET_COUNT_WITH_SANITIZER_HOOK 1
#define RINGLET_TSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RINGLET_COUNT_WITH_SANITIZER_HOOK 1
#elif __has_feature(thread_sanitizer)
#define RINGLET_COUNT_WITH_SANITIZER_HOOK 1
#define RINGLET_TSAN 1
#endif
#endif

namespace {

std::atomic<std::uint64_t> g_allocations{0};
// Static TLS of the executable (a trivial type): reading it allocates nothing.
thread_local std::uint64_t t_allocations = 0;

void count() noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  ++t_allocations;
}

}  // namespace

namespace ringlet::test {
std::uint64_t allocations() noexcept { return g_allocations.load(std::memory_order_relaxed); }
std::uint64_t thread_allocations() noexcept { return t_allocations; }
}  // namespace ringlet::test

#ifdef RINGLET_COUNT_WITH_SANITIZER_HOOK

// sanitizer/allocator_interface.h (clang ships it, GCC does not): hooks called by the
// sanitizer's allocator; they must not allocate.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                          void (*free_hook)(const volatile void*));

namespace {

void on_malloc(const volatile void*, std::size_t) { count(); }
void on_free(const volatile void*) {}

// Installed before main(); allocations during static initialisation are not counted (no test
// runs then). If the runtime refused (it keeps a few hooks only), AllocationCounter.Counts* fail.
[[maybe_unused]] const int g_hook_slot = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);

#ifdef RINGLET_TSAN
extern "C" {
int __interceptor_posix_memalign(void** out, std::size_t align, std::size_t size);
void* __interceptor_aligned_alloc(std::size_t align, std::size_t size);
void* __interceptor_memalign(std::size_t align, std::size_t size);
void* __interceptor_valloc(std::size_t size);
void* __interceptor_pvalloc(std::size_t size);

int posix_memalign(void** out, std::size_t align, std::size_t size) noexcept {
  count();
  return __interceptor_posix_memalign(out, align, size);
}
void* aligned_alloc(std::size_t align, std::size_t size) noexcept {
  count();
  return __interceptor_aligned_alloc(align, size);
}
void* memalign(std::size_t align, std::size_t size) noexcept {
  count();
  return __interceptor_memalign(align, size);
}
void* valloc(std::size_t size) noexcept {
  count();
  return __interceptor_valloc(size);
}
void* pvalloc(std::size_t size) noexcept {
  count();
  return __interceptor_pvalloc(size);
}
}  // extern "C"
#endif

// operator new below allocates through malloc or posix_memalign, which are already counted.
void* raw_allocate(std::size_t size, std::size_t align) noexcept {
  if (align <= alignof(std::max_align_t)) return std::malloc(size);
  void* p = nullptr;
  return posix_memalign(&p, align, size) == 0 ? p : nullptr;
}

}  // namespace

#else  // interposition

// glibc's allocator under the names it exports for allocators that wrap it.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t align, std::size_t size);
void* __libc_valloc(std::size_t size);
void* __libc_pvalloc(std::size_t size);
}

namespace {

// operator new counts itself, so it takes glibc's memory directly (not through malloc below).
void* raw_allocate(std::size_t size, std::size_t align) noexcept {
  return align <= alignof(std::max_align_t) ? __libc_malloc(size) : __libc_memalign(align, size);
}

bool valid_alignment(std::size_t align) noexcept {
  return align != 0 && (align & (align - 1)) == 0 && align % sizeof(void*) == 0;
}

}  // namespace

// The C allocation functions, replacing glibc's for the whole process. Same contracts as glibc's
// (noexcept: glibc declares them so for C++).
extern "C" {

void* malloc(std::size_t size) noexcept {
  count();
  return __libc_malloc(size);
}

void* calloc(std::size_t n, std::size_t size) noexcept {
  count();
  return __libc_calloc(n, size);
}

void* realloc(void* p, std::size_t size) noexcept {
  count();
  return __libc_realloc(p, size);
}

int posix_memalign(void** out, std::size_t align, std::size_t size) noexcept {
  count();
  if (!valid_alignment(align)) return EINVAL;
  void* p = __libc_memalign(align, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}

void* aligned_alloc(std::size_t align, std::size_t size) noexcept {
  count();
  return __libc_memalign(align, size);
}

void* memalign(std::size_t align, std::size_t size) noexcept {
  count();
  return __libc_memalign(align, size);
}

void* valloc(std::size_t size) noexcept {
  count();
  return __libc_valloc(size);
}

void* pvalloc(std::size_t size) noexcept {
  count();
  return __libc_pvalloc(size);
}

}  // extern "C"

#endif

namespace {

void* counted_new(std::size_t size, std::size_t align) {
#ifndef RINGLET_COUNT_WITH_SANITIZER_HOOK
  count();
#endif
  void* p = raw_allocate(size == 0 ? 1 : size, align);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace

void* operator new(std::size_t size) { return counted_new(size, alignof(std::max_align_t)); }
void* operator new[](std::size_t size) { return counted_new(size, alignof(std::max_align_t)); }
void* operator new(std::size_t size, std::align_val_t align) { return counted_new(size, static_cast<std::size_t>(align)); }
void* operator new[](std::size_t size, std::align_val_t align) { return counted_new(size, static_cast<std::size_t>(align)); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
