#pragma once
// A file opened once for reading and then read only through that descriptor, at given offsets
// (pread): whatever is renamed or replaced at its path afterwards, it is the same file. Several
// readers may read it one after another, each from offset 0.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace hexray::inline io {

// A file that cannot be opened or read; what() names it.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ReadOnlyFile {
public:
    // Opens `path` (close-on-exec, no controlling terminal). Throws InputError naming it.
    explicit ReadOnlyFile(const std::string& path);
    // Adopts an open descriptor (closed on destruction); `name` is what messages call it.
    ReadOnlyFile(int descriptor, std::string name);
    ~ReadOnlyFile();
    ReadOnlyFile(ReadOnlyFile&& other) noexcept;
    ReadOnlyFile& operator=(ReadOnlyFile&& other) noexcept;
    ReadOnlyFile(const ReadOnlyFile&) = delete;
    ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

    const std::string& name() const { return name_; }
    // The file's size now. Throws InputError.
    std::uint64_t size() const;
    // Up to bytes.size() bytes from `offset`: fewer only at the end of the file. Throws InputError.
    std::size_t readAt(std::uint64_t offset, std::span<std::byte> bytes) const;

private:
    int descriptor_ = -1;
    std::string name_;
};

}  // namespace hexray::io
