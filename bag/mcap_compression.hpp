#pragma once
// Chunk compression of MCAP files: "" (none), "zstd" (a zstd frame) and "lz4" (an LZ4 frame), as
// the MCAP specification names them.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace littermap::bag {

enum class McapCompression { kNone, kZstd, kLz4 };

// Bytes allocated without being zeroed first: a chunk's records are written in full before they
// are read, and zeroing megabytes per chunk would cost as much as decompressing them.
class ByteBuffer {
 public:
  ByteBuffer() = default;
  explicit ByteBuffer(std::size_t size) : data_(new std::uint8_t[size]), size_(size) {}
  std::uint8_t* data() { return data_.get(); }
  const std::uint8_t* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  std::span<const std::uint8_t> span() const { return {data_.get(), size_}; }
  // Keeps the first min(size, new size) bytes.
  void Resize(std::size_t size) {
    ByteBuffer bigger(size);
    if (size_ > 0) std::memcpy(bigger.data(), data(), std::min(size, size_));
    *this = std::move(bigger);
  }

 private:
  std::unique_ptr<std::uint8_t[]> data_;
  std::size_t size_ = 0;
};

// The specification's name of a compression ("", "zstd", "lz4").
const char* McapCompressionName(McapCompression compression);
// "none" | "zstd" | "lz4" (a user's choice); throws UsageError naming the accepted values.
McapCompression ParseMcapCompression(const std::string& name);

std::vector<std::uint8_t> CompressChunk(std::span<const std::uint8_t> records,
                                        McapCompression compression);

// Decompresses a chunk's records to exactly uncompressed_size bytes. Throws BadInputError with
// the reason (unknown compression named, corrupt frame, wrong size); the caller adds where.
ByteBuffer DecompressChunk(std::span<const std::uint8_t> compressed, const std::string& compression,
                           std::uint64_t uncompressed_size);

}  // namespace littermap::bag
