#pragma once
// Work split into parts, one thread per part (the caller's among them).

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace hexray::inline util {

// How many threads runParts has started in this process: what the tests count, since work split
// by something that grows with the input (a thread per light) would show there.
inline std::atomic<std::uint64_t>& partThreadsStarted() {
    static std::atomic<std::uint64_t> started{0};
    return started;
}

// Runs part(i) for every i in [0, parts), each on a thread of its own; parts whose thread cannot
// start run on the caller's. Rethrows the first exception a part threw, once all have finished.
inline void runParts(unsigned parts, const std::function<void(unsigned)>& part) {
    std::exception_ptr failure;
    std::mutex failureMutex;
    const auto guarded = [&](unsigned index) {
        try {
            part(index);
        } catch (...) {
            const std::lock_guard lock(failureMutex);
            if (!failure) {
                failure = std::current_exception();
            }
        }
    };
    {
        std::vector<unsigned> leftOver;
        std::vector<std::jthread> helpers;
        for (unsigned index = 1; index < parts; ++index) {
            try {
                helpers.emplace_back(guarded, index);
                ++partThreadsStarted();
            } catch (const std::system_error&) {
                leftOver.push_back(index);
            }
        }
        guarded(0);
        for (const unsigned index : leftOver) {
            guarded(index);
        }
    }
    if (failure) {
        std::rethrow_exception(failure);
    }
}

// Where part `part` of `parts` equal parts of [0, count) begins (part == parts: count).
inline std::size_t partBegin(std::size_t count, unsigned parts, unsigned part) {
    return count * part / parts;
}

// The number of threads to use: `requested`, or one per core for 0.
inline unsigned threadsFor(unsigned requested) {
    return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

// Walks over a scene's nodes (a few dozen operations a node) split across cores in parts of at
// least this many: a smaller part costs less on one thread than starting one.
inline constexpr std::size_t kNodesPerPart = std::size_t{1} << 16;

// How many parts runAcrossCores splits `count` items into: one per thread (threadsFor), each of at
// least `leastPerPart` items (for a little work, starting a thread costs more than it saves).
inline unsigned partsAcrossCores(std::size_t count, std::size_t leastPerPart, unsigned threads = 0) {
    return unsigned(std::clamp<std::size_t>(count / std::max<std::size_t>(leastPerPart, 1), 1, threadsFor(threads)));
}

// Runs work(first, end) over [0, count) split into equal parts (partsAcrossCores).
inline void runAcrossCores(std::size_t count, std::size_t leastPerPart,
                           const std::function<void(std::size_t, std::size_t)>& work, unsigned threads = 0) {
    const unsigned parts = partsAcrossCores(count, leastPerPart, threads);
    runParts(parts, [&](unsigned part) { work(partBegin(count, parts, part), partBegin(count, parts, part + 1)); });
}

// Folds [0, count) into a T across cores as runAcrossCores splits it: each part folds its items
// into a copy of `init` (fold(T&, i)), then the parts' results are merged in order into another
// (merge(T&, const T&)). For results that do not depend on the grouping (a minimum, a count), from
// an `init` that merging leaves unchanged (infinity for a minimum, 0 for a count, true for "all").
template <typename T, typename Fold, typename Merge>
T reduceAcrossCores(std::size_t count, std::size_t leastPerPart, const T& init, const Fold& fold, const Merge& merge) {
    const unsigned parts = partsAcrossCores(count, leastPerPart);
    std::vector<T> results(parts, init);
    runParts(parts, [&](unsigned part) {
        T result = init;  // not in `results` while folding: parts' results share cache lines
        for (std::size_t i = partBegin(count, parts, part); i < partBegin(count, parts, part + 1); ++i) {
            fold(result, i);
        }
        results[part] = result;
    });
    T total = init;
    for (const T& result : results) {
        merge(total, result);
    }
    return total;
}

}  // namespace hexray::util
