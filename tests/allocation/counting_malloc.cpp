#include "counting_malloc.h"

#include <cerrno>
#include <cstdlib>

// glibc's own entry points, which the interposed functions below forward to.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
}

namespace {

// Plain integers with static storage: touching them allocates nothing, so counting cannot
// recurse.
thread_local std::size_t allocations = 0;
thread_local bool counting = false;

void count() {
  if (counting) ++allocations;
}

}  // namespace

namespace animkit::testing {

AllocationCount::AllocationCount() : start_(allocations), was_counting_(counting) {
  counting = true;
}
AllocationCount::~AllocationCount() {
  counting = was_counting_;
}
std::size_t AllocationCount::value() const {
  return allocations - start_;
}

}  // namespace animkit::testing

extern "C" {
void* malloc(std::size_t size) {
  count();
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  count();
  return __libc_realloc(p, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  count();
  if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}
}
