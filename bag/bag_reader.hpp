#pragma once
// Reads a ROS 2 bag directory with sqlite3 storage written by littermap or by any ROS 2 release
// since Foxy (older schemas lack the schema/metadata/message_definitions tables and some topic
// columns). Messages come in receive-time order, optionally filtered by topic, merged across
// split files. Without metadata.yaml the metadata is rebuilt from the databases, as
// `ros2 bag reindex` does.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bag/bag_info.hpp"
#include "core/time.hpp"

namespace littermap::bag {

struct BagMessage {
  const TopicInfo* topic = nullptr;  // points into BagReader::info().topics
  TimestampNs timestamp_ns = 0;      // receive time
  std::uint64_t index = 0;           // 0-based position of this message within its topic
  std::vector<std::uint8_t> data;    // serialized message (CDR)
};

class BagReader {
 public:
  // Opens a bag directory (or a single .db3 file). Throws BadInputError when the directory has
  // no .db3, a database is not a rosbag2 database, or metadata.yaml is malformed.
  explicit BagReader(const std::filesystem::path& path);
  ~BagReader();
  BagReader(const BagReader&) = delete;
  BagReader& operator=(const BagReader&) = delete;

  // Metadata; message counts and times are read from the databases, so they are right even
  // after a crash left metadata.yaml missing or stale.
  const BagInfo& info() const;
  bool metadata_rebuilt() const;  // true when metadata.yaml was missing or disagreed
  const std::filesystem::path& directory() const;
  // The topic's metadata. Throws BadInputError "BAG: no ROLE topic NAME" when the bag lacks it.
  const TopicInfo& RequireTopic(const std::string& name, const std::string& role) const;

  // Restricts Next() to these topics (empty: all) and restarts from the first message.
  void SetTopicFilter(const std::vector<std::string>& topics);
  // The next message in time order (ties in write order), or nullopt at the end.
  std::optional<BagMessage> Next();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace littermap::bag
