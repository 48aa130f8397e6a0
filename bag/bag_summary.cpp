#include "bag/bag_summary.hpp"

#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <nlohmann/json.hpp>

#include "bag/bag_reader.hpp"
#include "bag/sensor_roles.hpp"
#include "bag/verify_messages.hpp"

namespace littermap::bag {
namespace {

constexpr const char* kIndent = "                   ";  // under the values of ToText

__attribute__((format(printf, 1, 2))) std::string Format(const char* format, ...) {
  char text[256];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(text, sizeof(text), format, arguments);
  va_end(arguments);
  return text;
}

std::uint64_t SizeBytes(const BagReader& reader) {
  std::uint64_t size = 0;
  std::error_code error;
  for (const auto& file : reader.info().files) {
    size += std::filesystem::file_size(reader.directory() / file.relative_path, error);
  }
  return size;
}

void Warn(const WarningCallback& warn, const std::string& warning) {
  if (warn) warn(warning);
}

// Seconds with all nine digits of the stamp, from the integer (a double rounds 1.7e18 ns to
// 256 ns).
std::string ExactSeconds(TimestampNs ns) {
  const bool negative = ns < 0;
  const unsigned long long magnitude =
      negative ? 0ull - static_cast<unsigned long long>(ns) : static_cast<unsigned long long>(ns);
  return Format("%s%llu.%09llu", negative ? "-" : "", magnitude / 1000000000ull,
                magnitude % 1000000000ull);
}

}  // namespace

BagSummary SummariseBag(const std::filesystem::path& bag, const BagSummaryOptions& options,
                        const ProgressCallback& progress, const WarningCallback& warn) {
  BagReader reader(bag);
  std::error_code error;
  if (std::filesystem::is_regular_file(bag, error) && !reader.metadata_rebuilt()) {
    Warn(warn, bag.string() + ": one file of the bag " + reader.directory().string() +
                   "; the whole bag is shown (name the folder to silence this)");
  }
  if (reader.metadata_rebuilt()) {
    Warn(warn, bag.string() +
                   ": metadata.yaml is missing or out of date (was the recording interrupted?); "
                   "figures are rebuilt from the database" +
                   (options.reindex ? "" : " (--reindex rewrites it)"));
  }
  if (options.reindex) {
    BagInfo rebuilt = reader.info();
    rebuilt.version = BagInfo{}.version;  // written in littermap's (Iron) layout
    WriteMetadataYaml(reader.directory() / "metadata.yaml", rebuilt);
  }
  BagSummary summary;
  if (options.verify) {
    const VerifyResult verified = VerifyMessages(reader, progress);
    for (const std::string& warning : verified.warnings) Warn(warn, warning);
    summary.verified_message_count = verified.decoded_messages;
    summary.damage = verified.damage;
  }
  summary.path = reader.directory().string();
  summary.info = reader.info();
  summary.size_bytes = SizeBytes(reader);
  summary.metadata_rebuilt = reader.metadata_rebuilt();
  return summary;
}

std::string ToJson(const BagSummary& summary) {
  const BagInfo& info = summary.info;
  const TimestampNs end_ns = info.starting_time_ns + info.duration_ns;
  nlohmann::json json;
  json["path"] = summary.path;
  json["storage_identifier"] = info.storage_identifier;
  json["schema_version"] = info.schema_version;
  json["size_bytes"] = summary.size_bytes;
  json["files"] = nlohmann::json::array();
  for (const auto& file : info.files) json["files"].push_back(file.relative_path);
  json["message_count"] = info.message_count;
  json["start_ns"] = info.starting_time_ns;
  json["end_ns"] = end_ns;
  json["duration_s"] = ToSeconds(info.duration_ns);
  json["start_utc"] = IsoTimeUtc(info.starting_time_ns);
  json["end_utc"] = IsoTimeUtc(end_ns);
  json["metadata_rebuilt"] = summary.metadata_rebuilt;
  json["topics"] = nlohmann::json::array();
  for (const auto& topic : info.topics) {
    json["topics"].push_back({{"name", topic.name},
                              {"type", topic.type},
                              {"serialization_format", topic.serialization_format},
                              {"message_count", topic.message_count}});
  }
  const SensorRoles roles = FindSensorRoles(info);
  nlohmann::json& role_json = json["sensor_roles"] = nlohmann::json::object();
  for (const auto& [role, found] : roles.found) {
    role_json[role] = {{"found", found}};
    if (found == "ambiguous") {
      role_json[role]["candidates"] = roles.candidates.at(role);
    } else if (found != "missing") {
      role_json[role]["topic"] = TopicOf(roles, role);
    }
  }
  if (summary.verified_message_count) {
    json["verified_message_count"] = *summary.verified_message_count;
    json["damage"] = summary.damage;
  }
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ToText(const BagSummary& summary) {
  const BagInfo& info = summary.info;
  const TimestampNs end_ns = info.starting_time_ns + info.duration_ns;
  std::string text = "Files:             ";
  for (std::size_t i = 0; i < info.files.size(); ++i) {
    text += (i ? kIndent : "") + info.files[i].relative_path + "\n";
  }
  text += "Bag size:          " + HumanSize(summary.size_bytes) + "\n";
  text += "Storage id:        " + info.storage_identifier +
          (info.storage_identifier == "sqlite3" ? Format(" (schema %d)", info.schema_version)
                                                : std::string()) +
          "\n";
  text += Format("Duration:          %.3fs\n", ToSeconds(info.duration_ns));
  text += "Start:             " + IsoTimeUtc(info.starting_time_ns) + " (" +
          ExactSeconds(info.starting_time_ns) + ")\n";
  text += "End:               " + IsoTimeUtc(end_ns) + " (" + ExactSeconds(end_ns) + ")\n";
  text += Format("Messages:          %llu\n", static_cast<unsigned long long>(info.message_count));
  text += "Topic information: ";
  for (std::size_t i = 0; i < info.topics.size(); ++i) {
    const TopicInfo& topic = info.topics[i];
    text += (i ? kIndent : "") + ("Topic: " + topic.name) + " | Type: " + topic.type +
            " | Count: " + std::to_string(topic.message_count) +
            " | Serialization Format: " + topic.serialization_format + "\n";
  }
  if (info.topics.empty()) text += "\n";
  const auto roles = DescribeSensorRoles(FindSensorRoles(info));
  for (std::size_t i = 0; i < roles.size(); ++i) {
    text += (i ? kIndent : "Sensor roles:      ") + roles[i] + "\n";
  }
  if (summary.verified_message_count) {
    text += Format("Verified:          %llu messages decode\n",
                   static_cast<unsigned long long>(*summary.verified_message_count));
    for (std::size_t i = 0; i < summary.damage.size(); ++i) {
      text += (i ? kIndent : "Damaged:           ") + summary.damage[i] + "\n";
    }
  }
  return text;
}

std::string HumanSize(std::uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 4) {
    value /= 1024.0;
    ++unit;
  }
  return Format("%.1f %s", value, units[unit]);
}

std::string IsoTimeUtc(TimestampNs t) {
  const std::time_t seconds = static_cast<std::time_t>(t / kNanosecondsPerSecond);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char date[32];
  std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%S", &utc);
  return Format("%s.%09lldZ", date, static_cast<long long>(t % kNanosecondsPerSecond));
}

}  // namespace littermap::bag
