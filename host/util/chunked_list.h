#pragma once
// Values appended one by one when their number is not known in advance (a scene file's nodes and
// lights), then taken as one vector of just their number. A vector grown the usual way holds its
// values twice while it moves them and may end with twice the room they need; here they go into
// chunks that never move, growing to kMaxChunkBytes, and the chunks are let go as the vector is
// filled. Chunks that large are mapped on their own by the C library, so letting one go returns
// its memory to the system at once: the values are never held twice.

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace hexray::inline util {

template <typename T>
class ChunkedList {
public:
    // Above glibc's largest threshold for allocating by mmap of its own.
    static constexpr std::size_t kMaxChunkBytes = std::size_t{32} << 20;

    void push_back(T value) {
        if (chunks_.empty() || chunks_.back().size() == chunks_.back().capacity()) {
            const std::size_t previous = chunks_.empty() ? 0 : chunks_.back().capacity();
            chunks_.emplace_back().reserve(std::clamp(2 * previous, kFirstChunk, kMaxChunk));
        }
        chunks_.back().push_back(std::move(value));
        ++size_;
    }

    std::size_t size() const { return size_; }

    // Every value, in order, moved out; the list is left empty.
    std::vector<T> take() && {
        std::vector<T> values;
        values.reserve(size_);
        for (std::vector<T>& chunk : chunks_) {
            std::move(chunk.begin(), chunk.end(), std::back_inserter(values));
            std::vector<T>().swap(chunk);
        }
        chunks_.clear();
        size_ = 0;
        return values;
    }

private:
    static constexpr std::size_t kFirstChunk = std::max<std::size_t>(1, 4096 / sizeof(T));
    static constexpr std::size_t kMaxChunk = std::max<std::size_t>(1, kMaxChunkBytes / sizeof(T));

    std::vector<std::vector<T>> chunks_;
    std::size_t size_ = 0;
};

}  // namespace hexray::util
