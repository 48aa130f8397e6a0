#include "core/output_file.hpp"

#include <cerrno>
#include <system_error>
#include <utility>

#include "core/failure.hpp"

namespace littermap {
namespace {

// The file's name, checked: "." or a folder cannot be replaced by a file (rename would fail
// only after the work, and with EBUSY for "."), nor can "" be written.
std::filesystem::path TemporaryOf(const std::filesystem::path& file) {
  std::error_code error;
  if (file.empty() || std::filesystem::is_directory(file, error)) {
    throw FileFailure(file, "cannot write a file", EISDIR);
  }
  return file.string() + ".tmp";
}

}  // namespace

OutputFile::OutputFile(std::filesystem::path file)
    : file_(std::move(file)), temporary_(TemporaryOf(file_)) {
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    pending_ = false;
    throw FileFailure(file_, "cannot create", errno);
  }
}

OutputFile::OutputFile(std::filesystem::path file, ByNameTag)
    : file_(std::move(file)), temporary_(TemporaryOf(file_)) {}

OutputFile OutputFile::ByName(std::filesystem::path file) {
  return OutputFile(std::move(file), ByNameTag{});
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : file_(std::move(other.file_)),
      temporary_(std::move(other.temporary_)),
      out_(std::move(other.out_)),
      pending_(std::exchange(other.pending_, false)) {}

OutputFile::~OutputFile() {
  if (!pending_) return;
  if (out_.is_open()) out_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void OutputFile::Commit() {
  if (out_.is_open()) {
    out_.flush();
    out_.close();
    if (!out_) {
      const int error = errno;
      std::error_code ignored;
      std::filesystem::remove(temporary_, ignored);
      pending_ = false;
      throw FileFailure(file_, "cannot write", error);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary_, file_, error);
  if (error) throw FileFailure(file_, "cannot write", error.value());
  pending_ = false;
}

void WriteFileAtomically(const std::filesystem::path& file, std::string_view contents) {
  OutputFile out(file);
  out.stream().write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.Commit();
}

}  // namespace littermap
