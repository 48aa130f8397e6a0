#include "core/text_lines.hpp"

#include <zlib.h>

#include <array>
#include <cstdio>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace littermap {
namespace {

constexpr std::size_t kChunkBytes = 1u << 16;

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

}  // namespace

struct TextLineReader::Impl {
  std::filesystem::path path;
  TextLineReaderOptions options;
  std::unique_ptr<std::FILE, FileCloser> file;
  std::uint64_t file_size = 0;
  std::uint64_t consumed = 0;
  std::uint64_t line_number = 0;
  bool gzip = false;
  bool input_done = false;  // no more text will be appended to `pending`
  bool inflate_open = false;
  z_stream stream{};
  std::array<unsigned char, kChunkBytes> input{};
  std::string pending;  // text read but not yet returned, from `start` on
  std::size_t start = 0;

  ~Impl() {
    if (inflate_open) inflateEnd(&stream);
  }

  [[noreturn]] void Fail(const std::string& what) const {
    throw BadInputError(path.string() + ": " + what + " after line " + std::to_string(line_number));
  }

  std::size_t ReadRaw(unsigned char* buffer, std::size_t size) {
    const std::size_t got = std::fread(buffer, 1, size, file.get());
    if (got < size && std::ferror(file.get())) Fail("read error");
    consumed += got;
    return got;
  }

  void Open() {
    std::error_code error;
    file_size = std::filesystem::file_size(path, error);
    file.reset(std::fopen(path.c_str(), "rb"));
    if (!file || error) throw BadInputError(path.string() + ": cannot open file");
    // Peek at the magic bytes: 1f 8b starts every gzip member (RFC 1952, 2.3.1).
    const std::size_t got = ReadRaw(input.data(), 2);
    gzip = got == 2 && input[0] == 0x1f && input[1] == 0x8b;
    if (gzip) {
      // 15 + 16: a gzip wrapper is expected, its CRC-32 and length are checked at the end.
      if (inflateInit2(&stream, 15 + 16) != Z_OK) throw InternalError("zlib: inflateInit2 failed");
      inflate_open = true;
      stream.next_in = input.data();
      stream.avail_in = 2;
    } else {
      pending.assign(reinterpret_cast<const char*>(input.data()), got);
    }
  }

  void FillPlain() {
    const std::size_t old_size = pending.size();
    pending.resize(old_size + kChunkBytes);
    const std::size_t got =
        ReadRaw(reinterpret_cast<unsigned char*>(pending.data() + old_size), kChunkBytes);
    pending.resize(old_size + got);
    if (got == 0) input_done = true;
  }

  // After the end of one gzip member: another member may follow (concatenated .gz files are
  // valid, RFC 1952, 2.2); anything else is junk that a truncated copy would not have.
  void StartNextMember() {
    if (stream.avail_in == 0) {
      stream.next_in = input.data();
      stream.avail_in = static_cast<uInt>(ReadRaw(input.data(), input.size()));
    }
    if (stream.avail_in == 0) {
      input_done = true;
      return;
    }
    if (stream.next_in[0] != 0x1f) Fail("unexpected data after the end of the gzip stream");
    inflateReset(&stream);
  }

  void FillGzip() {
    const std::size_t old_size = pending.size();
    pending.resize(old_size + kChunkBytes);
    stream.next_out = reinterpret_cast<Bytef*>(pending.data() + old_size);
    stream.avail_out = static_cast<uInt>(kChunkBytes);
    while (stream.avail_out == kChunkBytes && !input_done) {
      if (stream.avail_in == 0) {
        stream.next_in = input.data();
        stream.avail_in = static_cast<uInt>(ReadRaw(input.data(), input.size()));
        if (stream.avail_in == 0) Fail("gzip data truncated (the file ends inside the stream)");
      }
      const int status = inflate(&stream, Z_NO_FLUSH);
      if (status == Z_STREAM_END) {
        StartNextMember();
      } else if (status == Z_DATA_ERROR || status == Z_NEED_DICT) {
        Fail(std::string("corrupt gzip data (") + (stream.msg ? stream.msg : "zlib error") + ")");
      } else if (status == Z_MEM_ERROR) {
        throw InternalError("zlib: out of memory inflating " + path.string());
      }
    }
    pending.resize(old_size + (kChunkBytes - stream.avail_out));
  }

  void Fill() {
    if (start > 0) {  // keep only the unreturned tail so the buffer does not grow
      pending.erase(0, start);
      start = 0;
    }
    if (gzip) {
      FillGzip();
    } else {
      FillPlain();
    }
  }

  bool Next(std::string_view* line) {
    std::size_t searched = start;
    while (true) {
      const std::size_t newline = pending.find('\n', searched);
      if (newline != std::string::npos) {
        CheckLength(newline - start);
        Emit(line, newline - start, newline + 1);
        return true;
      }
      CheckLength(pending.size() - start);
      if (input_done) {
        if (start >= pending.size()) return false;
        Emit(line, pending.size() - start, pending.size());  // last line without "\n"
        return true;
      }
      const std::size_t scanned = pending.size() - start;  // no newline in there
      Fill();  // moves the unreturned text to the front: start becomes 0
      searched = start + scanned;
    }
  }

  void CheckLength(std::size_t length) const {
    if (length <= options.max_line_bytes) return;
    throw BadInputError(path.string() + ": line " + std::to_string(line_number + 1) +
                        " is longer than " + std::to_string(options.max_line_bytes) +
                        " bytes (not a text file?)");
  }

  void Emit(std::string_view* line, std::size_t length, std::size_t next_start) {
    std::string_view text(pending.data() + start, length);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    *line = text;
    start = next_start;
    ++line_number;
  }
};

TextLineReader::TextLineReader(const std::filesystem::path& path, TextLineReaderOptions options)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->options = options;
  impl_->Open();
}

TextLineReader::~TextLineReader() = default;

bool TextLineReader::Next(std::string_view* line) { return impl_->Next(line); }
std::uint64_t TextLineReader::line_number() const { return impl_->line_number; }
std::uint64_t TextLineReader::bytes_consumed() const { return impl_->consumed; }
std::uint64_t TextLineReader::file_size() const { return impl_->file_size; }
bool TextLineReader::compressed() const { return impl_->gzip; }
const std::filesystem::path& TextLineReader::path() const { return impl_->path; }

}  // namespace littermap
