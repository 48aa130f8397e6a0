#pragma once
// What a run bag holds: the rosbag2 metadata (metadata.yaml) as a plain struct.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/time.hpp"

namespace littermap::bag {

struct TopicInfo {
  std::string name;  // "/scan"
  std::string type;  // "sensor_msgs/msg/LaserScan"
  std::string serialization_format = "cdr";
  std::string offered_qos_profiles;  // rosbag2's YAML text; empty when unknown
  std::string type_description_hash;
  std::string message_definition;  // the type's ros2msg text as the bag stores it; may be empty
  std::uint64_t message_count = 0;
};

struct BagFileInfo {
  std::string relative_path;  // relative to the bag directory
  TimestampNs starting_time_ns = 0;
  TimestampNs duration_ns = 0;
  std::uint64_t message_count = 0;
};

struct BagInfo {
  int version = 8;  // metadata.yaml version (rosbag2 Iron layout)
  std::string storage_identifier = "sqlite3";
  TimestampNs starting_time_ns = 0;  // first message; 0 for an empty bag
  TimestampNs duration_ns = 0;       // last minus first message
  std::uint64_t message_count = 0;
  std::vector<TopicInfo> topics;
  std::vector<BagFileInfo> files;
  std::string ros_distro;
  int schema_version = 0;  // rosbag2 sqlite schema: 0 (Foxy and older) .. 4 (Iron and later)

  const TopicInfo* FindTopic(const std::string& name) const;
};

// metadata.yaml <-> BagInfo. Reading throws BadInputError naming the file and field.
BagInfo ReadMetadataYaml(const std::filesystem::path& path);
std::string MetadataYamlText(const BagInfo& info);
void WriteMetadataYaml(const std::filesystem::path& path, const BagInfo& info);

}  // namespace littermap::bag
