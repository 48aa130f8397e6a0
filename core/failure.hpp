#pragma once
// One mapping from failures to error kinds (and so to exit codes): littermap's own errors carry
// their kind; an operating-system error (std::system_error, std::filesystem::filesystem_error, an
// errno) is bad input when the path or data named is at fault (no such file, symlink loop, name
// too long, not a folder, invalid bytes) and environment when the machine is (disk full, no
// permission, read-only file system, device gone); out of memory is environment; anything else
// is internal, a bug.

#include <exception>
#include <filesystem>
#include <string_view>

#include "core/error.hpp"

namespace littermap {

ErrorKind KindOfErrno(int errno_value);

ErrorKind KindOf(const std::exception& failure);

// The error for a file operation that failed with errno_value: "FILE: DOING: strerror", of the
// errno's kind (environment when the errno is 0, as after a stream that failed without one).
Error FileFailure(const std::filesystem::path& file, std::string_view doing, int errno_value);

}  // namespace littermap
