#pragma once
// One storage file of a bag, as BagReader and BagWriter see it whatever the storage: rosbag2's
// sqlite3 (.db3, bag/sqlite_storage.cpp) or MCAP (.mcap, bag/mcap_storage_reader.cpp and
// bag/mcap_storage_writer.cpp). Topic ids are the file's own.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bag/bag_info.hpp"
#include "core/time.hpp"

namespace littermap::bag {

struct StoredTopic {
  std::int64_t id = 0;
  TopicInfo info;  // message_count left 0: see TopicCount
};

struct TopicCount {
  std::int64_t id = 0;
  std::uint64_t count = 0;
  TimestampNs first_ns = 0;  // receive times of its first and last message
  TimestampNs last_ns = 0;
};

struct StoredMessage {
  std::int64_t topic_id = 0;
  TimestampNs timestamp_ns = 0;
  std::vector<std::uint8_t> data;
};

class StorageFileReader {
 public:
  virtual ~StorageFileReader() = default;
  virtual std::vector<StoredTopic> Topics() const = 0;
  virtual std::vector<TopicCount> Counts() = 0;
  virtual int SchemaVersion() const = 0;  // sqlite3 schema version; 0 for MCAP
  // Restarts at the first message of these topics (empty: all), in receive-time order.
  virtual void Start(const std::vector<std::int64_t>& topic_ids) = 0;
  // Receive time of the next message, or nullopt at the end.
  virtual std::optional<TimestampNs> PeekTime() = 0;
  virtual StoredMessage Take() = 0;  // only after PeekTime() gave a time
  // Whether chunk checksums are checked as chunks are read (MCAP; off by default: a checksum
  // costs as much as the rest of reading, and a damaged compressed chunk fails to decompress).
  virtual void SetVerifyChecksums(bool /*verify*/) {}
  // Damage that was skipped over (a corrupt chunk, a cut-off end), each naming file and offset.
  virtual std::vector<std::string> TakeWarnings() { return {}; }
};

// Opens a .db3 / an .mcap; BadInputError names the file when it is not one.
std::unique_ptr<StorageFileReader> OpenSqliteStorage(const std::filesystem::path& file);
std::unique_ptr<StorageFileReader> OpenMcapStorage(const std::filesystem::path& file);

class StorageFileWriter {
 public:
  virtual ~StorageFileWriter() = default;
  virtual std::int64_t AddTopic(const TopicInfo& topic) = 0;
  virtual void Write(std::int64_t topic_id, TimestampNs timestamp_ns,
                     std::span<const std::uint8_t> serialized) = 0;
  virtual void Commit() = 0;  // everything written so far is on disk when this returns
  // Commits and finishes the file; `info` is the bag's metadata for storages that embed it.
  virtual void Close(const BagInfo& info) = 0;
  virtual const std::filesystem::path& file() const = 0;
};

// Creates a new storage file (which must not exist); BagWriter chooses the storage.
std::unique_ptr<StorageFileWriter> CreateSqliteStorage(const std::filesystem::path& file,
                                                       const std::string& ros_distro);
struct McapStorageOptions;  // bag/mcap_storage_writer.hpp
std::unique_ptr<StorageFileWriter> CreateMcapStorage(const std::filesystem::path& file,
                                                     const McapStorageOptions& options);

}  // namespace littermap::bag
