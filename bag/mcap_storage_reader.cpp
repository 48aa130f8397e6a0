// MCAP storage (https://mcap.dev/spec): a file written by littermap, by rosbag2's MCAP plugin
// or by any MCAP writer with ROS 2 messages (schema encoding "ros2msg", message encoding "cdr").
//
// Opening reads the summary section when the file has a complete one (statistics and one chunk
// index per chunk): schemas, channels, counts and where each chunk is, without touching the
// data. Otherwise (a recording cut off before its summary, a writer that writes none) the data
// section is scanned once, chunk by chunk. Messages then come in log-time order: chunks are
// opened in the order of their first message and merged, so overlapping chunks and split files
// come out right. A damaged chunk (bad compression, CRC or records) is skipped with a warning
// naming file and offset; the rest of the file is read. The file is mapped into memory: chunks
// decompress straight from the page cache, and uncompressed ones are not copied at all.

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <utility>

#include "bag/mcap_compression.hpp"
#include "bag/mcap_records.hpp"
#include "bag/storage_file.hpp"

namespace littermap::bag {
namespace {

using mcap::Opcode;

// A piece of the data section that holds messages: a chunk, or one message outside any chunk.
struct Block {
  std::uint64_t offset = 0;  // of the record's opcode
  std::uint64_t length = 0;  // of the whole record
  std::uint64_t start_time = 0;
  bool chunk = false;
  std::vector<std::uint16_t> channels;  // empty: not known before opening it
};

// A chunk's records: in the mapped file (uncompressed) or in a decompressed buffer.
struct ChunkRecords {
  std::shared_ptr<const ByteBuffer> owner;  // null when bytes point into the mapped file
  std::span<const std::uint8_t> bytes;
};

struct Pending {
  std::uint64_t time = 0;
  std::uint64_t order = 0;  // ties keep file order
  std::uint16_t channel = 0;
  std::shared_ptr<const ByteBuffer> owner;  // keeps data alive; null: data is in the map
  std::span<const std::uint8_t> data;
};

struct Later {
  bool operator()(const Pending& a, const Pending& b) const {
    return a.time != b.time ? a.time > b.time : a.order > b.order;
  }
};

class McapStorageReader : public StorageFileReader {
 public:
  explicit McapStorageReader(const std::filesystem::path& file) : path_(file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw BadInputError(file.string() + ": cannot open: " + std::strerror(errno));
    struct stat status {};
    if (::fstat(fd, &status) == 0 && status.st_size > 0) {
      size_ = static_cast<std::uint64_t>(status.st_size);
      void* map = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
      map_ = map == MAP_FAILED ? nullptr : static_cast<const std::uint8_t*>(map);
    }
    const int error = errno;
    ::close(fd);
    if (size_ > 0 && map_ == nullptr) {
      throw BadInputError(file.string() + ": cannot map: " + std::strerror(error));
    }
    const auto magic = ReadAt(0, std::min<std::uint64_t>(size_, mcap::kMagic.size()));
    if (!std::equal(magic.begin(), magic.end(), mcap::kMagic.begin(), mcap::kMagic.end())) {
      throw BadInputError(file.string() + ": not an MCAP file (no MCAP magic at offset 0)");
    }
    if (!ReadSummary()) ScanDataSection();
    std::stable_sort(blocks_.begin(), blocks_.end(),
                     [](const Block& a, const Block& b) { return a.start_time < b.start_time; });
  }

  ~McapStorageReader() override {
    if (map_ != nullptr) ::munmap(const_cast<std::uint8_t*>(map_), size_);
  }
  McapStorageReader(const McapStorageReader&) = delete;
  McapStorageReader& operator=(const McapStorageReader&) = delete;

  std::vector<StoredTopic> Topics() const override {
    std::vector<StoredTopic> topics;
    for (const auto& [id, channel] : channels_) {
      StoredTopic topic;
      topic.id = id;
      topic.info.name = channel.topic;
      topic.info.serialization_format = channel.message_encoding;
      if (auto schema = schemas_.find(channel.schema_id); schema != schemas_.end()) {
        topic.info.type = schema->second.name;
        topic.info.message_definition = schema->second.data;
      }
      if (auto qos = channel.metadata.find("offered_qos_profiles"); qos != channel.metadata.end()) {
        topic.info.offered_qos_profiles = qos->second;
      }
      if (auto hash = channel.metadata.find("topic_type_hash"); hash != channel.metadata.end()) {
        topic.info.type_description_hash = hash->second;
      }
      topics.push_back(std::move(topic));
    }
    return topics;
  }

  std::vector<TopicCount> Counts() override {
    std::vector<TopicCount> counts;
    for (const auto& [id, count] : counts_) {
      if (count.count == 0) continue;
      if (channels_.count(id) == 0) {
        warnings_.push_back(path_.string() + ": " + std::to_string(count.count) +
                            " messages on channel " + std::to_string(id) +
                            ", which the file never defines; skipped");
        continue;
      }
      counts.push_back(count);
    }
    return counts;
  }

  int SchemaVersion() const override { return 0; }

  void Start(const std::vector<std::int64_t>& topic_ids) override {
    filter_.clear();
    for (const std::int64_t id : topic_ids) filter_.insert(static_cast<std::uint16_t>(id));
    pending_ = {};
    next_block_ = 0;
    order_ = 0;
  }

  std::optional<TimestampNs> PeekTime() override {
    while (next_block_ < blocks_.size() &&
           (pending_.empty() || blocks_[next_block_].start_time <= pending_.top().time)) {
      Load(blocks_[next_block_++]);
    }
    if (pending_.empty()) return std::nullopt;
    return static_cast<TimestampNs>(pending_.top().time);
  }

  StoredMessage Take() override {
    const Pending& top = pending_.top();
    StoredMessage message;
    message.topic_id = top.channel;
    message.timestamp_ns = static_cast<TimestampNs>(top.time);
    message.data.assign(top.data.begin(), top.data.end());
    pending_.pop();
    return message;
  }

  void SetVerifyChecksums(bool verify) override { verify_checksums_ = verify; }

  std::vector<std::string> TakeWarnings() override { return std::exchange(warnings_, {}); }

 private:
  std::string Where(std::uint64_t offset) const {
    return path_.string() + ": offset " + std::to_string(offset);
  }

  std::span<const std::uint8_t> ReadAt(std::uint64_t offset, std::uint64_t size) const {
    if (offset > size_ || size > size_ - offset) {
      throw BadInputError(Where(offset) + ": " + std::to_string(size) +
                          " bytes run past the end of the file");
    }
    return {map_ + offset, static_cast<std::size_t>(size)};
  }

  // <opcode><length> at offset; false when the file ends before the record does.
  bool RecordAt(std::uint64_t offset, Opcode& opcode, std::uint64_t& length) const {
    if (size_ - offset < mcap::kRecordPrefixBytes) return false;
    const auto prefix = ReadAt(offset, mcap::kRecordPrefixBytes);
    mcap::FieldReader reader(prefix);
    opcode = static_cast<Opcode>(reader.U8());
    length = reader.U64();
    return length <= size_ - offset - mcap::kRecordPrefixBytes;
  }

  void AddSchema(mcap::Schema schema) {
    if (schema.id != 0) schemas_.emplace(schema.id, std::move(schema));
  }
  void AddChannel(mcap::Channel channel) {
    counts_[channel.id].id = channel.id;
    channels_.emplace(channel.id, std::move(channel));
  }
  void Count(std::uint16_t channel, std::uint64_t time) {
    TopicCount& count = counts_[channel];
    count.id = channel;
    const auto t = static_cast<TimestampNs>(time);
    count.first_ns = count.count ? std::min(count.first_ns, t) : t;
    count.last_ns = count.count ? std::max(count.last_ns, t) : t;
    ++count.count;
  }

  // The summary, when the file has a complete one. False (nothing read) otherwise.
  bool ReadSummary() {
    const std::uint64_t tail =
        mcap::kRecordPrefixBytes + mcap::kFooterContentBytes + mcap::kMagic.size();
    if (size_ < mcap::kMagic.size() + tail) return false;
    const std::uint64_t footer_offset = size_ - tail;
    const auto bytes = ReadAt(footer_offset, tail);
    if (bytes[0] != static_cast<std::uint8_t>(Opcode::kFooter) ||
        !std::equal(mcap::kMagic.begin(), mcap::kMagic.end(), bytes.end() - 8)) {
      return false;
    }
    const mcap::Footer footer = mcap::ParseFooter(
        std::span(bytes).subspan(mcap::kRecordPrefixBytes, mcap::kFooterContentBytes));
    if (footer.summary_start < mcap::kMagic.size() || footer.summary_start >= footer_offset) {
      return false;
    }
    try {
      std::map<std::uint16_t, mcap::Schema> schemas;
      std::map<std::uint16_t, mcap::Channel> channels;
      std::vector<mcap::ChunkIndex> chunks;
      std::optional<mcap::Statistics> statistics;
      const auto summary = ReadAt(footer.summary_start, footer_offset - footer.summary_start);
      mcap::FieldReader records(summary);
      while (!records.done()) {
        const auto opcode = static_cast<Opcode>(records.U8());
        const auto content = records.Bytes(records.U64());
        if (opcode == Opcode::kSchema) {
          auto schema = mcap::ParseSchema(content);
          schemas.emplace(schema.id, std::move(schema));
        } else if (opcode == Opcode::kChannel) {
          auto channel = mcap::ParseChannel(content);
          channels.emplace(channel.id, std::move(channel));
        } else if (opcode == Opcode::kChunkIndex) {
          chunks.push_back(mcap::ParseChunkIndex(content));
        } else if (opcode == Opcode::kStatistics) {
          statistics = mcap::ParseStatistics(content);
        }
      }
      // Messages outside chunks have no index: only a summary that accounts for every chunk
      // of a chunked file (or an empty one) replaces the scan.
      if (!statistics || statistics->chunk_count != chunks.size() ||
          (chunks.empty() && statistics->message_count > 0)) {
        return false;
      }
      for (auto& [id, schema] : schemas) AddSchema(std::move(schema));
      for (auto& [id, channel] : channels) AddChannel(std::move(channel));
      for (const auto& [channel, count] : statistics->channel_message_counts) {
        TopicCount& topic = counts_[channel];
        topic = {channel, count, static_cast<TimestampNs>(statistics->message_start_time),
                 static_cast<TimestampNs>(statistics->message_end_time)};
      }
      for (const mcap::ChunkIndex& chunk : chunks) {
        Block block{
            chunk.chunk_start_offset, chunk.chunk_length, chunk.message_start_time, true, {}};
        for (const auto& [channel, offset] : chunk.message_index_offsets) {
          block.channels.push_back(channel);
        }
        blocks_.push_back(std::move(block));
      }
      return true;
    } catch (const BadInputError& e) {
      warnings_.push_back(Where(footer.summary_start) + ": the summary section is damaged (" +
                          e.what() + "); the data section is scanned instead");
      schemas_.clear();
      channels_.clear();
      counts_.clear();
      blocks_.clear();
      return false;
    }
  }

  void ScanDataSection() {
    std::uint64_t offset = mcap::kMagic.size();
    std::uint64_t messages = 0;
    while (offset < size_) {
      Opcode opcode{};
      std::uint64_t length = 0;
      if (!RecordAt(offset, opcode, length)) {
        warnings_.push_back(Where(offset) +
                            ": the file is cut off inside a record (a recording "
                            "that did not finish?); the " +
                            std::to_string(messages) + " messages before it are read");
        return;
      }
      const std::uint64_t content_offset = offset + mcap::kRecordPrefixBytes;
      const std::uint64_t next = content_offset + length;
      try {
        switch (opcode) {
          case Opcode::kSchema:
            AddSchema(mcap::ParseSchema(ReadAt(content_offset, length)));
            break;
          case Opcode::kChannel:
            AddChannel(mcap::ParseChannel(ReadAt(content_offset, length)));
            break;
          case Opcode::kMessage: {
            const auto head = ReadAt(content_offset, std::min<std::uint64_t>(length, 22));
            const mcap::Message message = mcap::ParseMessage(head);
            Count(message.channel_id, message.log_time);
            ++messages;
            blocks_.push_back(
                {offset, next - offset, message.log_time, false, {message.channel_id}});
            break;
          }
          case Opcode::kChunk:
            messages += ScanChunk(offset, next - offset);
            break;
          case Opcode::kDataEnd:
          case Opcode::kFooter:
            return;
          default:
            break;
        }
      } catch (const BadInputError& e) {
        warnings_.push_back(Where(offset) + ": record is damaged (" + e.what() + "); skipped");
      }
      offset = next;
    }
    warnings_.push_back(Where(offset) +
                        ": the file ends without a summary (a recording that did "
                        "not finish?); its " +
                        std::to_string(messages) + " messages are read");
  }

  // The records of the chunk record at offset; BadInputError when it is damaged.
  ChunkRecords RecordsOf(std::uint64_t offset, std::uint64_t length) const {
    const auto record = ReadAt(offset, length);
    if (record[0] != static_cast<std::uint8_t>(Opcode::kChunk)) {
      throw BadInputError("no chunk record there");
    }
    const mcap::Chunk chunk = mcap::ParseChunk(record.subspan(mcap::kRecordPrefixBytes));
    ChunkRecords records;
    if (chunk.compression.empty() && chunk.records.size() == chunk.uncompressed_size) {
      records.bytes = chunk.records;
    } else {
      records.owner = std::make_shared<const ByteBuffer>(
          DecompressChunk(chunk.records, chunk.compression, chunk.uncompressed_size));
      records.bytes = records.owner->span();
    }
    if (verify_checksums_ && chunk.uncompressed_crc != 0 &&
        crc32(0, records.bytes.data(), static_cast<uInt>(records.bytes.size())) !=
            chunk.uncompressed_crc) {
      throw BadInputError("its records fail their CRC");
    }
    return records;
  }

  // Calls each(opcode, content) for every record in a chunk's records.
  template <typename Each>
  static void ForEachRecord(std::span<const std::uint8_t> records, Each&& each) {
    mcap::FieldReader reader(records);
    while (!reader.done()) {
      const auto opcode = static_cast<Opcode>(reader.U8());
      const std::uint64_t length = reader.U64();
      each(opcode, reader.Bytes(length));
    }
  }

  std::uint64_t ScanChunk(std::uint64_t offset, std::uint64_t length) {
    ChunkRecords records;
    try {
      records = RecordsOf(offset, length);
    } catch (const BadInputError& e) {
      warnings_.push_back(Where(offset) + ": chunk is damaged (" + e.what() +
                          "); its messages are skipped");
      return 0;
    }
    Block block{offset, length, 0, true, {}};
    std::set<std::uint16_t> channels;
    std::uint64_t messages = 0;
    ForEachRecord(records.bytes, [&](Opcode opcode, std::span<const std::uint8_t> content) {
      if (opcode == Opcode::kSchema) AddSchema(mcap::ParseSchema(content));
      if (opcode == Opcode::kChannel) AddChannel(mcap::ParseChannel(content));
      if (opcode != Opcode::kMessage) return;
      const mcap::Message message = mcap::ParseMessage(content);
      block.start_time = messages ? std::min(block.start_time, message.log_time) : message.log_time;
      channels.insert(message.channel_id);
      Count(message.channel_id, message.log_time);
      ++messages;
    });
    block.channels.assign(channels.begin(), channels.end());
    if (messages > 0) blocks_.push_back(std::move(block));
    return messages;
  }

  bool Wanted(std::uint16_t channel) const {
    return filter_.empty() ? channels_.count(channel) > 0 : filter_.count(channel) > 0;
  }

  void Load(const Block& block) {
    if (!block.channels.empty() &&
        std::none_of(block.channels.begin(), block.channels.end(),
                     [&](std::uint16_t channel) { return Wanted(channel); })) {
      return;
    }
    try {
      ChunkRecords records;
      std::vector<Pending> messages;
      auto add = [&](std::span<const std::uint8_t> content) {
        const mcap::Message message = mcap::ParseMessage(content);
        if (Wanted(message.channel_id)) {
          messages.push_back({message.log_time, 0, message.channel_id, nullptr, message.data});
        }
      };
      if (block.chunk) {
        records = RecordsOf(block.offset, block.length);
        ForEachRecord(records.bytes, [&](Opcode opcode, std::span<const std::uint8_t> content) {
          if (opcode == Opcode::kMessage) add(content);
        });
      } else {
        add(ReadAt(block.offset + mcap::kRecordPrefixBytes,
                   block.length - mcap::kRecordPrefixBytes));
      }
      for (Pending& message : messages) {
        message.order = order_++;
        message.owner = records.owner;
        pending_.push(std::move(message));
      }
    } catch (const BadInputError& e) {
      warnings_.push_back(Where(block.offset) + ": " + (block.chunk ? "chunk" : "message") +
                          " is damaged (" + e.what() + "); its messages are skipped");
    }
  }

  std::filesystem::path path_;
  const std::uint8_t* map_ = nullptr;  // the whole file, read-only
  std::uint64_t size_ = 0;
  std::map<std::uint16_t, mcap::Schema> schemas_;
  std::map<std::uint16_t, mcap::Channel> channels_;
  std::map<std::uint16_t, TopicCount> counts_;
  std::vector<Block> blocks_;
  std::vector<std::string> warnings_;
  bool verify_checksums_ = false;

  std::set<std::uint16_t> filter_;
  std::size_t next_block_ = 0;
  std::uint64_t order_ = 0;
  std::priority_queue<Pending, std::vector<Pending>, Later> pending_;
};

}  // namespace

std::unique_ptr<StorageFileReader> OpenMcapStorage(const std::filesystem::path& file) {
  return std::make_unique<McapStorageReader>(file);
}

}  // namespace littermap::bag
