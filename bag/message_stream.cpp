#include "bag/message_stream.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace littermap::bag {
namespace {

// Tries each alternative of AnyMessage whose ROS type name matches.
template <std::size_t I = 0>
bool DecodeAny(const BagReader& reader, const BagMessage& raw, AnyMessage& out) {
  if constexpr (I == std::variant_size_v<AnyMessage>) {
    return false;
  } else {
    using M = std::variant_alternative_t<I, AnyMessage>;
    if (raw.topic->type == MessageTraits<M>::kTypeName) {
      out = DecodeBagMessage<M>(reader, raw);
      return true;
    }
    return DecodeAny<I + 1>(reader, raw, out);
  }
}

// Both kinds of message carry their topic, index and time under the same names.
template <typename Message>
std::string OriginOf(const BagReader& reader, const Message& message) {
  return reader.directory().string() + ": topic '" + message.topic->name + "' message #" +
         std::to_string(message.index) + " (t=" + std::to_string(message.timestamp_ns) + " ns)";
}

}  // namespace

std::string MessageOrigin(const BagReader& reader, const BagMessage& message) {
  return OriginOf(reader, message);
}

std::string MessageOrigin(const BagReader& reader, const DecodedMessage& message) {
  return OriginOf(reader, message);
}

void ThrowUndecodable(const BagReader& reader, const BagMessage& message,
                      const std::string& reason) {
  throw BadInputError(MessageOrigin(reader, message) + ": " + reason);
}

void ThrowUndecodable(const BagReader& reader, const DecodedMessage& message,
                      const std::string& reason) {
  throw BadInputError(MessageOrigin(reader, message) + ": " + reason);
}

std::optional<DecodedMessage> MessageStream::Next() {
  while (auto raw = reader_.Next()) {
    if (raw->topic->serialization_format != "cdr") {
      ThrowUndecodable(reader_, *raw,
                       "serialization format '" + raw->topic->serialization_format +
                           "' is not supported (only cdr)");
    }
    DecodedMessage decoded;
    if (!DecodeAny(reader_, *raw, decoded.message)) {
      const std::string& name = raw->topic->name;
      if (std::find(warned_topics_.begin(), warned_topics_.end(), name) == warned_topics_.end()) {
        warned_topics_.push_back(name);
        warnings_.push_back(name + ": type " + raw->topic->type + " is not used; skipped");
      }
      continue;
    }
    if (const auto* scan = std::get_if<msg::LaserScan>(&decoded.message)) {
      // A scan whose beams have no directions cannot be used: refused like a damaged message
      // rather than left for the tracker to skip without a word.
      if (!std::isfinite(scan->angle_min) || !std::isfinite(scan->angle_increment)) {
        ThrowUndecodable(reader_, *raw,
                         "LaserScan angle_min " + std::to_string(scan->angle_min) +
                             " and angle_increment " + std::to_string(scan->angle_increment) +
                             " give its beams no directions");
      }
    }
    decoded.topic = raw->topic;
    decoded.timestamp_ns = raw->timestamp_ns;
    decoded.index = raw->index;
    return decoded;
  }
  return std::nullopt;
}

}  // namespace littermap::bag
