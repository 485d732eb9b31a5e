// Uninitialized scratch buffers of millions of elements for the sampling core and the analyses,
// from the pool of large blocks of growthuq/core/large_vector.hpp (reused from one piece of work
// to the next).
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "growthuq/core/large_vector.hpp"

namespace growthuq::detail {

// n uninitialized elements of a trivial type, from the pool of large blocks.
template <class T>
class LargeBuffer {
 public:
  explicit LargeBuffer(std::size_t n) : size_(n) {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
    data_ = static_cast<T*>(acquire_block(n * sizeof(T)));
  }
  LargeBuffer(const LargeBuffer&) = delete;
  LargeBuffer& operator=(const LargeBuffer&) = delete;
  LargeBuffer(LargeBuffer&& other) noexcept : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
  LargeBuffer& operator=(LargeBuffer&& other) noexcept {
    if (this != &other) {
      release_block(data_, size_ * sizeof(T));
      data_ = std::exchange(other.data_, nullptr);
      size_ = std::exchange(other.size_, 0);
    }
    return *this;
  }
  ~LargeBuffer() { release_block(data_, size_ * sizeof(T)); }

  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  std::size_t size() const { return size_; }

 private:
  T* data_;
  std::size_t size_;
};

}  // namespace growthuq::detail
