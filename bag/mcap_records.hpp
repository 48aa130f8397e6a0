#pragma once
// The records of the MCAP file format (https://mcap.dev/spec, major version 0) that a ROS 2 bag
// uses, and their little-endian fields. A record is <opcode u8><content length u64><content>;
// strings are <u32 length><bytes>, maps and arrays <u32 byte length><entries>.
//
//   <magic><Header><Data section>[<Summary section>][<Summary Offset section>]<Footer><magic>
//
// Reading past a record's end throws McapFieldError; the storage reader adds file and offset.

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace littermap::bag::mcap {

inline constexpr std::array<std::uint8_t, 8> kMagic = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
inline constexpr std::size_t kRecordPrefixBytes = 9;  // opcode + content length
inline constexpr std::size_t kFooterContentBytes = 20;

enum class Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

class McapFieldError : public BadInputError {
 public:
  using BadInputError::BadInputError;
};

// Reads the fields of one record's content in order.
class FieldReader {
 public:
  explicit FieldReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  std::uint8_t U8() { return static_cast<std::uint8_t>(Little(1)); }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Little(2)); }
  std::uint32_t U32() { return static_cast<std::uint32_t>(Little(4)); }
  std::uint64_t U64() { return Little(8); }
  std::string String();
  std::span<const std::uint8_t> Bytes(std::uint64_t size);
  std::span<const std::uint8_t> Rest() { return Bytes(bytes_.size() - position_); }
  std::map<std::string, std::string> StringMap();
  std::size_t position() const { return position_; }
  bool done() const { return position_ == bytes_.size(); }

 private:
  std::uint64_t Little(int size);
  std::span<const std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

// Appends little-endian fields to a record's content.
class FieldWriter {
 public:
  explicit FieldWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  void U8(std::uint8_t value) { Little(value, 1); }
  void U16(std::uint16_t value) { Little(value, 2); }
  void U32(std::uint32_t value) { Little(value, 4); }
  void U64(std::uint64_t value) { Little(value, 8); }
  void String(const std::string& text);
  void Bytes(std::span<const std::uint8_t> bytes) {
    out_.insert(out_.end(), bytes.begin(), bytes.end());
  }
  void StringMap(const std::map<std::string, std::string>& map);

 private:
  void Little(std::uint64_t value, int size);
  std::vector<std::uint8_t>& out_;
};

struct Schema {
  std::uint16_t id = 0;  // 0 is reserved: a channel without schema
  std::string name;      // "sensor_msgs/msg/LaserScan"
  std::string encoding;  // "ros2msg"
  std::string data;      // the message definition
};

struct Channel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;  // "cdr"
  std::map<std::string, std::string> metadata;
};

struct Message {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;  // receive time, ns
  std::uint64_t publish_time = 0;
  std::span<const std::uint8_t> data;  // into the record's bytes
};

struct Chunk {
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::uint64_t uncompressed_size = 0;
  std::uint32_t uncompressed_crc = 0;  // 0: not computed
  std::string compression;             // "", "zstd", "lz4"
  std::span<const std::uint8_t> records;
};

struct ChunkIndex {
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::uint64_t chunk_start_offset = 0;  // of the chunk record's opcode
  std::uint64_t chunk_length = 0;        // whole record, prefix included
  std::map<std::uint16_t, std::uint64_t> message_index_offsets;
  std::uint64_t message_index_length = 0;
  std::string compression;
  std::uint64_t compressed_size = 0;
  std::uint64_t uncompressed_size = 0;
};

struct Statistics {
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0;
  std::uint32_t attachment_count = 0;
  std::uint32_t metadata_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint64_t message_start_time = 0;
  std::uint64_t message_end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

struct Footer {
  std::uint64_t summary_start = 0;         // 0: no summary section
  std::uint64_t summary_offset_start = 0;  // 0: no summary offset section
  std::uint32_t summary_crc = 0;
};

Schema ParseSchema(std::span<const std::uint8_t> content);
Channel ParseChannel(std::span<const std::uint8_t> content);
Message ParseMessage(std::span<const std::uint8_t> content);
Chunk ParseChunk(std::span<const std::uint8_t> content);
ChunkIndex ParseChunkIndex(std::span<const std::uint8_t> content);
Statistics ParseStatistics(std::span<const std::uint8_t> content);
Footer ParseFooter(std::span<const std::uint8_t> content);

// Appends one whole record (prefix and content) to out.
void AppendRecord(std::vector<std::uint8_t>& out, Opcode opcode,
                  std::span<const std::uint8_t> content);
std::vector<std::uint8_t> SchemaContent(const Schema& schema);
std::vector<std::uint8_t> ChannelContent(const Channel& channel);
// A message record's content without its data, which the caller appends.
std::vector<std::uint8_t> MessageContentHead(const Message& message);
std::vector<std::uint8_t> ChunkIndexContent(const ChunkIndex& index);
std::vector<std::uint8_t> StatisticsContent(const Statistics& statistics);

}  // namespace littermap::bag::mcap
