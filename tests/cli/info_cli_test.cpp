// `littermap info` and the CLI's contract: exit codes, --version, --help.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bag/bag_writer.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::RunLittermap;

void WriteSmallBag(const std::filesystem::path& path) {
  bag::BagWriter writer(path);
  writer.AddTopic<msg::String>("/notes", bag::TopicQos::kReliable);
  for (int i = 0; i < 5; ++i) {
    writer.WriteMessage("/notes", 2'000'000'000 + i * 500'000'000LL, msg::String{"note"});
  }
}

TEST(InfoCli, JsonHasStableKeysAndRightFigures) {
  test::TempDir dir;
  WriteSmallBag(dir / "bag");
  const auto result = RunLittermap("info --json " + (dir / "bag").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const auto json = nlohmann::json::parse(result.output);
  EXPECT_EQ(json.at("message_count"), 5);
  EXPECT_DOUBLE_EQ(json.at("duration_s").get<double>(), 2.0);
  EXPECT_EQ(json.at("start_ns"), 2'000'000'000);
  EXPECT_EQ(json.at("topics").at(0).at("name"), "/notes");
  EXPECT_EQ(json.at("topics").at(0).at("type"), "std_msgs/msg/String");
  EXPECT_EQ(json.at("topics").at(0).at("message_count"), 5);
  EXPECT_EQ(json.at("metadata_rebuilt"), false);
}

TEST(InfoCli, TextLooksLikeRos2BagInfo) {
  test::TempDir dir;
  WriteSmallBag(dir / "bag");
  const auto result = RunLittermap("info " + (dir / "bag").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("Duration:          2.000s"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("Topic: /notes | Type: std_msgs/msg/String | Count: 5"),
            std::string::npos)
      << result.output;
}

TEST(InfoCli, ReindexRestoresMissingMetadata) {
  test::TempDir dir;
  WriteSmallBag(dir / "bag");
  std::filesystem::remove(dir / "bag" / "metadata.yaml");
  const auto warned = RunLittermap("info " + (dir / "bag").string());
  EXPECT_EQ(warned.exit_code, 0);
  EXPECT_NE(warned.output.find("warning: "), std::string::npos) << warned.output;
  EXPECT_EQ(RunLittermap("info --reindex " + (dir / "bag").string()).exit_code, 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "bag" / "metadata.yaml"));
  const auto quiet = RunLittermap("info " + (dir / "bag").string());
  EXPECT_EQ(quiet.output.find("warning: "), std::string::npos) << quiet.output;
}

TEST(InfoCli, BadInputExitsTwoAndNamesTheFile) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "broken");
  std::ofstream(dir / "broken" / "broken_0.db3") << std::string(4096, '\x42');
  const auto result = RunLittermap("info " + (dir / "broken").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("broken_0.db3"), std::string::npos) << result.output;

  const auto missing = RunLittermap("info " + (dir / "missing").string());
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
}

TEST(Cli, UsageErrorsExitOne) {
  EXPECT_EQ(RunLittermap("").exit_code, 1);
  EXPECT_EQ(RunLittermap("info").exit_code, 1);
  EXPECT_EQ(RunLittermap("no-such-command").exit_code, 1);
  EXPECT_EQ(RunLittermap("info --no-such-flag x").exit_code, 1);
}

TEST(Cli, VersionAndHelpExitZero) {
  const auto version = RunLittermap("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("littermap "), std::string::npos);
  for (const char* command : {"", "info ", "reconstruct ", "survey "}) {
    const auto help = RunLittermap(std::string(command) + "--help");
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_NE(help.output.find("Usage:"), std::string::npos) << command;
  }
}

}  // namespace
}  // namespace littermap

namespace littermap {
namespace {

TEST(InfoCli, VerifyNamesTheDamagedMessageAndExitsTwo) {
  test::TempDir dir;
  {
    bag::BagWriter writer(dir / "bag");
    writer.AddTopic<msg::LaserScan>("/scan");
    writer.AddTopic("/custom", "acme_msgs/msg/Widget", bag::TopicQos::kReliable);
    msg::LaserScan scan;
    scan.ranges = {1.f, 2.f};
    const auto bytes = bag::Encode(scan);
    writer.Write("/scan", 1, bytes);
    writer.Write("/custom", 2, bytes);
    writer.Write("/scan", 3, std::span(bytes).first(bytes.size() - 3));
  }
  const auto result = test::RunLittermap("info --verify " + (dir / "bag").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("'/scan' message #1"), std::string::npos) << result.output;

  test::TempDir good;
  WriteSmallBag(good / "bag");
  const auto ok = test::RunLittermap("info --verify --json " + (good / "bag").string());
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_EQ(nlohmann::json::parse(ok.output).at("verified_message_count"), 5);
  EXPECT_EQ(nlohmann::json::parse(ok.output).at("damage"), nlohmann::json::array());
}

// A damaged MCAP chunk: the rest is verified and shown, the chunk named by file and offset, and
// the recording is refused (exit 2), whether or not the file has its summary.
TEST(InfoCli, VerifyNamesADamagedMcapChunkAndExitsTwo) {
  test::TempDir dir;
  {
    bag::BagWriterOptions options;
    options.storage = "mcap";
    options.mcap.chunk_size_bytes = 512;
    bag::BagWriter writer(dir / "bag", options);
    writer.AddTopic<msg::String>("/notes", bag::TopicQos::kReliable);
    for (int i = 0; i < 200; ++i) {
      writer.WriteMessage("/notes", 2'000'000'000 + i * 10'000'000LL,
                          msg::String{"note " + std::to_string(i)});
    }
  }
  const auto file = dir / "bag" / "bag_0.mcap";
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t middle = bytes.size() / 2;
  for (std::size_t i = 0; i < 16; ++i)
    bytes[middle + i] = static_cast<char>(bytes[middle + i] ^ 0x5A);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;

  for (const bool without_metadata : {false, true}) {
    if (without_metadata) std::filesystem::remove(dir / "bag" / "metadata.yaml");
    const auto result = RunLittermap("info --verify " + (dir / "bag").string());
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("Damaged:           "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("bag_0.mcap: offset "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("messages decode"), std::string::npos) << result.output;
  }
}

}  // namespace
}  // namespace littermap
