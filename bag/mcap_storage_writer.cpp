#include "bag/mcap_storage_writer.hpp"

#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <utility>
#include <vector>

#include "bag/mcap_records.hpp"
#include "bag/storage_file.hpp"
#include "core/failure.hpp"
#include "littermap_version.hpp"

namespace littermap::bag {
namespace {

using mcap::Opcode;

class McapStorageWriter : public StorageFileWriter {
 public:
  McapStorageWriter(const std::filesystem::path& file, const McapStorageOptions& options)
      : path_(file), options_(options), stream_(std::fopen(file.c_str(), "wbx")) {
    if (stream_ == nullptr) {
      throw FileFailure(file, "cannot create", errno);
    }
    std::vector<std::uint8_t> header;
    mcap::FieldWriter writer(header);
    writer.String("ros2");
    writer.String(std::string("littermap ") + LITTERMAP_VERSION);
    std::vector<std::uint8_t> out(mcap::kMagic.begin(), mcap::kMagic.end());
    mcap::AppendRecord(out, Opcode::kHeader, header);
    Put(out);
    if (std::fflush(stream_) != 0) Fail("cannot write");
    commits_.push_back(position_);
  }

  ~McapStorageWriter() override {
    if (stream_ != nullptr) std::fclose(stream_);
  }

  std::int64_t AddTopic(const TopicInfo& topic) override {
    std::vector<std::uint8_t> out;
    std::uint16_t schema_id = 0;
    for (const auto& schema : schemas_) {
      if (schema.name == topic.type) schema_id = schema.id;
    }
    if (schema_id == 0) {
      mcap::Schema schema{static_cast<std::uint16_t>(schemas_.size() + 1), topic.type, "ros2msg",
                          topic.message_definition};
      schema_id = schema.id;
      mcap::AppendRecord(out, Opcode::kSchema, mcap::SchemaContent(schema));
      schemas_.push_back(std::move(schema));
    }
    mcap::Channel channel;
    channel.id = static_cast<std::uint16_t>(channels_.size());
    channel.schema_id = schema_id;
    channel.topic = topic.name;
    channel.message_encoding = topic.serialization_format;
    channel.metadata["offered_qos_profiles"] = topic.offered_qos_profiles;
    if (!topic.type_description_hash.empty()) {
      channel.metadata["topic_type_hash"] = topic.type_description_hash;
    }
    mcap::AppendRecord(out, Opcode::kChannel, mcap::ChannelContent(channel));
    channels_.push_back(std::move(channel));
    Put(out);
    return channels_.back().id;
  }

  void Write(std::int64_t topic_id, TimestampNs timestamp_ns,
             std::span<const std::uint8_t> serialized) override {
    const auto channel = static_cast<std::uint16_t>(topic_id);
    const auto log_time = static_cast<std::uint64_t>(timestamp_ns);
    mcap::Message message;
    message.channel_id = channel;
    message.sequence = static_cast<std::uint32_t>(statistics_.message_count);
    message.log_time = message.publish_time = log_time;
    const auto head = mcap::MessageContentHead(message);
    if (chunk_records_.empty()) chunk_start_ = chunk_end_ = log_time;
    chunk_start_ = std::min(chunk_start_, log_time);
    chunk_end_ = std::max(chunk_end_, log_time);
    chunk_indexes_[channel].push_back({log_time, chunk_records_.size()});
    mcap::FieldWriter writer(chunk_records_);
    writer.U8(static_cast<std::uint8_t>(Opcode::kMessage));
    writer.U64(head.size() + serialized.size());
    writer.Bytes(head);
    writer.Bytes(serialized);

    if (statistics_.message_count == 0) {
      statistics_.message_start_time = statistics_.message_end_time = log_time;
    }
    statistics_.message_start_time = std::min(statistics_.message_start_time, log_time);
    statistics_.message_end_time = std::max(statistics_.message_end_time, log_time);
    ++statistics_.message_count;
    ++statistics_.channel_message_counts[channel];
    if (chunk_records_.size() >= options_.chunk_size_bytes) CloseChunk();
  }

  void Commit() override {
    CloseChunk();
    if (std::fflush(stream_) != 0 || ::fsync(fileno(stream_)) != 0) Fail("cannot sync");
    if (position_ != commits_.back()) commits_.push_back(position_);
  }

  // A write that fails while closing (the disk full) is thrown once the last commit is salvaged.
  void Close(const BagInfo&) override {
    std::exception_ptr failure;
    if (!failed_) {
      try {
        Finish();
        return;
      } catch (...) {
        if (!failed_) throw;
        failure = std::current_exception();
      }
    }
    Salvage();
    if (failure) std::rethrow_exception(failure);
  }

  const std::filesystem::path& file() const override { return path_; }

 private:
  // The open chunk, the data end, the summary and the footer.
  void Finish() {
    CloseChunk();
    std::vector<std::uint8_t> out;
    AppendDataEnd(out);
    Put(out);
    out.clear();

    const std::uint64_t summary_start = position_;
    struct Group {
      Opcode opcode;
      std::uint64_t start, length;
    };
    std::vector<Group> groups;
    auto group = [&](Opcode opcode, auto&& append) {
      const std::uint64_t start = summary_start + out.size();
      append();
      if (summary_start + out.size() > start) {
        groups.push_back({opcode, start, summary_start + out.size() - start});
      }
    };
    group(Opcode::kSchema, [&] {
      for (const auto& schema : schemas_) {
        mcap::AppendRecord(out, Opcode::kSchema, mcap::SchemaContent(schema));
      }
    });
    group(Opcode::kChannel, [&] {
      for (const auto& channel : channels_) {
        mcap::AppendRecord(out, Opcode::kChannel, mcap::ChannelContent(channel));
      }
    });
    statistics_.schema_count = static_cast<std::uint16_t>(schemas_.size());
    statistics_.channel_count = static_cast<std::uint32_t>(channels_.size());
    statistics_.chunk_count = static_cast<std::uint32_t>(chunk_index_records_.size());
    group(Opcode::kStatistics, [&] {
      mcap::AppendRecord(out, Opcode::kStatistics, mcap::StatisticsContent(statistics_));
    });
    group(Opcode::kChunkIndex, [&] {
      for (const auto& index : chunk_index_records_) {
        mcap::AppendRecord(out, Opcode::kChunkIndex, mcap::ChunkIndexContent(index));
      }
    });
    const std::uint64_t summary_offset_start = summary_start + out.size();
    for (const Group& g : groups) {
      std::vector<std::uint8_t> content;
      mcap::FieldWriter writer(content);
      writer.U8(static_cast<std::uint8_t>(g.opcode));
      writer.U64(g.start);
      writer.U64(g.length);
      mcap::AppendRecord(out, Opcode::kSummaryOffset, content);
    }
    End(std::move(out), summary_start, summary_offset_start);
  }

  static void AppendDataEnd(std::vector<std::uint8_t>& out) {
    mcap::FieldWriter data_end(out);
    data_end.U8(static_cast<std::uint8_t>(Opcode::kDataEnd));
    data_end.U64(4);
    data_end.U32(0);  // data section CRC: not computed
  }

  // Writes `out`, then the footer (summary_start 0: no summary section) and the closing magic;
  // syncs and closes the file.
  void End(std::vector<std::uint8_t> out, std::uint64_t summary_start,
           std::uint64_t summary_offset_start) {
    std::vector<std::uint8_t> footer;
    mcap::FieldWriter writer(footer);
    writer.U64(summary_start);
    writer.U64(summary_offset_start);
    writer.U32(0);  // summary CRC: not computed
    mcap::AppendRecord(out, Opcode::kFooter, footer);
    out.insert(out.end(), mcap::kMagic.begin(), mcap::kMagic.end());
    Put(out);
    if (std::fflush(stream_) != 0 || ::fsync(fileno(stream_)) != 0) Fail("cannot sync");
    if (std::fclose(stream_) != 0) {
      stream_ = nullptr;
      Fail("cannot close");
    }
    stream_ = nullptr;
  }

  struct IndexEntry {
    std::uint64_t log_time;
    std::uint64_t offset;  // into the chunk's uncompressed records
  };

  [[noreturn]] void Fail(const char* what) {
    const int error = errno;
    failed_ = true;
    throw FileFailure(path_, what, error);
  }

  // After a failed write (the disk full): cuts the file back to its last commit, every record of
  // which is on disk whole, and ends it there with a data end and a footer without summary, which
  // readers answer by scanning the data. The uncommitted messages are lost, as in a crash; the
  // file is valid MCAP. The ending takes 50 bytes: when the disk filled less than that after the
  // last commit, the file ends at the commit before it (one more second of the recording lost).
  void Salvage() {
    std::fflush(stream_);  // fails again; what it wrote beyond the commit is cut off below
    for (std::size_t k = commits_.size(); k-- > 0;) {
      std::clearerr(stream_);
      const std::uint64_t commit = commits_[k];
      if (::ftruncate(fileno(stream_), static_cast<off_t>(commit)) != 0 ||
          std::fseek(stream_, static_cast<long>(commit), SEEK_SET) != 0) {
        Fail("cannot cut the file back to its last commit");
      }
      position_ = commit;
      std::vector<std::uint8_t> out;
      AppendDataEnd(out);
      try {
        End(std::move(out), 0, 0);
        return;
      } catch (const Error&) {
        if (k == 0) throw;  // not even the header's ending fits
      }
    }
  }

  void Put(std::span<const std::uint8_t> bytes) {
    if (std::fwrite(bytes.data(), 1, bytes.size(), stream_) != bytes.size()) Fail("cannot write");
    position_ += bytes.size();
  }

  // Writes the open chunk, then one message index per channel in it.
  void CloseChunk() {
    if (chunk_records_.empty()) return;
    McapCompression compression = options_.compression;
    auto compressed = CompressChunk(chunk_records_, compression);
    // Camera frames arrive compressed already (JPEG, PNG): a chunk that does not shrink by a
    // tenth is stored as it is, so readers copy it straight from the file.
    if (compression != McapCompression::kNone &&
        compressed.size() * 10 > chunk_records_.size() * 9) {
      compression = McapCompression::kNone;
      compressed = chunk_records_;
    }
    mcap::ChunkIndex index;
    index.message_start_time = chunk_start_;
    index.message_end_time = chunk_end_;
    index.chunk_start_offset = position_;
    index.compression = McapCompressionName(compression);
    index.compressed_size = compressed.size();
    index.uncompressed_size = chunk_records_.size();

    std::vector<std::uint8_t> out;
    std::vector<std::uint8_t> content;
    mcap::FieldWriter chunk(content);
    chunk.U64(chunk_start_);
    chunk.U64(chunk_end_);
    chunk.U64(chunk_records_.size());
    chunk.U32(static_cast<std::uint32_t>(
        crc32(0, chunk_records_.data(), static_cast<uInt>(chunk_records_.size()))));
    chunk.String(index.compression);
    chunk.U64(compressed.size());
    chunk.Bytes(compressed);
    mcap::AppendRecord(out, Opcode::kChunk, content);
    index.chunk_length = out.size();

    for (const auto& [channel, entries] : chunk_indexes_) {
      index.message_index_offsets[channel] = position_ + out.size();
      content.clear();
      mcap::FieldWriter writer(content);
      writer.U16(channel);
      writer.U32(static_cast<std::uint32_t>(entries.size() * 16));
      for (const IndexEntry& entry : entries) {
        writer.U64(entry.log_time);
        writer.U64(entry.offset);
      }
      mcap::AppendRecord(out, Opcode::kMessageIndex, content);
    }
    index.message_index_length = out.size() - index.chunk_length;
    Put(out);
    chunk_index_records_.push_back(std::move(index));
    chunk_records_.clear();
    chunk_indexes_.clear();
  }

  std::filesystem::path path_;
  McapStorageOptions options_;
  std::FILE* stream_;
  std::uint64_t position_ = 0;
  std::vector<std::uint64_t> commits_;  // where each commit ended, on disk whole; first the header
  bool failed_ = false;                 // a write failed: Close salvages the last commit
  std::vector<mcap::Schema> schemas_;
  std::vector<mcap::Channel> channels_;
  mcap::Statistics statistics_;
  std::vector<std::uint8_t> chunk_records_;
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::map<std::uint16_t, std::vector<IndexEntry>> chunk_indexes_;
  std::vector<mcap::ChunkIndex> chunk_index_records_;
};

}  // namespace

std::unique_ptr<StorageFileWriter> CreateMcapStorage(const std::filesystem::path& file,
                                                     const McapStorageOptions& options) {
  return std::make_unique<McapStorageWriter>(file, options);
}

}  // namespace littermap::bag
