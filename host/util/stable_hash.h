#pragma once
// A 64-bit FNV-1a hash: the same value on every run and build, for a strip stamp's scene identity.
// Not a guard against collisions or tampering (the kernel cache uses SHA-256, util/sha256.h).

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace hexray::inline util {

class StableHash {
public:
    void add(std::string_view bytes) {
        for (const char c : bytes) {
            value_ = (value_ ^ std::uint8_t(c)) * 0x100000001b3ull;
        }
        value_ = (value_ ^ 0xffu) * 0x100000001b3ull;  // a separator: "ab"+"c" differs from "a"+"bc"
    }
    std::uint64_t value() const { return value_; }
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value_));
        return text;
    }

private:
    std::uint64_t value_ = 0xcbf29ce484222325ull;
};

}  // namespace hexray::util
