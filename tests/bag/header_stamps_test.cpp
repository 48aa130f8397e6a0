// Header stamps against recording stamps: read and written in place in either byte order, the
// reader's policy, and the warning for a bag whose clocks disagree.

#include <gtest/gtest.h>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "bag/header_stamps.hpp"
#include "bag/message_stream.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

TEST(HeaderStamps, ReadAndWrittenInPlace) {
  msg::LaserScan scan;
  scan.header.stamp = {12, 345};
  scan.ranges = {1.0f};
  std::vector<std::uint8_t> bytes = Encode(scan);
  EXPECT_EQ(HeaderStamp("sensor_msgs/msg/LaserScan", bytes), 12'000'000'345);
  EXPECT_FALSE(HeaderStamp("tf2_msgs/msg/TFMessage", bytes));
  EXPECT_FALSE(HeaderStamp("sensor_msgs/msg/LaserScan", std::span(bytes).first(8)));
  ASSERT_TRUE(SetHeaderStamp("sensor_msgs/msg/LaserScan", bytes, 7'000'000'001));
  const auto decoded = Decode<msg::LaserScan>(bytes);
  EXPECT_EQ(decoded.header.stamp.sec, 7);
  EXPECT_EQ(decoded.header.stamp.nanosec, 1u);
  EXPECT_EQ(decoded.ranges, scan.ranges);

  // Big-endian CDR: the same stamp, bytes the other way round.
  std::vector<std::uint8_t> big = {0x00, 0x00, 0x00, 0x00, 0, 0, 0, 12, 0, 0, 0x01, 0x59};
  EXPECT_EQ(HeaderStamp("sensor_msgs/msg/Imu", big), 12'000'000'345);
}

TEST(HeaderStamps, RecordedStampsReplaceHeadersAndDisagreementIsReported) {
  test::TempDir dir;
  {
    BagWriter writer(dir / "bag");
    writer.AddTopic<msg::LaserScan>("/scan");
    for (int i = 0; i < 20; ++i) {
      msg::LaserScan scan;
      scan.header.stamp = {i, 0};  // a simulated clock from 0
      writer.WriteMessage("/scan", 1'700'000'000'000'000'000 + i * 1'000'000'000LL, scan);
    }
  }
  BagReader reader(dir / "bag");
  MessageStream stream(reader);
  auto first = stream.Next();
  EXPECT_EQ(std::get<msg::LaserScan>(first->message).header.stamp.sec, 0);
  while (stream.Next()) {
  }
  ASSERT_EQ(reader.warnings().size(), 1u);
  EXPECT_NE(reader.warnings()[0].find("/scan: header stamps are 1700000000.0 s behind"),
            std::string::npos)
      << reader.warnings()[0];

  BagReader recorded(dir / "bag");
  recorded.SetStampSource(StampSource::kRecorded);
  MessageStream recorded_stream(recorded);
  first = recorded_stream.Next();
  EXPECT_EQ(std::get<msg::LaserScan>(first->message).header.stamp.sec, 1'700'000'000);
  EXPECT_THROW(ParseStampSource("gps"), UsageError);
}

}  // namespace
}  // namespace littermap::bag
