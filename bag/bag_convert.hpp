#pragma once
// Copies a bag into another storage (sqlite3 <-> MCAP), or the same one with fewer topics:
// every message with its receive stamp and bytes, every topic with its type, serialization
// format, QoS profiles, type hash and message definition. A conversion that fails removes what
// it wrote.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bag/bag_writer.hpp"
#include "core/progress.hpp"

namespace littermap::bag {

struct ConvertOptions {
  std::string storage = "mcap";     // of the output: "sqlite3" | "mcap"
  McapStorageOptions mcap;          // with storage "mcap"
  std::vector<std::string> topics;  // copy only these (each must be in the input); empty: all
};

struct ConvertResult {
  std::uint64_t message_count = 0;
  std::size_t topic_count = 0;
  std::uint64_t output_bytes = 0;     // of the storage files written
  std::vector<std::string> warnings;  // damage in the input that was read past
};

ConvertResult ConvertBag(const std::filesystem::path& input, const std::filesystem::path& output,
                         const ConvertOptions& options, const ProgressCallback& progress);

}  // namespace littermap::bag
