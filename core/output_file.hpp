#pragma once
// An output written under a temporary name (FILE.tmp) and renamed over FILE once complete, so
// that FILE is either absent, the previous version or the whole new one: a full disk, a kill or
// an error half-way never leaves a truncated file that looks finished.

#include <filesystem>
#include <fstream>
#include <string_view>

namespace littermap {

class OutputFile {
 public:
  // Opens FILE.tmp for writing through stream(). Throws the FileFailure naming FILE.
  explicit OutputFile(std::filesystem::path file);
  // For a library that opens the file by name itself (libtiff): nothing is opened here; the
  // library writes temporary(), then Commit() renames it.
  static OutputFile ByName(std::filesystem::path file);

  OutputFile(OutputFile&& other) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  OutputFile& operator=(OutputFile&&) = delete;
  // Removes the temporary file unless committed.
  ~OutputFile();

  std::ostream& stream() { return out_; }
  const std::filesystem::path& file() const { return file_; }
  const std::filesystem::path& temporary() const { return temporary_; }

  // Flushes and closes the stream, then renames the temporary over FILE. Throws the FileFailure
  // naming FILE (disk full: environment) and removes the temporary.
  void Commit();

 private:
  struct ByNameTag {};
  OutputFile(std::filesystem::path file, ByNameTag);

  std::filesystem::path file_;
  std::filesystem::path temporary_;
  std::ofstream out_;
  bool pending_ = true;  // the temporary exists or may exist, and is not renamed yet
};

// The whole contents at once.
void WriteFileAtomically(const std::filesystem::path& file, std::string_view contents);

}  // namespace littermap
