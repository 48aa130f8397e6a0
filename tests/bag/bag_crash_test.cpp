// A recording killed with SIGKILL keeps every message committed before the kill: the writer
// commits at least once a second, so at most the last second may be lost. Both storages.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kPayloadBytes = 2048;

std::vector<std::uint8_t> Payload(std::uint64_t index) {
  std::vector<std::uint8_t> bytes(kPayloadBytes);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(index + i);
  return bytes;
}

// Child: records as fast as a sensor would (~500 Hz), telling the parent how many messages it
// has handed to the writer.
[[noreturn]] void RecordUntilKilled(const std::filesystem::path& bag, const std::string& storage,
                                    int report_fd) {
  BagWriterOptions options;
  options.storage = storage;
  BagWriter writer(bag, options);
  writer.AddTopic("/data", "x/msg/Blob", TopicQos::kSensorData);
  for (std::uint64_t i = 0;; ++i) {
    writer.Write("/data", static_cast<TimestampNs>(i), Payload(i));
    const std::uint64_t written = i + 1;
    if (write(report_fd, &written, sizeof(written)) != sizeof(written)) _exit(3);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

class BagCrash : public ::testing::TestWithParam<std::string> {};

TEST_P(BagCrash, SigkillLosesAtMostTheLastSecond) {
  test::TempDir dir;
  const auto bag = dir / "killed";
  int pipe_fds[2];
  ASSERT_EQ(pipe(pipe_fds), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(pipe_fds[0]);
    RecordUntilKilled(bag, GetParam(), pipe_fds[1]);
  }
  close(pipe_fds[1]);

  // Track how many messages had been written by each moment, then kill 3 s in.
  const auto start = Clock::now();
  const auto kill_at = start + std::chrono::seconds(3);
  std::vector<std::pair<Clock::time_point, std::uint64_t>> reports;
  std::uint64_t written = 0;
  while (Clock::now() < kill_at && read(pipe_fds[0], &written, sizeof(written)) > 0) {
    reports.emplace_back(Clock::now(), written);
  }
  const auto killed_at = Clock::now();
  ASSERT_EQ(kill(child, SIGKILL), 0);
  int status = 0;
  waitpid(child, &status, 0);
  close(pipe_fds[0]);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_FALSE(reports.empty());

  // Everything written more than 1.25 s before the kill (1 s commit interval + scheduling slack)
  // must be in the bag.
  std::uint64_t must_survive = 0;
  for (const auto& [time, count] : reports) {
    if (killed_at - time >= std::chrono::milliseconds(1250)) must_survive = count;
  }
  ASSERT_GT(must_survive, 100u) << "the recorder did not get going";

  BagReader reader(bag);
  EXPECT_TRUE(reader.metadata_rebuilt()) << "a killed recorder never wrote metadata.yaml";
  std::uint64_t read_count = 0;
  while (auto message = reader.Next()) {
    ASSERT_EQ(message->index, read_count) << "messages missing in the middle";
    ASSERT_EQ(message->data, Payload(read_count)) << "message " << read_count << " damaged";
    ++read_count;
  }
  RecordProperty("written", std::to_string(written));
  RecordProperty("must_survive", std::to_string(must_survive));
  RecordProperty("read", std::to_string(read_count));
  EXPECT_GE(read_count, must_survive);
  EXPECT_LE(read_count, written);
  EXPECT_EQ(reader.info().message_count, read_count);
  if (GetParam() == "mcap") {
    ASSERT_FALSE(reader.warnings().empty()) << "a cut-off MCAP file is reported";
    EXPECT_NE(reader.warnings()[0].find("killed_0.mcap"), std::string::npos)
        << reader.warnings()[0];
  }
}

INSTANTIATE_TEST_SUITE_P(Storages, BagCrash, ::testing::Values("sqlite3", "mcap"));

}  // namespace
}  // namespace littermap::bag
