#include "core/atomic_file.hpp"

#include <cerrno>
#include <fstream>
#include <system_error>

#include "core/failure.hpp"

namespace littermap {

void WriteFileAtomically(const std::filesystem::path& file, std::string_view contents) {
  const std::filesystem::path temporary = file.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw FileFailure(file, "cannot write", errno);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) throw FileFailure(file, "cannot write", error.value());
}

}  // namespace littermap
