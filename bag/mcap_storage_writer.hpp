#pragma once
// Options of the MCAP storage that BagWriter writes with `storage = "mcap"`.
//
// The file is laid out as rosbag2's MCAP storage writes it: profile "ros2", one schema per
// message type (encoding "ros2msg", the message definition), one channel per topic (message
// encoding "cdr", its QoS in the channel metadata "offered_qos_profiles"), messages in chunks
// followed by their message indexes, and on Close() the summary (schemas, channels, statistics,
// chunk indexes) with its summary offsets. Schemas and channels go to the data section as
// written, outside any chunk, and each commit closes the open chunk and syncs the file: a
// recording cut off at any moment reads back (by a linear scan) up to its last commit.

#include <cstdint>

#include "bag/mcap_compression.hpp"

namespace littermap::bag {

struct McapStorageOptions {
  // Of chunks that shrink by a tenth at least; others are stored uncompressed.
  McapCompression compression = McapCompression::kZstd;
  std::uint64_t chunk_size_bytes = 1 << 20;  // a chunk closes once its records reach this size
};

}  // namespace littermap::bag
