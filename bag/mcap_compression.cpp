#include "bag/mcap_compression.hpp"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <cstring>
#include <memory>

#include "core/error.hpp"

namespace littermap::bag {
namespace {

// rosbag2 closes chunks at ~1 MiB; one message (a raw 4K image is 24 MiB) may make a chunk
// bigger, but no sensor message needs this much.
constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{512} << 20;

// zstd at level 1 and LZ4 at its default, the fastest settings: recording must keep up with
// the sensors.
constexpr int kZstdLevel = 1;

std::vector<std::uint8_t> Lz4Compress(std::span<const std::uint8_t> records) {
  LZ4F_preferences_t preferences{};
  preferences.frameInfo.contentSize = records.size();
  std::vector<std::uint8_t> out(LZ4F_compressFrameBound(records.size(), &preferences));
  const std::size_t size =
      LZ4F_compressFrame(out.data(), out.size(), records.data(), records.size(), &preferences);
  if (LZ4F_isError(size)) {
    throw InternalError(std::string("lz4 compression failed: ") + LZ4F_getErrorName(size));
  }
  out.resize(size);
  return out;
}

// Output grows as the frame produces bytes, up to the size the chunk states: a hostile size
// field costs nothing until the data is really there.
class GrowingOutput {
 public:
  // Real chunks pack less than 64:1, so they get their whole output at once.
  GrowingOutput(std::uint64_t stated, std::size_t compressed_size)
      : stated_(stated),
        bytes_(static_cast<std::size_t>(std::min<std::uint64_t>(
            stated, std::max<std::uint64_t>(kFirstSize, 64 * std::uint64_t{compressed_size})))) {}
  // Room for more output; false when the stated size is reached.
  bool Grow() {
    if (bytes_.size() >= stated_) return false;
    bytes_.Resize(static_cast<std::size_t>(std::min<std::uint64_t>(stated_, bytes_.size() * 2)));
    return true;
  }
  std::uint8_t* at(std::size_t offset) { return bytes_.data() + offset; }
  std::size_t size() const { return bytes_.size(); }
  [[noreturn]] void ThrowUnfinished(std::size_t written, const char* codec) const {
    throw BadInputError(std::string(codec) + (written >= stated_ ? " frame holds more than the " +
                                                                       std::to_string(stated_) +
                                                                       " bytes the chunk states"
                                                                 : " frame is cut short"));
  }
  ByteBuffer Finish(std::size_t written, const char* codec) {
    if (written != stated_) {
      throw BadInputError(std::string(codec) + " frame is cut short or holds " +
                          std::to_string(written) + " bytes, not the " + std::to_string(stated_) +
                          " the chunk states");
    }
    return std::move(bytes_);
  }

 private:
  static constexpr std::uint64_t kFirstSize = 1 << 20;
  std::uint64_t stated_;
  ByteBuffer bytes_;
};

ByteBuffer Lz4Decompress(std::span<const std::uint8_t> in, std::uint64_t stated) {
  LZ4F_dctx* context = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&context, LZ4F_VERSION))) {
    throw InternalError("lz4: cannot create a decompression context");
  }
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> owner(
      context, &LZ4F_freeDecompressionContext);
  GrowingOutput out(stated, in.size());
  std::size_t written = 0, read = 0, status = 1;
  while (status != 0) {
    if (written == out.size() && !out.Grow()) break;
    std::size_t out_size = out.size() - written;
    std::size_t in_size = in.size() - read;
    status =
        LZ4F_decompress(context, out.at(written), &out_size, in.data() + read, &in_size, nullptr);
    if (LZ4F_isError(status)) {
      throw BadInputError(std::string("lz4 frame is corrupt: ") + LZ4F_getErrorName(status));
    }
    written += out_size;
    read += in_size;
    if (out_size == 0 && in_size == 0 && written < out.size()) break;  // input exhausted
  }
  if (status != 0) out.ThrowUnfinished(written, "lz4");
  return out.Finish(written, "lz4");
}

ByteBuffer ZstdDecompress(std::span<const std::uint8_t> in, std::uint64_t stated) {
  std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> context(ZSTD_createDCtx(), &ZSTD_freeDCtx);
  if (!context) throw InternalError("zstd: cannot create a decompression context");
  GrowingOutput out(stated, in.size());
  ZSTD_inBuffer input{in.data(), in.size(), 0};
  std::size_t written = 0, status = 1;
  while (status != 0) {
    if (written == out.size() && !out.Grow()) break;
    ZSTD_outBuffer output{out.at(0), out.size(), written};
    status = ZSTD_decompressStream(context.get(), &output, &input);
    if (ZSTD_isError(status)) {
      throw BadInputError(std::string("zstd frame is corrupt: ") + ZSTD_getErrorName(status));
    }
    const bool progressed = output.pos != written;
    written = output.pos;
    if (!progressed && input.pos == input.size && written < out.size()) break;  // input exhausted
  }
  if (status != 0) out.ThrowUnfinished(written, "zstd");
  return out.Finish(written, "zstd");
}

}  // namespace

const char* McapCompressionName(McapCompression compression) {
  switch (compression) {
    case McapCompression::kZstd:
      return "zstd";
    case McapCompression::kLz4:
      return "lz4";
    case McapCompression::kNone:
      break;
  }
  return "";
}

McapCompression ParseMcapCompression(const std::string& name) {
  if (name == "none" || name.empty()) return McapCompression::kNone;
  if (name == "zstd") return McapCompression::kZstd;
  if (name == "lz4") return McapCompression::kLz4;
  throw UsageError("unknown MCAP compression '" + name + "' (none, zstd or lz4)");
}

std::vector<std::uint8_t> CompressChunk(std::span<const std::uint8_t> records,
                                        McapCompression compression) {
  switch (compression) {
    case McapCompression::kNone:
      return {records.begin(), records.end()};
    case McapCompression::kLz4:
      return Lz4Compress(records);
    case McapCompression::kZstd:
      break;
  }
  std::vector<std::uint8_t> out(ZSTD_compressBound(records.size()));
  const std::size_t size =
      ZSTD_compress(out.data(), out.size(), records.data(), records.size(), kZstdLevel);
  if (ZSTD_isError(size)) {
    throw InternalError(std::string("zstd compression failed: ") + ZSTD_getErrorName(size));
  }
  out.resize(size);
  return out;
}

ByteBuffer DecompressChunk(std::span<const std::uint8_t> compressed, const std::string& compression,
                           std::uint64_t uncompressed_size) {
  if (compression.empty()) {
    if (compressed.size() != uncompressed_size) {
      throw BadInputError("uncompressed chunk holds " + std::to_string(compressed.size()) +
                          " bytes, not the " + std::to_string(uncompressed_size) + " it states");
    }
    ByteBuffer copy(compressed.size());
    if (!compressed.empty()) std::memcpy(copy.data(), compressed.data(), compressed.size());
    return copy;
  }
  if (uncompressed_size > kMaxChunkBytes) {
    throw BadInputError("chunk states " + std::to_string(uncompressed_size) +
                        " uncompressed bytes, more than the " +
                        std::to_string(kMaxChunkBytes >> 20) + " MiB littermap reads in one chunk");
  }
  if (compression != "zstd" && compression != "lz4") {
    throw BadInputError("chunk compression '" + compression +
                        "' is not supported (zstd, lz4 or none)");
  }
  return compression == "lz4" ? Lz4Decompress(compressed, uncompressed_size)
                              : ZstdDecompress(compressed, uncompressed_size);
}

}  // namespace littermap::bag
