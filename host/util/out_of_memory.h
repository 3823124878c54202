#pragma once
// Running out of memory, said in terms of what was too big: the scene (its spheres and lights, and
// how much they need) or the image, so that the message can say what to reduce.

#include <new>
#include <string>
#include <utility>

namespace hexray::inline util {

class OutOfMemory : public std::bad_alloc {
public:
    // `what`: what could not be held, e.g. "the scene's 1000000 spheres and 2 lights in the GPU's
    // buffers (about 250 MiB)".
    explicit OutOfMemory(std::string what) : what_(std::move(what)) {}
    const char* what() const noexcept override { return what_.c_str(); }

private:
    std::string what_;
};

// work(), with running out of memory in it reported as `describe()` being too big (unless a step
// inside already said what was).
template <typename Describe, typename Work>
decltype(auto) holding(const Describe& describe, Work&& work) {
    try {
        return work();
    } catch (const OutOfMemory&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw OutOfMemory(describe());
    }
}

}  // namespace hexray::util
