#pragma once
// A double uniform in [low, high) from a 64-bit engine, the same on every standard library
// (std::uniform_real_distribution's sequence is implementation-defined).

#include <random>

namespace hexray::test {

inline double uniform(std::mt19937_64& engine, double low, double high) {
    return low + (high - low) * double(engine() >> 11) * 0x1.0p-53;
}

}  // namespace hexray::test
