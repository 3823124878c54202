#pragma once
// Removing whatever is at a name inside a directory, and nothing outside it: a file, a FIFO, a
// device node, a symbolic link (never what it points to) or a directory with all it holds. Every
// step works relative to a directory opened without following links, so a link at any depth, or
// one swapped in meanwhile, is removed as a link and never followed.

#include <filesystem>
#include <string>

namespace hexray::inline io {

// Removes `name` (one path component) from `directory`. Returns false when something could not
// be removed (permissions, a tree deeper than 32 levels); nothing there counts as removed.
bool removeWithoutFollowing(const std::filesystem::path& directory, const std::string& name);

}  // namespace hexray::io
