#include "core/text_file.hpp"

#include <cerrno>
#include <fstream>
#include <system_error>

#include "core/error.hpp"
#include "core/failure.hpp"

namespace littermap {

std::string ReadTextFile(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error) throw FileFailure(path, "cannot read", error.value());
  if (!std::filesystem::exists(status)) throw FileFailure(path, "cannot read", ENOENT);
  if (!std::filesystem::is_regular_file(status)) {
    throw BadInputError(path.string() + ": not a regular file (" +
                        (std::filesystem::is_directory(status) ? "a folder" : "a device or pipe") +
                        ")");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw FileFailure(path, "cannot read", error.value());
  if (size > max_bytes) {
    throw BadInputError(path.string() + ": " + std::to_string(size) + " bytes, more than the " +
                        std::to_string(max_bytes) + " a text file of this kind may have");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileFailure(path, "cannot open", errno);
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.bad()) throw FileFailure(path, "cannot read", errno);
  if (in.gcount() != static_cast<std::streamsize>(size)) {
    throw BadInputError(path.string() + ": changed while it was read");
  }
  return text;
}

}  // namespace littermap
