// Uninitialized buffers of millions of elements for the sampling core, backed by 2 MiB pages
// where the kernel allows (Linux transparent huge pages on request, madvise(MADV_HUGEPAGE)).
// The design's gathers, scatters and shuffle touch random elements of 4-32 MB arrays; with 4 KiB
// pages most such accesses also miss the TLB (a random gather from an 8 MB table, measured on a
// loaded 2-core machine: 10-17 ns per element with 4 KiB pages, 3-13 ns with 2 MiB pages).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace growthuq::detail {

inline constexpr std::size_t huge_page_bytes = std::size_t{1} << 21;

// Asks for huge pages over the whole 2 MiB pages inside [data, data + bytes); call it before the
// memory is first touched. Only a hint: without transparent huge pages nothing changes.
inline void advise_huge_pages([[maybe_unused]] void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + huge_page_bytes - 1) & ~(huge_page_bytes - 1);
  const std::uintptr_t last = (begin + bytes) & ~(huge_page_bytes - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

// A std::vector of n value-initialized elements whose storage was advised before it was touched.
template <class T>
void resize_large(std::vector<T>& vector, std::size_t n) {
  vector.clear();
  vector.reserve(n);
  advise_huge_pages(vector.data(), n * sizeof(T));
  vector.resize(n);
}

// n uninitialized elements of a trivial type. Plain malloc (not 2 MiB-aligned allocation), so
// the C library can hand back memory a previous design freed, already mapped: fresh pages cost a
// fault and the kernel's zeroing each, which measured as much as the gathers they speed up.
template <class T>
class LargeBuffer {
 public:
  explicit LargeBuffer(std::size_t n) : size_(n) {
    void* memory = std::malloc(std::max<std::size_t>(n * sizeof(T), 1));
    if (memory == nullptr) throw std::bad_alloc();
    advise_huge_pages(memory, n * sizeof(T));
    data_.reset(static_cast<T*>(memory));
  }
  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  std::size_t size() const { return size_; }

 private:
  struct Free {
    void operator()(T* memory) const { std::free(memory); }
  };
  std::unique_ptr<T[], Free> data_;
  std::size_t size_;
};

}  // namespace growthuq::detail
