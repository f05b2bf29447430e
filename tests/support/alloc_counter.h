#pragma once
// Counts heap allocations made on threads that ask for it: replaces operator new and, outside sanitizer
// builds, malloc/calloc/realloc. Include it in exactly one file of a test binary (it defines the global
// replacements). Set t_counting on the thread under test; read g_allocations.
#include <atomic>
#include <cstdlib>
#include <new>

namespace {
thread_local bool t_counting = false;
std::atomic<long> g_allocations{0};
void noteAllocation() {
  if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
extern "C" void* __libc_malloc(size_t);
extern "C" void* __libc_calloc(size_t, size_t);
extern "C" void* __libc_realloc(void*, size_t);
extern "C" void* malloc(size_t n) {
  noteAllocation();
  return __libc_malloc(n);
}
extern "C" void* calloc(size_t n, size_t m) {
  noteAllocation();
  return __libc_calloc(n, m);
}
extern "C" void* realloc(void* p, size_t n) {
  noteAllocation();
  return __libc_realloc(p, n);
}
#endif

// Every allocation below goes through malloc, so free is the matching release; GCC 12 cannot see that
// when it inlines a sized delete into a caller and warns (-Wmismatched-new-delete, an error here).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  noteAllocation();
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  noteAllocation();
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

