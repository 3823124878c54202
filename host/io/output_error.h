#pragma once
// An output that cannot be written: a missing or read-only directory, a write that failed.
// what() names the path as the user gave it. The command's exit code is 5.

#include <stdexcept>

namespace hexray::inline io {

class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace hexray::io
