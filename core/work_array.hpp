// A solver's work array: a std::vector whose elements are left uninitialised when it is sized (default-
// initialised, not value-initialised: no zeros written), for arrays whose every element is written before it
// is read. std::vector<T>(n) writes n zeros on the allocating thread, which is where most of a large array's
// pages are first touched (a page fault each 4 KiB) and then written again by the solver's threads (issue 42:
// a 1024^2 active_set's arrays were zero-filled on one thread before every pass wrote them).
// Blocks of 8 MiB or more are aligned to 2 MiB and advised to use transparent huge pages (as LargeBuffer,
// core/large_buffer.hpp): one fault a 2 MiB page instead of 512; a hint only, all works without them.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/mman.h>

namespace contactbench {

template <class T>
class DefaultInitAllocator {
  static_assert(std::is_trivially_destructible_v<T>);

 public:
  using value_type = T;

  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    constexpr std::size_t kHugePage = std::size_t{2} << 20;
    const std::size_t bytes = n * sizeof(T);
    void* data = nullptr;
    if (bytes < 4 * kHugePage) {
      data = std::malloc(bytes == 0 ? 1 : bytes);
    } else {
      const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
      data = std::aligned_alloc(kHugePage, rounded);
      if (data) ::madvise(data, rounded, MADV_HUGEPAGE);
    }
    if (!data) throw std::bad_alloc();
    return static_cast<T*>(data);
  }
  void deallocate(T* data, std::size_t) noexcept { std::free(data); }

  // Default-initialisation: for the arithmetic types of the solvers, no write at all.
  template <class U>
  void construct(U* at) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(at)) U;
  }
  template <class U, class... Args>
  void construct(U* at, Args&&... args) {
    ::new (static_cast<void*>(at)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const DefaultInitAllocator<U>&) const noexcept {
    return true;
  }
};

// resize(n) / WorkArray<T>(n) leave the new elements unwritten; resize(n, value) and assign write them.
template <class T>
using WorkArray = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace contactbench
