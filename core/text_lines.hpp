#pragma once
// Reads a text file line by line, plain or gzip-compressed (recognised by the gzip magic bytes,
// not by the file name), so importers take LOG and LOG.gz alike. Damaged compressed data is an
// error, never a silently shorter file: a truncated or corrupt gzip stream throws BadInputError
// naming the file and the last complete line read.
//
//   TextLineReader reader("intel.log.gz");
//   std::string_view line;
//   while (reader.Next(&line)) Parse(line, reader.line_number());

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string_view>

namespace littermap {

struct TextLineReaderOptions {
  std::size_t max_line_bytes = 16u << 20;  // longer lines are an error (binary junk, not text)
};

class TextLineReader {
 public:
  // Opens the file; throws BadInputError if it cannot be opened.
  explicit TextLineReader(const std::filesystem::path& path, TextLineReaderOptions options = {});
  ~TextLineReader();
  TextLineReader(const TextLineReader&) = delete;
  TextLineReader& operator=(const TextLineReader&) = delete;

  // The next line without its "\n" or "\r\n"; false at the end of the file. The view stays valid
  // until the next call. Throws BadInputError on truncated or corrupt gzip data.
  bool Next(std::string_view* line);

  std::uint64_t line_number() const;     // 1-based number of the line Next() returned last
  std::uint64_t bytes_consumed() const;  // bytes of the file read so far (for progress)
  std::uint64_t file_size() const;
  bool compressed() const;
  const std::filesystem::path& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace littermap
