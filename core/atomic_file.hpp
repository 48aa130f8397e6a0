#pragma once
// Writing a file so that readers see the old contents or the new, never half of the new: the
// contents go to FILE.tmp, which is then renamed over FILE.

#include <filesystem>
#include <string_view>

namespace littermap {

// Throws the FileFailure naming the file when it cannot be written (disk full: environment).
void WriteFileAtomically(const std::filesystem::path& file, std::string_view contents);

}  // namespace littermap
