#pragma once
// A vector whose resize leaves new elements of a trivial type uninitialized, for arrays every
// element of which is written next (a million-sphere scene's candidate lists: tens of megabytes a
// plain vector would first fill with zeros, on one thread).

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace hexray::inline util {

template <typename T>
class DefaultInitAllocator : public std::allocator<T> {
public:
    template <typename U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };

    DefaultInitAllocator() = default;
    template <typename U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

    // resize(n) and the like construct with no arguments: default-initialization (none, for T trivial).
    template <typename U>
    void construct(U* place) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(place)) U;
    }
    template <typename U, typename... Arguments>
    void construct(U* place, Arguments&&... arguments) {
        std::allocator_traits<std::allocator<T>>::construct(*this, place, std::forward<Arguments>(arguments)...);
    }
};

template <typename T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace hexray::util
