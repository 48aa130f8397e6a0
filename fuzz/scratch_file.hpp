#pragma once
// The file a fuzz target hands its input to a file-reading library through: one per process in
// the temporary directory, removed with its SQLite side files when the fuzzer exits (libFuzzer
// ends a time-limited run with exit(), which runs static destructors).

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace littermap::fuzz {

class ScratchFile {
 public:
  // TMPDIR/PREFIX_PID.EXTENSION
  ScratchFile(const std::string& prefix, const std::string& extension)
      : path_(std::filesystem::temp_directory_path() /
              (prefix + "_" + std::to_string(::getpid()) + extension)) {}
  ~ScratchFile() { Remove(); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // Removes the file and what SQLite may have left beside it.
  void Remove() const {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
    for (const char* suffix : {"-wal", "-shm", "-journal"}) {
      std::filesystem::remove(path_.string() + suffix, ignored);
    }
  }

 private:
  std::filesystem::path path_;
};

}  // namespace littermap::fuzz
