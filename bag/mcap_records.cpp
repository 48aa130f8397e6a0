#include "bag/mcap_records.hpp"

namespace littermap::bag::mcap {

std::uint64_t FieldReader::Little(int size) {
  if (bytes_.size() - position_ < static_cast<std::size_t>(size)) {
    throw McapFieldError("record ends inside a " + std::to_string(8 * size) +
                         "-bit field at byte " + std::to_string(position_));
  }
  std::uint64_t value = 0;
  for (int i = size - 1; i >= 0; --i) value = value << 8 | bytes_[position_ + i];
  position_ += static_cast<std::size_t>(size);
  return value;
}

std::span<const std::uint8_t> FieldReader::Bytes(std::uint64_t size) {
  if (bytes_.size() - position_ < size) {
    throw McapFieldError("a field of " + std::to_string(size) + " bytes at byte " +
                         std::to_string(position_) + " runs past the record's end");
  }
  const auto field = bytes_.subspan(position_, static_cast<std::size_t>(size));
  position_ += static_cast<std::size_t>(size);
  return field;
}

std::string FieldReader::String() {
  const auto bytes = Bytes(U32());
  return {bytes.begin(), bytes.end()};
}

std::map<std::string, std::string> FieldReader::StringMap() {
  FieldReader entries(Bytes(U32()));
  std::map<std::string, std::string> map;
  while (!entries.done()) {
    std::string key = entries.String();
    map[std::move(key)] = entries.String();
  }
  return map;
}

void FieldWriter::Little(std::uint64_t value, int size) {
  for (int i = 0; i < size; ++i) out_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void FieldWriter::String(const std::string& text) {
  U32(static_cast<std::uint32_t>(text.size()));
  out_.insert(out_.end(), text.begin(), text.end());
}

void FieldWriter::StringMap(const std::map<std::string, std::string>& map) {
  std::vector<std::uint8_t> entries;
  FieldWriter writer(entries);
  for (const auto& [key, value] : map) {
    writer.String(key);
    writer.String(value);
  }
  U32(static_cast<std::uint32_t>(entries.size()));
  Bytes(entries);
}

namespace {

std::map<std::uint16_t, std::uint64_t> ReadIdMap(FieldReader& reader) {
  FieldReader entries(reader.Bytes(reader.U32()));
  std::map<std::uint16_t, std::uint64_t> map;
  while (!entries.done()) {
    const std::uint16_t key = entries.U16();
    map[key] = entries.U64();
  }
  return map;
}

void WriteIdMap(FieldWriter& writer, const std::map<std::uint16_t, std::uint64_t>& map) {
  writer.U32(static_cast<std::uint32_t>(map.size() * 10));
  for (const auto& [key, value] : map) {
    writer.U16(key);
    writer.U64(value);
  }
}

}  // namespace

Schema ParseSchema(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  Schema schema;
  schema.id = reader.U16();
  schema.name = reader.String();
  schema.encoding = reader.String();
  const auto data = reader.Bytes(reader.U32());
  schema.data.assign(data.begin(), data.end());
  return schema;
}

Channel ParseChannel(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  Channel channel;
  channel.id = reader.U16();
  channel.schema_id = reader.U16();
  channel.topic = reader.String();
  channel.message_encoding = reader.String();
  channel.metadata = reader.StringMap();
  return channel;
}

Message ParseMessage(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  Message message;
  message.channel_id = reader.U16();
  message.sequence = reader.U32();
  message.log_time = reader.U64();
  message.publish_time = reader.U64();
  message.data = reader.Rest();
  return message;
}

Chunk ParseChunk(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  Chunk chunk;
  chunk.message_start_time = reader.U64();
  chunk.message_end_time = reader.U64();
  chunk.uncompressed_size = reader.U64();
  chunk.uncompressed_crc = reader.U32();
  chunk.compression = reader.String();
  chunk.records = reader.Bytes(reader.U64());
  return chunk;
}

ChunkIndex ParseChunkIndex(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  ChunkIndex index;
  index.message_start_time = reader.U64();
  index.message_end_time = reader.U64();
  index.chunk_start_offset = reader.U64();
  index.chunk_length = reader.U64();
  index.message_index_offsets = ReadIdMap(reader);
  index.message_index_length = reader.U64();
  index.compression = reader.String();
  index.compressed_size = reader.U64();
  index.uncompressed_size = reader.U64();
  return index;
}

Statistics ParseStatistics(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  Statistics statistics;
  statistics.message_count = reader.U64();
  statistics.schema_count = reader.U16();
  statistics.channel_count = reader.U32();
  statistics.attachment_count = reader.U32();
  statistics.metadata_count = reader.U32();
  statistics.chunk_count = reader.U32();
  statistics.message_start_time = reader.U64();
  statistics.message_end_time = reader.U64();
  statistics.channel_message_counts = ReadIdMap(reader);
  return statistics;
}

Footer ParseFooter(std::span<const std::uint8_t> content) {
  FieldReader reader(content);
  Footer footer;
  footer.summary_start = reader.U64();
  footer.summary_offset_start = reader.U64();
  footer.summary_crc = reader.U32();
  return footer;
}

void AppendRecord(std::vector<std::uint8_t>& out, Opcode opcode,
                  std::span<const std::uint8_t> content) {
  FieldWriter writer(out);
  writer.U8(static_cast<std::uint8_t>(opcode));
  writer.U64(content.size());
  writer.Bytes(content);
}

std::vector<std::uint8_t> SchemaContent(const Schema& schema) {
  std::vector<std::uint8_t> out;
  FieldWriter writer(out);
  writer.U16(schema.id);
  writer.String(schema.name);
  writer.String(schema.encoding);
  writer.String(schema.data);  // bytes with a u32 length: the same layout
  return out;
}

std::vector<std::uint8_t> ChannelContent(const Channel& channel) {
  std::vector<std::uint8_t> out;
  FieldWriter writer(out);
  writer.U16(channel.id);
  writer.U16(channel.schema_id);
  writer.String(channel.topic);
  writer.String(channel.message_encoding);
  writer.StringMap(channel.metadata);
  return out;
}

std::vector<std::uint8_t> MessageContentHead(const Message& message) {
  std::vector<std::uint8_t> out;
  FieldWriter writer(out);
  writer.U16(message.channel_id);
  writer.U32(message.sequence);
  writer.U64(message.log_time);
  writer.U64(message.publish_time);
  return out;
}

std::vector<std::uint8_t> ChunkIndexContent(const ChunkIndex& index) {
  std::vector<std::uint8_t> out;
  FieldWriter writer(out);
  writer.U64(index.message_start_time);
  writer.U64(index.message_end_time);
  writer.U64(index.chunk_start_offset);
  writer.U64(index.chunk_length);
  WriteIdMap(writer, index.message_index_offsets);
  writer.U64(index.message_index_length);
  writer.String(index.compression);
  writer.U64(index.compressed_size);
  writer.U64(index.uncompressed_size);
  return out;
}

std::vector<std::uint8_t> StatisticsContent(const Statistics& statistics) {
  std::vector<std::uint8_t> out;
  FieldWriter writer(out);
  writer.U64(statistics.message_count);
  writer.U16(statistics.schema_count);
  writer.U32(statistics.channel_count);
  writer.U32(statistics.attachment_count);
  writer.U32(statistics.metadata_count);
  writer.U32(statistics.chunk_count);
  writer.U64(statistics.message_start_time);
  writer.U64(statistics.message_end_time);
  WriteIdMap(writer, statistics.channel_message_counts);
  return out;
}

}  // namespace littermap::bag::mcap
