// Vectors of millions of numbers (a design's columns, an analysis's ranks) that are neither
// zero-filled when created nor handed fresh memory every time: elements are default-initialized
// (left as they are, for numbers) and storage of 1 MiB or more comes from a process-wide pool
// of released blocks. Writing to fresh memory costs a page fault and the kernel's zeroing per
// page, and zero-filling a column that is overwritten at once costs another pass; for a 1e6
// sample design both together measured about a tenth of its time.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace growthuq {

namespace detail {

// Memory of at least `bytes`, from the pool when it holds a block of about that size (no more
// than a quarter larger), else from malloc. Blocks of 1 MiB or more that are released are kept,
// up to 64 blocks and 512 MiB in all (the oldest go first): about what one 1e6-sample line of a
// campaign uses at a time. (No transparent huge pages: on the 2-core test machine, their
// compaction on first touch made a campaign's designs 20-40 % slower, and the random accesses
// they would speed up measured no faster.) Thread-safe.
void* acquire_block(std::size_t bytes);
void release_block(void* block, std::size_t bytes) noexcept;
// Frees every kept block.
void release_cached_blocks() noexcept;

}  // namespace detail

template <class T>
class LargeAllocator {
 public:
  using value_type = T;

  LargeAllocator() noexcept = default;
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(detail::acquire_block(n * sizeof(T)));
  }
  void deallocate(T* memory, std::size_t n) noexcept { detail::release_block(memory, n * sizeof(T)); }

  // Default-initialization: a number is left as it is instead of being set to zero.
  template <class U>
  void construct(U* place) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(place)) U;
  }
  template <class U, class... Arguments>
  void construct(U* place, Arguments&&... arguments) {
    ::new (static_cast<void*>(place)) U(std::forward<Arguments>(arguments)...);
  }

  template <class U>
  bool operator==(const LargeAllocator<U>&) const noexcept {
    return true;
  }
};

// resize(n) leaves new numbers uninitialized; assign() and the like write them once.
template <class T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace growthuq
