// Decoded reading: known types decode, unknown types are skipped with one warning per topic,
// a damaged message is a BadInputError that names the bag, topic and message index.

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "bag/bag_writer.hpp"
#include "bag/message_stream.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

TEST(MessageStream, DecodesKnownTypesAndWarnsOncePerUnknownTopic) {
  test::TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic<msg::String>("/notes");
    writer.AddTopic("/custom", "acme_msgs/msg/Widget", TopicQos::kReliable);
    for (int i = 0; i < 3; ++i) {
      writer.WriteMessage("/notes", 10 * i, msg::String{"n" + std::to_string(i)});
      writer.Write("/custom", 10 * i + 1, std::vector<std::uint8_t>{0, 1, 0, 0, 42});
    }
  }
  BagReader reader(dir / "bag");
  MessageStream stream(reader);
  std::vector<std::string> texts;
  while (auto message = stream.Next()) {
    ASSERT_TRUE(std::holds_alternative<msg::String>(message->message));
    texts.push_back(std::get<msg::String>(message->message).data);
    EXPECT_EQ(message->index, texts.size() - 1);
  }
  EXPECT_EQ(texts, (std::vector<std::string>{"n0", "n1", "n2"}));
  ASSERT_EQ(stream.warnings().size(), 1u);
  EXPECT_NE(stream.warnings()[0].find("/custom"), std::string::npos);
  EXPECT_NE(stream.warnings()[0].find("acme_msgs/msg/Widget"), std::string::npos);
}

TEST(MessageStream, TruncatedMessageNamesTopicAndIndex) {
  test::TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic<msg::LaserScan>("/scan");
    msg::LaserScan scan;
    scan.header.frame_id = "laser";
    scan.ranges = {1.f, 2.f, 3.f};
    auto bytes = Encode(scan);
    writer.Write("/scan", 1, bytes);
    writer.Write("/scan", 2, bytes);
    bytes.resize(bytes.size() - 5);  // cut into the ranges
    writer.Write("/scan", 3, bytes);
  }
  BagReader reader(dir / "bag");
  MessageStream stream(reader);
  ASSERT_TRUE(stream.Next().has_value());
  ASSERT_TRUE(stream.Next().has_value());
  try {
    stream.Next();
    FAIL() << "a truncated LaserScan decoded";
  } catch (const BadInputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'/scan'"), std::string::npos) << what;
    EXPECT_NE(what.find("message #2"), std::string::npos) << what;
    EXPECT_NE(what.find("LaserScan.ranges"), std::string::npos) << what;
  }
}

TEST(MessageStream, AScanWithoutBeamDirectionsIsBadInput) {
  test::TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic<msg::LaserScan>("/scan");
    msg::LaserScan scan;
    scan.ranges = {1.f, 2.f, 3.f};
    scan.angle_min = -1.f;
    scan.angle_increment = 0.01f;
    writer.WriteMessage("/scan", 1, scan);
    scan.angle_increment = std::numeric_limits<float>::quiet_NaN();
    writer.WriteMessage("/scan", 2, scan);
  }
  BagReader reader(dir / "bag");
  MessageStream stream(reader);
  ASSERT_TRUE(stream.Next().has_value());
  try {
    stream.Next();
    FAIL() << "a LaserScan with a NaN angle_increment was accepted";
  } catch (const BadInputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'/scan' message #1"), std::string::npos) << what;
    EXPECT_NE(what.find("give its beams no directions"), std::string::npos) << what;
  }
}

TEST(MessageStream, WrongTypeForTopicIsBadInput) {
  test::TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic<msg::String>("/notes");
    writer.WriteMessage("/notes", 1, msg::String{"x"});
  }
  BagReader reader(dir / "bag");
  const auto raw = reader.Next();
  ASSERT_TRUE(raw.has_value());
  EXPECT_THROW(DecodeBagMessage<msg::LaserScan>(reader, *raw), BadInputError);
  EXPECT_EQ(DecodeBagMessage<msg::String>(reader, *raw).data, "x");
}

}  // namespace
}  // namespace littermap::bag
