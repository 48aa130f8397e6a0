// The summary of a run bag (`littermap info`): the ros2-bag-info text, the JSON keys, a stale
// metadata.yaml warned about and rewritten, and verification that decodes every message.

#include "bag/bag_summary.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bag/bag_writer.hpp"
#include "bag/image_codec.hpp"
#include "bag/ros_codec.hpp"
#include "bag/sensor_roles.hpp"
#include "bag/verify_messages.hpp"
#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

using test::TempDir;

constexpr TimestampNs kStartNs = 1'700'000'000'250'000'000;  // 2023-11-14T22:13:20.25Z

// Three scans 0.5 s apart on /scan and, if asked, one message of an unknown type on /foo.
void WriteBag(const std::filesystem::path& path, bool unknown_topic = false) {
  BagWriter writer(path);
  writer.AddTopic<msg::LaserScan>("/scan");
  msg::LaserScan scan;
  scan.ranges = {1.0f, 2.0f};
  for (int k = 0; k < 3; ++k) writer.WriteMessage("/scan", kStartNs + k * 500'000'000, scan);
  if (unknown_topic) {
    writer.AddTopic("/foo", "pkg/msg/Bar", TopicQos::kReliable);
    writer.Write("/foo", kStartNs + 1, std::vector<std::uint8_t>{0, 1, 0, 0});
  }
  writer.Close();
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    lines.push_back(text.substr(start, end - start));
  }
  EXPECT_EQ(start, text.size()) << "the text ends in a newline";
  return lines;
}

TEST(BagSummary, FormatsSizesAndTimesForPeople) {
  EXPECT_EQ(HumanSize(0), "0.0 B");
  EXPECT_EQ(HumanSize(1023), "1023.0 B");
  EXPECT_EQ(HumanSize(761856), "744.0 KiB");
  EXPECT_EQ(HumanSize(33869824), "32.3 MiB");
  EXPECT_EQ(HumanSize(3ull << 40), "3.0 TiB");
  EXPECT_EQ(HumanSize(5000ull << 40), "5000.0 TiB");  // no unit beyond TiB
  EXPECT_EQ(IsoTimeUtc(21'019'900'000), "1970-01-01T00:00:21.019900000Z");
  EXPECT_EQ(IsoTimeUtc(kStartNs), "2023-11-14T22:13:20.250000000Z");
}

TEST(BagSummary, TextIsTheRos2BagInfoLayout) {
  TempDir dir;
  WriteBag(dir / "run");
  const BagSummary summary = SummariseBag(dir / "run");
  EXPECT_EQ(summary.path, (dir / "run").string());
  EXPECT_FALSE(summary.metadata_rebuilt);
  EXPECT_FALSE(summary.verified_message_count);
  EXPECT_EQ(summary.size_bytes, std::filesystem::file_size(dir / "run" / "run_0.db3"));
  const std::vector<std::string> lines = Lines(ToText(summary));
  ASSERT_EQ(lines.size(), 14u);
  EXPECT_EQ(lines[0], "Files:             run_0.db3");
  EXPECT_EQ(lines[1], "Bag size:          " + HumanSize(summary.size_bytes));
  EXPECT_EQ(lines[2], "Storage id:        sqlite3 (schema 4)");
  EXPECT_EQ(lines[3], "Duration:          1.000s");
  EXPECT_EQ(lines[4], "Start:             2023-11-14T22:13:20.250000000Z (1700000000.250000000)");
  EXPECT_EQ(lines[5], "End:               2023-11-14T22:13:21.250000000Z (1700000001.250000000)");
  EXPECT_EQ(lines[6], "Messages:          3");
  EXPECT_EQ(lines[7],
            "Topic information: Topic: /scan | Type: sensor_msgs/msg/LaserScan | Count: 3 | "
            "Serialization Format: cdr");
  EXPECT_EQ(lines[8], "Sensor roles:      scan: /scan (default)");
  EXPECT_EQ(lines[9], "                   odometry: none");
  EXPECT_EQ(lines[13], "                   camera_info: none");
}

TEST(BagSummary, TextOfNoTopicsAndSeveralFilesKeepsTheColumns) {
  BagSummary summary;
  summary.info.files = {{"a_0.db3"}, {"a_1.db3"}};
  const std::vector<std::string> lines = Lines(ToText(summary));
  ASSERT_EQ(lines.size(), 15u);
  EXPECT_EQ(lines[0], "Files:             a_0.db3");
  EXPECT_EQ(lines[1], "                   a_1.db3");
  EXPECT_EQ(lines[8], "Topic information: ");
  EXPECT_EQ(lines[9], "Sensor roles:      scan: none");
  summary.verified_message_count = 0;
  EXPECT_EQ(Lines(ToText(summary)).back(), "Verified:          0 messages decode");
}

TEST(BagSummary, JsonKeepsItsKeys) {
  TempDir dir;
  WriteBag(dir / "run");
  BagSummary summary = SummariseBag(dir / "run");
  nlohmann::json json = nlohmann::json::parse(ToJson(summary));
  EXPECT_EQ(json["path"], (dir / "run").string());
  EXPECT_EQ(json["storage_identifier"], "sqlite3");
  EXPECT_EQ(json["schema_version"], 4);
  EXPECT_EQ(json["size_bytes"], summary.size_bytes);
  EXPECT_EQ(json["files"], nlohmann::json::array({"run_0.db3"}));
  EXPECT_EQ(json["message_count"], 3);
  EXPECT_EQ(json["start_ns"], kStartNs);
  EXPECT_EQ(json["end_ns"], kStartNs + 1'000'000'000);
  EXPECT_DOUBLE_EQ(json["duration_s"], 1.0);
  EXPECT_EQ(json["start_utc"], "2023-11-14T22:13:20.250000000Z");
  EXPECT_EQ(json["end_utc"], "2023-11-14T22:13:21.250000000Z");
  EXPECT_EQ(json["metadata_rebuilt"], false);
  ASSERT_EQ(json["topics"].size(), 1u);
  EXPECT_EQ(json["topics"][0], nlohmann::json({{"name", "/scan"},
                                               {"type", "sensor_msgs/msg/LaserScan"},
                                               {"serialization_format", "cdr"},
                                               {"message_count", 3}}));
  EXPECT_EQ(json["sensor_roles"]["scan"],
            nlohmann::json({{"found", "default"}, {"topic", "/scan"}}));
  EXPECT_EQ(json["sensor_roles"]["imu"], nlohmann::json({{"found", "missing"}}));
  EXPECT_EQ(json["sensor_roles"].size(), SensorRoleNames().size());
  EXPECT_FALSE(json.contains("verified_message_count"));
  summary.verified_message_count = 3;
  EXPECT_EQ(nlohmann::json::parse(ToJson(summary))["verified_message_count"], 3);
  EXPECT_EQ(ToJson(summary).back(), '}');  // no final newline
}

TEST(BagSummary, WarnsAboutAMissingMetadataYamlAndReindexRewritesIt) {
  TempDir dir;
  WriteBag(dir / "run");
  std::filesystem::remove(dir / "run" / "metadata.yaml");
  std::vector<std::string> warnings;
  const auto warn = [&warnings](const std::string& warning) { warnings.push_back(warning); };
  const BagSummary stale = SummariseBag(dir / "run", {}, {}, warn);
  EXPECT_TRUE(stale.metadata_rebuilt);
  EXPECT_EQ(stale.info.message_count, 3u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir / "run").string() +
                             ": metadata.yaml is missing or out of date (was the recording "
                             "interrupted?); figures are rebuilt from the database (--reindex "
                             "rewrites it)");
  EXPECT_FALSE(std::filesystem::exists(dir / "run" / "metadata.yaml"));

  warnings.clear();
  BagSummaryOptions options;
  options.reindex = true;
  SummariseBag(dir / "run", options, {}, warn);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].find("--reindex"), std::string::npos) << warnings[0];
  ASSERT_TRUE(std::filesystem::exists(dir / "run" / "metadata.yaml"));
  EXPECT_EQ(ReadMetadataYaml(dir / "run" / "metadata.yaml").message_count, 3u);

  warnings.clear();
  EXPECT_FALSE(SummariseBag(dir / "run", {}, {}, warn).metadata_rebuilt);
  EXPECT_TRUE(warnings.empty());
}

TEST(BagSummary, VerifyCountsWhatDecodesAndWarnsAboutUnusedTypesAfterTheStaleMetadata) {
  TempDir dir;
  WriteBag(dir / "run", true);
  std::filesystem::remove(dir / "run" / "metadata.yaml");
  std::vector<std::string> warnings;
  BagSummaryOptions options;
  options.verify = true;
  const BagSummary summary = SummariseBag(
      dir / "run", options, {}, [&warnings](const std::string& w) { warnings.push_back(w); });
  EXPECT_EQ(summary.info.message_count, 4u);
  EXPECT_EQ(summary.verified_message_count, 3u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("metadata.yaml is missing"), std::string::npos) << warnings[0];
  EXPECT_EQ(warnings[1], "/foo: type pkg/msg/Bar is not used; skipped");
}

TEST(VerifyMessages, ReportsProgressEvery256Messages) {
  TempDir dir;
  {
    BagWriter writer(dir / "run");
    writer.AddTopic<msg::LaserScan>("/scan");
    for (int k = 0; k < 600; ++k) {
      msg::LaserScan scan;  // header stamps agree with the recording stamps: no warning
      scan.header.stamp = {static_cast<std::int32_t>((kStartNs + k) / kNanosecondsPerSecond),
                           static_cast<std::uint32_t>((kStartNs + k) % kNanosecondsPerSecond)};
      writer.WriteMessage("/scan", kStartNs + k, scan);
    }
  }
  BagReader reader(dir / "run");
  std::vector<std::uint64_t> done;
  const VerifyResult result = VerifyMessages(reader, [&done](const Progress& progress) {
    EXPECT_EQ(progress.task, "verifying");
    EXPECT_EQ(progress.total, 600u);
    done.push_back(progress.done);
  });
  EXPECT_EQ(result.decoded_messages, 600u);
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(done, (std::vector<std::uint64_t>{256, 512}));
}

TEST(VerifyMessages, ADamagedMessageIsBadInputNamingTopicAndIndex) {
  TempDir dir;
  {
    BagWriter writer(dir / "run");
    writer.AddTopic<msg::LaserScan>("/scan");
    writer.WriteMessage("/scan", kStartNs, msg::LaserScan{});
    writer.Write("/scan", kStartNs + 1, std::vector<std::uint8_t>{0, 1});
  }
  BagSummaryOptions options;
  options.verify = true;
  try {
    SummariseBag(dir / "run", options);
    FAIL() << "a damaged message verified";
  } catch (const BadInputError& error) {
    EXPECT_NE(std::string(error.what()).find("topic '/scan' message #1"), std::string::npos)
        << error.what();
  }
}

// A colour camera info of 64x48 and, after it, the given colour JPEG and depth PNG (whose
// camera has no camera info: its size is not checked).
std::string VerifyImages(const std::filesystem::path& bag, const msg::CompressedImage& colour,
                         const msg::CompressedImage& depth) {
  {
    BagWriter writer(bag);
    writer.AddTopic<msg::CameraInfo>("/camera/color/camera_info");
    writer.AddTopic<msg::CompressedImage>("/camera/color/image_raw/compressed");
    writer.AddTopic<msg::CompressedImage>("/camera/depth/image_raw/compressed");
    msg::CameraInfo info;
    info.header.frame_id = "cam";
    info.width = 64;
    info.height = 48;
    writer.WriteMessage("/camera/color/camera_info", kStartNs, info);
    writer.WriteMessage("/camera/color/image_raw/compressed", kStartNs + 1, colour);
    writer.WriteMessage("/camera/depth/image_raw/compressed", kStartNs + 2, depth);
  }
  BagReader reader(bag);
  try {
    const VerifyResult result = VerifyMessages(reader);
    EXPECT_EQ(result.decoded_images, 2u);
    return "";
  } catch (const BadInputError& e) {
    return e.what();
  }
}

TEST(VerifyMessages, DecodesImagesAndChecksTheirSizeAgainstTheCameraInfo) {
  TempDir dir;
  msg::Header header;
  header.frame_id = "cam";
  const msg::CompressedImage colour =
      EncodeColorJpeg(cv::Mat(48, 64, CV_8UC3, cv::Scalar(10, 200, 30)), header);
  const msg::CompressedImage depth =
      EncodeDepthPng(cv::Mat(48, 64, CV_16UC1, cv::Scalar(1500)), header);
  EXPECT_EQ(VerifyImages(dir / "good", colour, depth), "");

  msg::CompressedImage cut = depth;  // a PNG cut short
  cut.data.resize(cut.data.size() / 2);
  const std::string truncated = VerifyImages(dir / "cut", colour, cut);
  EXPECT_NE(truncated.find("topic '/camera/depth/image_raw/compressed' message #0"),
            std::string::npos)
      << truncated;

  msg::CompressedImage short_jpeg = colour;            // a JPEG cut short still decodes: damaged
  short_jpeg.data.resize(short_jpeg.data.size() - 8);  // its last bytes and end marker
  const std::string damaged = VerifyImages(dir / "short", short_jpeg, depth);
  EXPECT_NE(damaged.find("topic '/camera/color/image_raw/compressed' message #0"),
            std::string::npos)
      << damaged;
  EXPECT_NE(damaged.find("JPEG is damaged: Premature end of JPEG file"), std::string::npos)
      << damaged;

  const msg::CompressedImage small =
      EncodeColorJpeg(cv::Mat(24, 32, CV_8UC3, cv::Scalar::all(90)), header);
  const std::string resized = VerifyImages(dir / "small", small, depth);
  EXPECT_NE(resized.find("topic '/camera/color/image_raw/compressed' message #0"),
            std::string::npos)
      << resized;
  EXPECT_NE(resized.find("image of 32x24 pixels, but /camera/color/camera_info says 64x48"),
            std::string::npos)
      << resized;
}

TEST(BagSummary, WhatIsNotABagIsBadInput) {
  TempDir dir;
  EXPECT_THROW(SummariseBag(dir / "missing"), BadInputError);
  EXPECT_THROW(SummariseBag(dir.path()), BadInputError);
}

}  // namespace
}  // namespace littermap::bag
