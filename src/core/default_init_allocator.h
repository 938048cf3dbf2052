// An allocator whose vectors leave new elements default-initialized (not zeroed) on resize.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace ewa {

// For large arrays that a parallel pass fills in whole: std::vector's resize would zero them on
// one thread first (touching every page there), this leaves the first touch to the pass.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace ewa
