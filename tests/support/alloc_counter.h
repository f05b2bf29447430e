#pragma once
// Counts heap allocations made on threads that ask for it: replaces operator new and, outside sanitizer
// builds, malloc/calloc/realloc and the aligned allocators (posix_memalign, aligned_alloc, memalign:
// cv::Mat's buffers come from posix_memalign). Each allocation is counted once: operator new counts only
// where malloc is not replaced. Include it in exactly one file of a test binary (it defines the global
// replacements). Count with a Counting object on the thread under test, or set t_counting and read
// g_allocations. Allocations made on threads a library starts itself (OpenCV's parallel_for_) are not seen.
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <new>

namespace {
thread_local bool t_counting = false;
std::atomic<long> g_allocations{0};
void noteAllocation() {
  if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
}

// Counts the allocations the current thread makes while it lives (t_counting on), e.g. per stereo pair.
class Counting {
 public:
  Counting() : start_(g_allocations.load()) { t_counting = true; }
  ~Counting() { t_counting = false; }
  Counting(const Counting&) = delete;
  Counting& operator=(const Counting&) = delete;
  long count() const { return g_allocations.load() - start_; }

 private:
  long start_;
};
}  // namespace

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
namespace {
constexpr bool kMallocCounted = true;
}  // namespace
extern "C" void* __libc_malloc(size_t);
extern "C" void* __libc_calloc(size_t, size_t);
extern "C" void* __libc_realloc(void*, size_t);
extern "C" void* __libc_memalign(size_t, size_t);
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
// posix_memalign's contract: alignment a power of two and a multiple of sizeof(void*), else EINVAL.
extern "C" int posix_memalign(void** out, size_t alignment, size_t n) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  noteAllocation();
  void* p = __libc_memalign(alignment, n);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
extern "C" void* aligned_alloc(size_t alignment, size_t n) {
  noteAllocation();
  return __libc_memalign(alignment, n);
}
extern "C" void* memalign(size_t alignment, size_t n) {
  noteAllocation();
  return __libc_memalign(alignment, n);
}
#else
namespace {
constexpr bool kMallocCounted = false;  // the sanitizer owns malloc: count at operator new
}  // namespace
#endif

// Every allocation below goes through malloc, so free is the matching release; GCC 12 cannot see that
// when it inlines a sized delete into a caller and warns (-Wmismatched-new-delete, an error here).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  if (!kMallocCounted) noteAllocation();
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  if (!kMallocCounted) noteAllocation();
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

