#pragma once
// Reads a ROS 2 bag directory written by littermap or by any ROS 2 release since Foxy, with
// sqlite3 storage (bag/sqlite_storage.cpp) or MCAP storage (bag/mcap_storage_reader.cpp), split
// into several files or not. Messages come in receive-time order, optionally filtered by topic,
// merged across split files. Without metadata.yaml the metadata is rebuilt from the storage
// files, as `ros2 bag reindex` does.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bag/bag_info.hpp"
#include "bag/header_stamps.hpp"
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
  // Opens a bag directory (or a single .db3 or .mcap file). Throws BadInputError when the
  // directory has no storage file, a file is neither a rosbag2 database nor an MCAP file, or
  // metadata.yaml is malformed.
  explicit BagReader(const std::filesystem::path& path);
  ~BagReader();
  BagReader(const BagReader&) = delete;
  BagReader& operator=(const BagReader&) = delete;

  // Metadata; message counts and times are read from the storage files, so they are right even
  // after a crash left metadata.yaml missing or stale.
  const BagInfo& info() const;
  bool metadata_rebuilt() const;  // true when metadata.yaml was missing or disagreed
  const std::filesystem::path& directory() const;
  // Damage read past so far, each naming file and offset: a corrupt MCAP chunk whose messages
  // were skipped, a recording cut off mid-record. Grows as Next() reads on.
  const std::vector<std::string>& warnings() const;
  // Of the warnings, the damage alone (not the stamp disagreements), each reported once.
  const std::vector<std::string>& damage() const;
  // The topic's metadata. Throws BadInputError "BAG: no ROLE topic NAME" when the bag lacks it.
  const TopicInfo& RequireTopic(const std::string& name, const std::string& role) const;

  // Which stamp the header of each message Next() returns carries (bag/header_stamps.hpp):
  // kRecorded writes the recording stamp into it. Either way a topic whose header and
  // recording stamps disagree by more than a second adds a warning.
  void SetStampSource(StampSource source);

  // Checks the checksums of MCAP chunks as they are read (`info --verify`); a chunk that fails
  // is skipped with a warning. Off by default. Restarts from the first message.
  void SetVerifyChecksums(bool verify);

  // Restricts Next() to these topics (empty: all) and restarts from the first message.
  void SetTopicFilter(const std::vector<std::string>& topics);
  // The next message in time order (ties in write order), or nullopt at the end.
  std::optional<BagMessage> Next();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace littermap::bag
