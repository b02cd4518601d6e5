// An uninitialised array for large scratch data that is accessed at random (union-find parents, labels):
// aligned to 2 MiB and advised to use transparent huge pages, so that random access over tens of
// megabytes does not miss the TLB on nearly every load (4 KiB pages cover 2 MiB of a 1,500-entry TLB;
// 2 MiB pages cover all of it).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>

#include <sys/mman.h>

namespace contactbench {

template <typename T>
class LargeBuffer {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  LargeBuffer() = default;
  explicit LargeBuffer(std::size_t size) { resize(size); }
  ~LargeBuffer() { std::free(data_); }
  LargeBuffer(const LargeBuffer&) = delete;
  LargeBuffer& operator=(const LargeBuffer&) = delete;

  // Makes room for `size` elements; the contents are undefined afterwards unless the size did not grow.
  void resize(std::size_t size) {
    if (size <= capacity_) {
      size_ = size;
      return;
    }
    std::free(data_);
    constexpr std::size_t kHugePage = std::size_t{2} << 20;
    const std::size_t bytes = size * sizeof(T);
    if (bytes < 4 * kHugePage) {
      // Small arrays fit the TLB anyway; a huge page would only cost 2 MiB of zeroing per allocation.
      data_ = static_cast<T*>(std::malloc(std::max<std::size_t>(bytes, 1)));
    } else {
      const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
      data_ = static_cast<T*>(std::aligned_alloc(kHugePage, rounded));
      if (data_) ::madvise(data_, rounded, MADV_HUGEPAGE);  // a hint: without huge pages all still works
    }
    if (!data_) throw std::bad_alloc();
    size_ = capacity_ = size;
  }

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0, capacity_ = 0;
};

}  // namespace contactbench
