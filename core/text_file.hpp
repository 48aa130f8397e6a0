#pragma once
// A small text file read whole (world descriptions, options, bag metadata, map headers). Only a
// regular file of at most max_bytes is read: a path that names a folder, /dev/zero or a pipe, or
// a file far larger than any such text, fails at once naming the file, instead of reading until
// memory runs out.

#include <cstdint>
#include <filesystem>
#include <string>

namespace littermap {

inline constexpr std::uintmax_t kMaxTextFileBytes = 16u << 20;

// The file's bytes. Throws BadInputError (not a regular file, too large) or FileFailure.
std::string ReadTextFile(const std::filesystem::path& path,
                         std::uintmax_t max_bytes = kMaxTextFileBytes);

}  // namespace littermap
