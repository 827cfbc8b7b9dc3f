#pragma once
// Counts the heap allocations a piece of code makes. counting_malloc.cpp interposes glibc's
// malloc, calloc, realloc and the aligned forms in the test binary it is linked into, which
// catches operator new (libstdc++ allocates through malloc) and Eigen (which calls malloc
// directly) alike. The binary cannot run under AddressSanitizer, which interposes the same
// functions, so CMake builds it only without ANIMKIT_SANITIZE.
#include <cstddef>

namespace animkit::testing {

/// Allocations on this thread while it lives: `AllocationCount count; f(); count.value()`.
class AllocationCount {
 public:
  AllocationCount();
  ~AllocationCount();
  AllocationCount(const AllocationCount&) = delete;
  AllocationCount& operator=(const AllocationCount&) = delete;
  std::size_t value() const;

 private:
  std::size_t start_;
  bool was_counting_;
};

}  // namespace animkit::testing
