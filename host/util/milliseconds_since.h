#pragma once
// Wall-clock milliseconds for the timings hexray prints.

#include <chrono>

namespace hexray::inline util {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hexray::util
