// Bags checked against independent implementations (tests/interop, pinned npm packages):
// Foxglove's @mcap/core reads every MCAP file littermap writes, with every compression, through
// its stream and its indexed reader, and @foxglove/rosmsg2-serialization decodes every message
// from the schemas in the file; littermap reads MCAP files @mcap/core wrote (zstd, lz4, none,
// and one without a summary) and a sqlite3 bag written with sql.js; and a conversion to MCAP and
// back gives the same bag.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "bag/bag_reader.hpp"
#include "bag/message_stream.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;

const std::filesystem::path kInteropDir =
    std::filesystem::path(LITTERMAP_TEST_OUTPUT_DIR) / "interop";

test::CommandResult RunShell(const std::string& command) {
  test::CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  std::size_t read = 0;
  while ((read = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, read);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

test::CommandResult RunNode(const std::string& script, const std::string& arguments) {
  return RunShell("node " + Quote(kInteropDir / script) + " " + arguments);
}

class BagInterop : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto install = RunShell(
        Quote(std::filesystem::path(LITTERMAP_SOURCE_DIR) / "tests" / "interop" / "install.sh") +
        " " + Quote(kInteropDir));
    ASSERT_EQ(install.exit_code, 0) << "installing the interop packages failed:\n"
                                    << install.output;
  }
};

// Everything a bag says about its topics and messages, in read order.
struct BagContents {
  std::vector<bag::TopicInfo> topics;
  std::vector<std::tuple<std::string, TimestampNs, std::vector<std::uint8_t>>> messages;
};

BagContents ReadContents(const std::filesystem::path& path) {
  bag::BagReader reader(path);
  BagContents contents;
  contents.topics = reader.info().topics;
  while (auto message = reader.Next()) {
    contents.messages.emplace_back(message->topic->name, message->timestamp_ns,
                                   std::move(message->data));
  }
  EXPECT_TRUE(reader.warnings().empty()) << path << ": " << reader.warnings()[0];
  return contents;
}

TEST_F(BagInterop, NodeReadsEveryMcapLittermapWritesAndConversionIsLossless) {
  test::TempDir dir;
  const auto world = std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples/worlds/park_small.yaml";
  auto result = RunLittermap("simulate --quiet " + Quote(world) + " -o " + Quote(dir / "run") +
                             " --truth " + Quote(dir / "truth") + " --duration 3");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const BagContents source = ReadContents(dir / "run");
  ASSERT_GT(source.messages.size(), 300u);

  for (const std::string compression : {"zstd", "lz4", "none"}) {
    SCOPED_TRACE(compression);
    const auto mcap = dir / ("mcap-" + compression);
    result = RunLittermap("convert --quiet " + Quote(dir / "run") + " -o " + Quote(mcap) +
                          " --storage mcap --compression " + compression);
    ASSERT_EQ(result.exit_code, 0) << result.output;

    const auto node =
        RunNode("read_mcap.mjs", Quote(mcap / (mcap.filename().string() + "_0.mcap")));
    ASSERT_EQ(node.exit_code, 0) << node.output;
    const auto json = nlohmann::json::parse(node.output);
    EXPECT_EQ(json["profile"], "ros2");
    EXPECT_EQ(json["indexed_message_count"], source.messages.size());
    EXPECT_EQ(json["statistics_message_count"], std::to_string(source.messages.size()));
    ASSERT_EQ(json["topics"].size(), source.topics.size());
    for (const bag::TopicInfo& topic : source.topics) {
      SCOPED_TRACE(topic.name);
      const auto& decoded = json["topics"][topic.name];
      EXPECT_EQ(decoded["type"], topic.type);
      EXPECT_EQ(decoded["encoding"], "ros2msg");
      EXPECT_EQ(decoded["message_encoding"], "cdr");
      EXPECT_EQ(decoded["count"], topic.message_count);
      EXPECT_EQ(decoded["qos"], topic.offered_qos_profiles);
    }
    // The first scan as Node decoded it, against littermap's own decoding.
    bag::BagReader reader(dir / "run");
    reader.SetTopicFilter({"/scan"});
    const auto raw = reader.Next();
    ASSERT_TRUE(raw);
    const auto scan = bag::DecodeBagMessage<msg::LaserScan>(reader, *raw);
    const auto& first = json["topics"]["/scan"]["first"];
    EXPECT_EQ(first["header"]["stamp"]["sec"], scan.header.stamp.sec);
    EXPECT_EQ(first["header"]["stamp"]["nanosec"], scan.header.stamp.nanosec);
    EXPECT_EQ(first["header"]["frame_id"], scan.header.frame_id);
    ASSERT_EQ(first["ranges"].size(), scan.ranges.size());
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
      // JSON has no infinity or NaN: Node prints them as null.
      if (!std::isfinite(scan.ranges[i])) {
        EXPECT_TRUE(first["ranges"][i].is_null()) << i;
        continue;
      }
      EXPECT_EQ(first["ranges"][i].get<float>(), scan.ranges[i]) << i;
    }

    // And back: the same topics (type, QoS, definition) and the same messages.
    result = RunLittermap("convert --quiet " + Quote(mcap) + " -o " +
                          Quote(dir / ("back-" + compression)) + " --storage sqlite3");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const BagContents back = ReadContents(dir / ("back-" + compression));
    ASSERT_EQ(back.topics.size(), source.topics.size());
    for (std::size_t i = 0; i < back.topics.size(); ++i) {
      EXPECT_EQ(back.topics[i].name, source.topics[i].name);
      EXPECT_EQ(back.topics[i].type, source.topics[i].type);
      EXPECT_EQ(back.topics[i].offered_qos_profiles, source.topics[i].offered_qos_profiles);
      EXPECT_EQ(back.topics[i].message_definition, source.topics[i].message_definition);
      EXPECT_FALSE(back.topics[i].message_definition.empty()) << back.topics[i].name;
    }
    EXPECT_TRUE(back.messages == source.messages) << "messages differ after a round trip";
  }
}

// What write_mcap.mjs and write_db3.mjs put in their bags (tests/interop/ros_types.mjs).
void ExpectInteropMessages(const std::filesystem::path& path) {
  SCOPED_TRACE(path.string());
  bag::BagReader reader(path);
  ASSERT_NE(reader.info().FindTopic("/scan_front"), nullptr);
  EXPECT_EQ(reader.info().FindTopic("/scan_front")->message_count, 60u);
  EXPECT_EQ(reader.info().FindTopic("/odometry/filtered")->message_count, 150u);
  bag::MessageStream stream(reader);
  int scans = 0, odometry = 0;
  TimestampNs previous = 0;
  constexpr TimestampNs kStart = 1'700'000'000'000'000'000;
  while (auto message = stream.Next()) {
    EXPECT_GE(message->timestamp_ns, previous);
    previous = message->timestamp_ns;
    if (const auto* scan = std::get_if<msg::LaserScan>(&message->message)) {
      EXPECT_EQ(message->timestamp_ns, kStart + scans * 100'000'000LL);
      EXPECT_EQ(scan->header.frame_id, "laser_front");
      ASSERT_EQ(scan->ranges.size(), 181u);
      EXPECT_FLOAT_EQ(scan->ranges[100], 1.0f + 0.01f * 100 + 0.001f * static_cast<float>(scans));
      EXPECT_FLOAT_EQ(scan->range_max, 30.0f);
      ++scans;
    } else if (const auto* odom = std::get_if<msg::Odometry>(&message->message)) {
      EXPECT_EQ(message->timestamp_ns, kStart + odometry * 40'000'000LL + 1000);
      EXPECT_EQ(odom->child_frame_id, "base_link");
      EXPECT_DOUBLE_EQ(odom->pose.pose.position.x, 0.02 * odometry);
      EXPECT_DOUBLE_EQ(odom->twist.twist.linear.x, 0.5);
      ++odometry;
    }
  }
  EXPECT_EQ(scans, 60);
  EXPECT_EQ(odometry, 150);
  EXPECT_TRUE(stream.warnings().empty());
}

TEST_F(BagInterop, LittermapReadsBagsWrittenInNode) {
  test::TempDir dir;
  for (const std::string variant : {"zstd", "lz4", "none", "zstd --no-summary"}) {
    const auto bag = dir / ("node-" + std::to_string(variant.size()) + "-" + variant.substr(0, 3));
    const auto node = RunNode("write_mcap.mjs", Quote(bag) + " " + variant);
    ASSERT_EQ(node.exit_code, 0) << node.output;
    ExpectInteropMessages(bag);
    const auto info = RunLittermap("info --verify " + Quote(bag));
    EXPECT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("Verified:          210 messages decode"), std::string::npos)
        << info.output;
  }
  const auto node = RunNode("write_db3.mjs", Quote(dir / "sqlite"));
  ASSERT_EQ(node.exit_code, 0) << node.output;
  ExpectInteropMessages(dir / "sqlite");
}

}  // namespace
}  // namespace littermap
