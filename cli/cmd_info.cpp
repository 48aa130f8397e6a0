// littermap info BAG [--json] [--reindex]: what a run bag holds, like `ros2 bag info`.

#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "bag/bag_reader.hpp"
#include "bag/message_stream.hpp"
#include "cli/cli_context.hpp"

namespace littermap::cli {
namespace {

struct InfoArguments {
  std::string bag;
  bool json = false;
  bool reindex = false;
  bool verify = false;
};

std::uint64_t BagSizeBytes(const bag::BagReader& reader) {
  std::uint64_t size = 0;
  std::error_code error;
  for (const auto& file : reader.info().files) {
    size += std::filesystem::file_size(reader.directory() / file.relative_path, error);
  }
  return size;
}

std::string HumanSize(std::uint64_t bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 4) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %s", value, units[unit]);
  return text;
}

// "2026-11-22T02:10:52.123456789Z" (UTC).
std::string IsoTime(TimestampNs t) {
  const std::time_t seconds = static_cast<std::time_t>(t / kNanosecondsPerSecond);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char date[32];
  std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%S", &utc);
  char text[64];
  std::snprintf(text, sizeof(text), "%s.%09lldZ", date,
                static_cast<long long>(t % kNanosecondsPerSecond));
  return text;
}

nlohmann::json InfoJson(const bag::BagReader& reader) {
  const bag::BagInfo& info = reader.info();
  nlohmann::json json;
  json["path"] = reader.directory().string();
  json["storage_identifier"] = info.storage_identifier;
  json["schema_version"] = info.schema_version;
  json["size_bytes"] = BagSizeBytes(reader);
  json["files"] = nlohmann::json::array();
  for (const auto& file : info.files) json["files"].push_back(file.relative_path);
  json["message_count"] = info.message_count;
  json["start_ns"] = info.starting_time_ns;
  json["end_ns"] = info.starting_time_ns + info.duration_ns;
  json["duration_s"] = ToSeconds(info.duration_ns);
  json["start_utc"] = IsoTime(info.starting_time_ns);
  json["end_utc"] = IsoTime(info.starting_time_ns + info.duration_ns);
  json["metadata_rebuilt"] = reader.metadata_rebuilt();
  json["topics"] = nlohmann::json::array();
  for (const auto& topic : info.topics) {
    json["topics"].push_back({{"name", topic.name},
                              {"type", topic.type},
                              {"serialization_format", topic.serialization_format},
                              {"message_count", topic.message_count}});
  }
  return json;
}

void PrintText(const bag::BagReader& reader) {
  const bag::BagInfo& info = reader.info();
  std::printf("Files:             ");
  for (std::size_t i = 0; i < info.files.size(); ++i) {
    std::printf("%s%s\n", i ? "                   " : "", info.files[i].relative_path.c_str());
  }
  std::printf("Bag size:          %s\n", HumanSize(BagSizeBytes(reader)).c_str());
  std::printf("Storage id:        %s (schema %d)\n", info.storage_identifier.c_str(),
              info.schema_version);
  std::printf("Duration:          %.3fs\n", ToSeconds(info.duration_ns));
  std::printf("Start:             %s (%.9f)\n", IsoTime(info.starting_time_ns).c_str(),
              ToSeconds(info.starting_time_ns));
  std::printf("End:               %s (%.9f)\n",
              IsoTime(info.starting_time_ns + info.duration_ns).c_str(),
              ToSeconds(info.starting_time_ns + info.duration_ns));
  std::printf("Messages:          %llu\n", static_cast<unsigned long long>(info.message_count));
  std::printf("Topic information: ");
  for (std::size_t i = 0; i < info.topics.size(); ++i) {
    const bag::TopicInfo& topic = info.topics[i];
    std::printf("%sTopic: %s | Type: %s | Count: %llu | Serialization Format: %s\n",
                i ? "                   " : "", topic.name.c_str(), topic.type.c_str(),
                static_cast<unsigned long long>(topic.message_count),
                topic.serialization_format.c_str());
  }
  if (info.topics.empty()) std::printf("\n");
}

// Decodes every message of a known type; the first one that does not decode is a BadInputError
// naming topic and index (exit 2). Returns how many messages decoded.
std::uint64_t VerifyMessages(bag::BagReader& reader, CliContext& context) {
  bag::MessageStream stream(reader);
  const ProgressCallback progress = context.Progress();
  const std::uint64_t total = reader.info().message_count;
  std::uint64_t decoded = 0;
  while (stream.Next()) {
    ++decoded;
    if (decoded % 256 == 0) ReportProgress(progress, {"verifying", decoded, total});
  }
  context.FinishProgress();
  for (const auto& warning : stream.warnings()) context.Warn(warning);
  return decoded;
}

void RunInfo(const InfoArguments& arguments, CliContext& context) {
  bag::BagReader reader(arguments.bag);
  if (reader.metadata_rebuilt()) {
    context.Warn(arguments.bag +
                 ": metadata.yaml is missing or out of date (was the recording interrupted?); "
                 "figures are rebuilt from the database" +
                 (arguments.reindex ? "" : " (--reindex rewrites it)"));
  }
  if (arguments.reindex) {
    bag::BagInfo rebuilt = reader.info();
    rebuilt.version = bag::BagInfo{}.version;  // written in littermap's (Iron) layout
    bag::WriteMetadataYaml(reader.directory() / "metadata.yaml", rebuilt);
  }
  std::optional<std::uint64_t> verified;
  if (arguments.verify) verified = VerifyMessages(reader, context);
  if (arguments.json) {
    nlohmann::json json = InfoJson(reader);
    if (verified) json["verified_message_count"] = *verified;
    std::cout << json.dump(2) << "\n";
  } else {
    PrintText(reader);
    if (verified) {
      std::printf("Verified:          %llu messages decode\n",
                  static_cast<unsigned long long>(*verified));
    }
  }
}

}  // namespace

void RegisterInfoCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<InfoArguments>();
  CLI::App* info =
      context.AddCommand(app, "info", "Show the topics, counts and duration of a run bag");
  info->add_option("BAG", arguments->bag, "Bag directory (or one .db3 file)")->required();
  info->add_flag("--json", arguments->json, "Machine-readable output with stable keys");
  info->add_flag("--reindex", arguments->reindex,
                 "Rewrite metadata.yaml from the database (after an interrupted recording)");
  info->add_flag("--verify", arguments->verify,
                 "Decode every message; a damaged one is an error naming topic and index");
  info->callback([arguments, &context] {
    context.run = [arguments, &context] { RunInfo(*arguments, context); };
  });
}

}  // namespace littermap::cli
