#pragma once
// What a run bag holds, for people and scripts, like `ros2 bag info`: its files, size, start,
// end and duration, and each topic's type and message count. Counts and times come from the
// database (bag/bag_reader.hpp), so an interrupted recording still reads correctly.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bag/bag_info.hpp"
#include "core/progress.hpp"
#include "core/time.hpp"

namespace littermap::bag {

struct BagSummaryOptions {
  bool reindex = false;  // rewrite metadata.yaml from the database, in littermap's layout
  bool verify = false;   // decode every message (bag/verify_messages.hpp)
};

struct BagSummary {
  std::string path;  // the bag directory
  BagInfo info;
  std::uint64_t size_bytes = 0;   // of the database files
  bool metadata_rebuilt = false;  // metadata.yaml was missing or out of date when opened
  std::optional<std::uint64_t> verified_message_count;  // with verify: messages that decoded
  std::vector<std::string> damage;  // with verify: damage read past, naming file and offset
};

// Opens the bag directory (or one .db3 file). Warns first when its metadata.yaml is missing or
// out of date, then reindexes and verifies as asked; verification reports progress and warns
// once per topic of an unused type. Throws BadInputError for what is not a bag and for a message
// that does not decode (naming topic and index).
BagSummary SummariseBag(const std::filesystem::path& bag, const BagSummaryOptions& options = {},
                        const ProgressCallback& progress = {}, const WarningCallback& warn = {});

// A JSON object, 2-space indent, no final newline. Stable keys: path, storage_identifier,
// schema_version, size_bytes, files, message_count, start_ns, end_ns, duration_s, start_utc,
// end_utc, metadata_rebuilt, topics[] (name, type, serialization_format, message_count),
// sensor_roles (role -> found, and topic or candidates; bag/sensor_roles.hpp) and, when
// verified, verified_message_count and damage[].
std::string ToJson(const BagSummary& summary);

// The `ros2 bag info` layout and which topic fills each sensor role, every line ending in "\n".
std::string ToText(const BagSummary& summary);

// Bytes in binary units with one decimal: "744.0 KiB".
std::string HumanSize(std::uint64_t bytes);

// UTC with nanoseconds: "2026-11-22T02:10:52.123456789Z".
std::string IsoTimeUtc(TimestampNs t);

}  // namespace littermap::bag
