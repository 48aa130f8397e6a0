#pragma once
// Writes a ROS 2 bag directory with rosbag2's sqlite3 storage (schema version 4, as Iron and
// later write it) or its MCAP storage: BAG/BAG_0.db3 or BAG/BAG_0.mcap and, on Close(),
// BAG/metadata.yaml.
//
// Crash safety: the writer commits at least every commit_interval_ms (sqlite3: a WAL
// transaction; MCAP: the open chunk is written and the file synced), so a recording killed by
// SIGKILL or a power cut keeps every message up to the last commit; BagReader rebuilds the
// metadata a crash left unwritten.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "bag/bag_info.hpp"
#include "bag/mcap_storage_writer.hpp"
#include "bag/ros_codec.hpp"
#include "core/time.hpp"

namespace littermap::bag {

struct BagWriterOptions {
  std::int64_t commit_interval_ms = 1000;  // longest time a written message stays uncommitted
  std::string ros_distro = "littermap";    // recorded in the schema table and metadata.yaml
  std::string storage = "sqlite3";         // "sqlite3" | "mcap"
  McapStorageOptions mcap;                 // with storage "mcap"
};

// QoS presets for offered_qos_profiles, so `ros2 bag play` republishes topics sensibly.
enum class TopicQos { kSensorData, kReliable, kLatched };

class BagWriter {
 public:
  // Creates the bag directory (which must not exist yet, or be empty). Throws UsageError if it
  // holds files, InternalError if it cannot be created.
  BagWriter(const std::filesystem::path& directory, BagWriterOptions options = {});
  ~BagWriter();  // closes; errors at that point are swallowed, so call Close() to see them
  BagWriter(const BagWriter&) = delete;
  BagWriter& operator=(const BagWriter&) = delete;

  // Registers a topic (idempotent for the same name and type; a different type is a UsageError).
  void AddTopic(const std::string& name, const std::string& type, TopicQos qos,
                std::string_view message_definition = {});
  // Registers a topic as another bag holds it: type, serialization format, QoS, type hash and
  // message definition kept as they are (message_count is ignored).
  void AddTopic(const TopicInfo& topic);
  template <typename M>
  void AddTopic(const std::string& name, TopicQos qos = TopicQos::kSensorData) {
    AddTopic(name, std::string(MessageTraits<M>::kTypeName), qos, MessageTraits<M>::Definition());
  }

  // Writes one serialized (CDR) message on a registered topic at receive time timestamp_ns.
  void Write(const std::string& topic, TimestampNs timestamp_ns,
             std::span<const std::uint8_t> serialized);
  template <typename M>
  void WriteMessage(const std::string& topic, TimestampNs timestamp_ns, const M& message) {
    Write(topic, timestamp_ns, Encode(message));
  }

  // Commits what has been written so far.
  void Flush();
  // Commits, writes metadata.yaml and closes the database. Idempotent.
  void Close();

  const std::filesystem::path& directory() const;
  std::uint64_t message_count() const;
  std::uint64_t bytes_written() const;  // serialized payload bytes

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace littermap::bag
