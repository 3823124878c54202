#pragma once
// A vector whose resize leaves new elements of a trivial type uninitialized, for arrays every
// element of which is written next (a million-sphere scene's candidate lists: tens of megabytes a
// plain vector would first fill with zeros, on one thread). Its storage starts on a page and spans
// whole pages, so that a Vulkan device on the host's memory can import it as it is
// (VK_EXT_external_memory_host) rather than hold a copy.

#include <cstddef>
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

    static constexpr std::size_t kPageBytes = 4096;

    DefaultInitAllocator() = default;
    template <typename U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

    T* allocate(std::size_t count) {
        return static_cast<T*>(::operator new (pagesFor(count), std::align_val_t{kPageBytes}));
    }
    void deallocate(T* storage, std::size_t /*count*/) noexcept {
        ::operator delete (storage, std::align_val_t{kPageBytes});
    }

    // resize(n) and the like construct with no arguments: default-initialization (none, for T trivial).
    template <typename U>
    void construct(U* place) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(place)) U;
    }
    template <typename U, typename... Arguments>
    void construct(U* place, Arguments&&... arguments) {
        std::allocator_traits<std::allocator<T>>::construct(*this, place, std::forward<Arguments>(arguments)...);
    }

private:
    static std::size_t pagesFor(std::size_t count) {
        return (count * sizeof(T) + kPageBytes - 1) / kPageBytes * kPageBytes;
    }
};

template <typename T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace hexray::util
