#pragma once
// The rosbag2 sqlite3 storage schema, version 4 (ROS 2 Iron and later): the tables, and the
// offered_qos_profiles text rosbag2 stores per topic.

#include <string>

namespace littermap::bag_schema {

inline constexpr int kSchemaVersion = 4;

inline constexpr const char* kCreateTables = R"sql(
CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);
CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL,
                      metadata TEXT NOT NULL);
CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,
                    serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL,
                    type_description_hash TEXT NOT NULL);
CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL,
                                 encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL,
                                 type_description_hash TEXT NOT NULL);
CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL,
                      timestamp INTEGER NOT NULL, data BLOB NOT NULL);
CREATE INDEX timestamp_idx ON messages (timestamp ASC);
)sql";

// rmw QoS enums as rosbag2 serialises them: reliability 1 reliable / 2 best effort,
// durability 1 transient local / 2 volatile, history 1 keep last; infinite durations.
inline std::string QosProfileYaml(int reliability, int durability) {
  const std::string infinite = "\n    sec: 9223372036\n    nsec: 854775807";
  return "- history: 1\n  depth: 10\n  reliability: " + std::to_string(reliability) +
         "\n  durability: " + std::to_string(durability) + "\n  deadline:" + infinite +
         "\n  lifespan:" + infinite + "\n  liveliness: 1\n  liveliness_lease_duration:" + infinite +
         "\n  avoid_ros_namespace_conventions: false";
}

}  // namespace littermap::bag_schema
