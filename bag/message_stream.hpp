#pragma once
// Decoded messages from a bag in time order. Types littermap does not know are skipped with one
// warning per topic; a message that does not decode is a BadInputError naming the bag, topic and
// message index, never a crash.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bag/bag_reader.hpp"
#include "bag/ros_codec.hpp"

namespace littermap::bag {

using AnyMessage =
    std::variant<msg::LaserScan, msg::Odometry, msg::CompressedImage, msg::Image, msg::CameraInfo,
                 msg::Imu, msg::NavSatFix, msg::TFMessage, msg::String>;

struct DecodedMessage {
  const TopicInfo* topic = nullptr;
  TimestampNs timestamp_ns = 0;
  std::uint64_t index = 0;
  AnyMessage message;
};

// Decodes one raw message as M, with an error that says where the message came from.
template <typename M>
M DecodeBagMessage(const BagReader& reader, const BagMessage& message);

class MessageStream {
 public:
  explicit MessageStream(BagReader& reader) : reader_(reader) {}

  std::optional<DecodedMessage> Next();
  // The bag's damage read past (BagReader::warnings), then one line per topic whose type was
  // not understood, e.g. "/foo: type pkg/msg/Bar is not used; skipped".
  std::vector<std::string> warnings() const {
    std::vector<std::string> all = reader_.warnings();
    all.insert(all.end(), warnings_.begin(), warnings_.end());
    return all;
  }

 private:
  BagReader& reader_;
  std::vector<std::string> warnings_;
  std::vector<std::string> warned_topics_;
};

// "BAG: topic 'T' message #N (t=… ns)": where a message is, for the errors it causes later.
std::string MessageOrigin(const BagReader& reader, const BagMessage& message);
std::string MessageOrigin(const BagReader& reader, const DecodedMessage& message);
// A BadInputError "BAG: topic 'T' message #N (t=… ns): REASON" for a message that cannot be used.
[[noreturn]] void ThrowUndecodable(const BagReader& reader, const BagMessage& message,
                                   const std::string& reason);
[[noreturn]] void ThrowUndecodable(const BagReader& reader, const DecodedMessage& message,
                                   const std::string& reason);

template <typename M>
M DecodeBagMessage(const BagReader& reader, const BagMessage& message) {
  if (message.topic->type != MessageTraits<M>::kTypeName) {
    ThrowUndecodable(reader, message,
                     "has type " + message.topic->type + ", expected " +
                         std::string(MessageTraits<M>::kTypeName));
  }
  try {
    return Decode<M>(message.data);
  } catch (const cdr::CdrError& e) {
    ThrowUndecodable(reader, message, e.what());
  }
}

}  // namespace littermap::bag
