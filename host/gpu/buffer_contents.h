#pragma once
// What a buffer receives, written straight into its mapped memory: a large scene's packed nodes and
// sphere records are made there, not in a host vector copied over (which would hold them twice).

#include <cstddef>
#include <cstring>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace hexray::inline gpu {

class BufferContents {
public:
    BufferContents() = default;
    // `size` bytes, which `write` writes to where it is given.
    BufferContents(std::size_t size, std::function<void(std::byte*)> write) : size_(size), write_(std::move(write)) {}

    // A vector's bytes, held until released.
    template <typename T>
    static BufferContents of(std::vector<T> values) {
        auto held = std::make_shared<const std::vector<T>>(std::move(values));
        const std::size_t size = held->size() * sizeof(T);
        return {size, [held, size](std::byte* out) { std::memcpy(out, held->data(), size); }};
    }

    std::size_t size() const { return size_; }
    void writeTo(std::byte* out) const {
        if (size_ != 0) {
            write_(out);
        }
    }
    // Frees what it holds, once written.
    void release() { *this = BufferContents(); }

private:
    std::size_t size_ = 0;
    std::function<void(std::byte*)> write_;
};

}  // namespace hexray::gpu
