#include "bag/bag_info.hpp"

#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "core/output_file.hpp"
#include "core/yaml_fields.hpp"

namespace littermap::bag {
namespace {

// rosbag2's root key of metadata.yaml.
constexpr const char* kRoot = "rosbag2_bagfile_information";

YAML::Node Nanoseconds(TimestampNs value) {
  YAML::Node node;
  node["nanoseconds"] = value;
  return node;
}

YAML::Node SinceEpoch(TimestampNs value) {
  YAML::Node node;
  node["nanoseconds_since_epoch"] = value;
  return node;
}

// Reads node[key] as T, throwing BadInputError naming the file and the field's path.
template <typename T>
T Field(const YAML::Node& node, const char* key, const std::string& where) {
  const YAML::Node value = node[key];
  if (!value) throw BadInputError(where + ": missing field '" + key + "'");
  try {
    return value.as<T>();
  } catch (const YAML::Exception& e) {
    throw BadInputError(where + ": field '" + key + "' has the wrong type (line " +
                        std::to_string(e.mark.line + 1) + ")");
  }
}

template <typename T>
T OptionalField(const YAML::Node& node, const char* key, const std::string& where, T fallback) {
  return node[key] ? Field<T>(node, key, where) : fallback;
}

TopicInfo ParseTopic(const YAML::Node& entry, const std::string& where) {
  const YAML::Node metadata = entry["topic_metadata"];
  if (!metadata) throw BadInputError(where + ": missing field 'topic_metadata'");
  TopicInfo topic;
  topic.name = Field<std::string>(metadata, "name", where);
  topic.type = Field<std::string>(metadata, "type", where);
  topic.serialization_format = Field<std::string>(metadata, "serialization_format", where);
  if (metadata["offered_qos_profiles"] && metadata["offered_qos_profiles"].IsScalar()) {
    topic.offered_qos_profiles = metadata["offered_qos_profiles"].as<std::string>();
  }
  topic.type_description_hash =
      OptionalField<std::string>(metadata, "type_description_hash", where, "");
  topic.message_count = Field<std::uint64_t>(entry, "message_count", where);
  return topic;
}

BagInfo ParseMetadata(const YAML::Node& document, const std::string& where) {
  const YAML::Node root = document[kRoot];
  if (!root) throw BadInputError(where + ": missing '" + kRoot + "' (not a rosbag2 metadata file)");
  BagInfo info;
  info.version = Field<int>(root, "version", where);
  info.storage_identifier = Field<std::string>(root, "storage_identifier", where);
  info.duration_ns = Field<TimestampNs>(root["duration"], "nanoseconds", where + ": duration");
  info.starting_time_ns = Field<TimestampNs>(root["starting_time"], "nanoseconds_since_epoch",
                                             where + ": starting_time");
  info.message_count = Field<std::uint64_t>(root, "message_count", where);
  info.ros_distro = OptionalField<std::string>(root, "ros_distro", where, "");
  const YAML::Node topics = root["topics_with_message_count"];
  if (topics && !topics.IsSequence() && !topics.IsNull()) {
    throw BadInputError(where + ": 'topics_with_message_count' is not a list");
  }
  for (const auto& entry : topics) info.topics.push_back(ParseTopic(entry, where));
  for (const auto& path : Field<std::vector<std::string>>(root, "relative_file_paths", where)) {
    info.files.push_back({path, 0, 0, 0});
  }
  return info;
}

}  // namespace

const TopicInfo* BagInfo::FindTopic(const std::string& name) const {
  for (const auto& topic : topics) {
    if (topic.name == name) return &topic;
  }
  return nullptr;
}

BagInfo ReadMetadataYaml(const std::filesystem::path& path) {
  const YAML::Node root = LoadYamlFile(path);
  try {
    return ParseMetadata(root, path.string());
  } catch (const YAML::Exception& e) {
    throw BadInputError(path.string() + ": line " + std::to_string(e.mark.line + 1) +
                        ": malformed YAML: " + e.msg);
  }
}

std::string MetadataYamlText(const BagInfo& info) {
  YAML::Node root;
  root["version"] = info.version;
  root["storage_identifier"] = info.storage_identifier;
  root["duration"] = Nanoseconds(info.duration_ns);
  root["starting_time"] = SinceEpoch(info.starting_time_ns);
  root["message_count"] = info.message_count;
  root["topics_with_message_count"] = YAML::Node(YAML::NodeType::Sequence);
  for (const auto& topic : info.topics) {
    YAML::Node entry;
    entry["topic_metadata"]["name"] = topic.name;
    entry["topic_metadata"]["type"] = topic.type;
    entry["topic_metadata"]["serialization_format"] = topic.serialization_format;
    entry["topic_metadata"]["offered_qos_profiles"] = topic.offered_qos_profiles;
    entry["topic_metadata"]["type_description_hash"] = topic.type_description_hash;
    entry["message_count"] = topic.message_count;
    root["topics_with_message_count"].push_back(entry);
  }
  root["compression_format"] = "";
  root["compression_mode"] = "";
  root["relative_file_paths"] = YAML::Node(YAML::NodeType::Sequence);
  root["files"] = YAML::Node(YAML::NodeType::Sequence);
  for (const auto& file : info.files) {
    root["relative_file_paths"].push_back(file.relative_path);
    YAML::Node entry;
    entry["path"] = file.relative_path;
    entry["starting_time"] = SinceEpoch(file.starting_time_ns);
    entry["duration"] = Nanoseconds(file.duration_ns);
    entry["message_count"] = file.message_count;
    root["files"].push_back(entry);
  }
  root["custom_data"] = YAML::Node(YAML::NodeType::Map);
  root["ros_distro"] = info.ros_distro;
  YAML::Node document;
  document[kRoot] = root;
  YAML::Emitter out;
  out << document;
  return std::string(out.c_str()) + "\n";
}

void WriteMetadataYaml(const std::filesystem::path& path, const BagInfo& info) {
  // A crash never leaves a half-written metadata.yaml.
  WriteFileAtomically(path, MetadataYamlText(info));
}

}  // namespace littermap::bag
