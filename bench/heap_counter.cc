#include "bench/heap_counter.h"

#include <malloc.h>

#include <atomic>
#include <cerrno>
#include <cstring>

// glibc's own allocator, under the names it exports for this purpose: the functions below
// interpose malloc and friends for the whole process (operator new, Eigen, Ceres all use them).
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {

std::atomic<std::size_t> g_in_use{0}, g_peak{0};

void* Counted(void* p) {
  if (p == nullptr) return p;
  const std::size_t size = malloc_usable_size(p);
  const std::size_t now = g_in_use.fetch_add(size, std::memory_order_relaxed) + size;
  std::size_t peak = g_peak.load(std::memory_order_relaxed);
  while (now > peak && !g_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
  return p;
}

void Uncount(void* p) {
  if (p != nullptr) g_in_use.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
}

}  // namespace

extern "C" {
void* malloc(std::size_t n) { return Counted(__libc_malloc(n)); }
void* calloc(std::size_t n, std::size_t size) { return Counted(__libc_calloc(n, size)); }
void* realloc(void* p, std::size_t n) {
  Uncount(p);
  void* q = __libc_realloc(p, n);
  if (q == nullptr && p != nullptr && n != 0) {
    Counted(p);  // the old block is still there
    return nullptr;
  }
  return Counted(q);
}
void free(void* p) {
  Uncount(p);
  __libc_free(p);
}
void* memalign(std::size_t alignment, std::size_t n) {
  return Counted(__libc_memalign(alignment, n));
}
void* aligned_alloc(std::size_t alignment, std::size_t n) { return memalign(alignment, n); }
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  void* p = memalign(alignment, n);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}

namespace usvid::bench {

std::size_t HeapInUse() { return g_in_use.load(); }
std::size_t HeapPeak() { return g_peak.load(); }
void ResetHeapPeak() { g_peak.store(g_in_use.load()); }

}  // namespace usvid::bench
