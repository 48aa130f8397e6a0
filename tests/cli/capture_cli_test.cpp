// `littermap capture` from emulated sensors (a SCIP 2.0 laser and a robot base on loopback TCP,
// OpenNI2's DummyDevice camera) as a separate process: stopped by SIGINT or SIGTERM it finishes
// the bag; killed by SIGKILL the bag still holds everything up to its last commit (at most 1 s
// old).

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bag/bag_reader.hpp"
#include "bag/ros_codec.hpp"
#include "bag/topics.hpp"
#include "support/odometry_emulator.hpp"
#include "support/run_command.hpp"
#include "support/scip_emulator.hpp"
#include "support/temp_dir.hpp"

extern char** environ;

namespace littermap {
namespace {

using namespace std::chrono_literals;

// A `littermap capture` process with its stdout and stderr in a file; with a file size limit
// (ulimit -f, in 512-byte blocks) its writes fail beyond that size as on a full disk.
class CaptureProcess {
 public:
  CaptureProcess(const std::vector<std::string>& arguments, const std::filesystem::path& log,
                 std::optional<int> file_size_limit_blocks = std::nullopt)
      : log_(log) {
    std::vector<std::string> argv_strings = {LITTERMAP_EXECUTABLE, "capture"};
    if (file_size_limit_blocks) {
      argv_strings.insert(
          argv_strings.begin(),
          {"/bin/sh", "-c",
           "ulimit -f " + std::to_string(*file_size_limit_blocks) + " && exec \"$0\" \"$@\""});
    }
    argv_strings.insert(argv_strings.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& s : argv_strings) argv.push_back(s.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    const int rc = posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) pid_ = -1;
  }
  ~CaptureProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool started() const { return pid_ > 0; }
  void Signal(int signal) const { kill(pid_, signal); }
  // The wait status once the process ended, or nothing after `timeout`.
  std::optional<int> Wait(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return status;
      }
      std::this_thread::sleep_for(20ms);
    }
    return std::nullopt;
  }
  std::string Log() const {
    std::ifstream in(log_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
};

// Waits until the log mentions `text` (the recorder is running), up to `timeout`.
bool WaitForLog(const CaptureProcess& process, const std::string& text,
                std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (process.Log().find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(50ms);
  }
  return false;
}

std::map<std::string, std::uint64_t> CountsByTopic(bag::BagReader& reader) {
  std::map<std::string, std::uint64_t> counts;
  for (const bag::TopicInfo& topic : reader.info().topics) counts[topic.name] = topic.message_count;
  return counts;
}

struct Sensors {
  Sensors()
      : laser(test::ScipEmulator::Link::kTcp, LaserOptions()),
        base(test::OdometryEmulator::Link::kTcp) {}
  static test::ScipEmulatorOptions LaserOptions() {
    test::ScipEmulatorOptions options;
    options.scan_period_ms = 25;  // 40 Hz
    return options;
  }
  std::vector<std::string> Arguments(const std::filesystem::path& bag) const {
    return {"--laser",    laser.uri(),
            "--odometry", base.uri(),
            "--camera",   "openni2:Dummy",
            "--robot",    std::string(LITTERMAP_SOURCE_DIR) + "/samples/robot.yaml",
            "-o",         bag.string()};
  }
  test::ScipEmulator laser;
  test::OdometryEmulator base;
};

// Emulated sensors and a capture process recording them into DIR/run.
struct Recording {
  Recording() : capture(sensors.Arguments(dir / "run"), dir / "log.txt") {}
  // Waits until the recorder reports its first status.
  ::testing::AssertionResult Started() const {
    if (!capture.started()) return ::testing::AssertionFailure() << "not started";
    if (!WaitForLog(capture, "recording", 10s)) {
      return ::testing::AssertionFailure() << "no status within 10 s\n" << capture.Log();
    }
    return ::testing::AssertionSuccess();
  }
  std::filesystem::path bag() const { return dir / "run"; }

  Sensors sensors;
  test::TempDir dir;
  CaptureProcess capture;
};

class CaptureCliStop : public ::testing::TestWithParam<int> {};

TEST_P(CaptureCliStop, FinishesTheBag) {
  Recording recording;
  CaptureProcess& capture = recording.capture;
  const auto bag = recording.bag();
  ASSERT_TRUE(recording.Started());
  std::this_thread::sleep_for(2500ms);
  capture.Signal(GetParam());
  const std::optional<int> status = capture.Wait(10s);
  ASSERT_TRUE(status.has_value()) << "still running 10 s after the signal\n" << capture.Log();
  ASSERT_TRUE(WIFEXITED(*status)) << capture.Log();
  EXPECT_EQ(WEXITSTATUS(*status), 0) << capture.Log();
  EXPECT_NE(capture.Log().find("stopped on request"), std::string::npos) << capture.Log();

  ASSERT_TRUE(std::filesystem::exists(bag / "metadata.yaml"));
  bag::BagReader reader(bag);
  EXPECT_FALSE(reader.metadata_rebuilt());
  auto counts = CountsByTopic(reader);
  EXPECT_GE(counts[topics::kScan], 40u);
  EXPECT_GE(counts[topics::kOdometry], 50u);
  EXPECT_GE(counts[topics::kColor], 60u);  // 30 Hz for 2.5 s and more
  EXPECT_EQ(counts[topics::kColor], counts[topics::kDepth]);
  EXPECT_EQ(counts[topics::kTfStatic], 1u);
}

INSTANTIATE_TEST_SUITE_P(Signals, CaptureCliStop, ::testing::Values(SIGINT, SIGTERM),
                         [](const ::testing::TestParamInfo<int>& signal) {
                           return signal.param == SIGINT ? std::string("Sigint")
                                                         : std::string("Sigterm");
                         });

TEST(CaptureCli, SigkillKeepsEverythingButTheLastSecond) {
  Recording recording;
  CaptureProcess& capture = recording.capture;
  const auto bag = recording.bag();
  ASSERT_TRUE(recording.Started());
  const int scans_before = recording.sensors.laser.frames_sent();
  std::this_thread::sleep_for(3s);
  const int scans_sent = recording.sensors.laser.frames_sent() - scans_before;
  capture.Signal(SIGKILL);
  ASSERT_TRUE(capture.Wait(5s).has_value());

  EXPECT_FALSE(std::filesystem::exists(bag / "metadata.yaml"));
  bag::BagReader reader(bag);
  EXPECT_TRUE(reader.metadata_rebuilt());
  auto counts = CountsByTopic(reader);
  // 3 s of 40 Hz scans were sent while recording; the last commit is at most 1 s old.
  EXPECT_GE(static_cast<int>(counts[topics::kScan]), scans_sent - 40 - 5) << scans_sent;
  EXPECT_GE(counts[topics::kOdometry], 80u);  // 50 Hz, at least 2 of the 3 s
  EXPECT_GE(counts[topics::kColor], 45u);     // 30 Hz, likewise
  EXPECT_EQ(counts[topics::kTfStatic], 1u);
  // Every message there decodes.
  reader.SetTopicFilter({topics::kScan});
  int scans = 0;
  while (auto message = reader.Next()) {
    EXPECT_EQ(bag::Decode<msg::LaserScan>(message->data).ranges.size(), 1081u);
    ++scans;
  }
  EXPECT_EQ(static_cast<std::uint64_t>(scans), counts[topics::kScan]);
}

// The disk fills while recording, with no reserve kept: the recording stops, the bag closes
// over its last commit and verifies, the exit code says environment, and the summary says what
// was kept.
class CaptureCliFullDisk : public ::testing::TestWithParam<std::string> {};

TEST_P(CaptureCliFullDisk, StopsAndKeepsAVerifiedBag) {
  Sensors sensors;
  test::TempDir dir;
  std::vector<std::string> arguments = sensors.Arguments(dir / "run");
  arguments.insert(arguments.end(), {"--storage", GetParam(), "--min-free-disk-mb", "0"});
  // 2 MiB: a few seconds of the camera into sqlite3, more into zstd-compressed MCAP. With 512 KiB
  // a loaded machine's first one-second commit could already be larger than the disk, and then
  // nothing at all is kept (correctly, but it is not the case this test is about).
  CaptureProcess capture(arguments, dir / "log.txt", 4096);
  ASSERT_TRUE(capture.started());
  const std::optional<int> status = capture.Wait(60s);
  ASSERT_TRUE(status.has_value()) << "still recording after 60 s\n" << capture.Log();
  ASSERT_TRUE(WIFEXITED(*status)) << "ended by signal " << WTERMSIG(*status) << "\n"
                                  << capture.Log();
  EXPECT_EQ(WEXITSTATUS(*status), 4) << capture.Log();
  const std::string log = capture.Log();
  EXPECT_NE(log.find("writing the bag failed"), std::string::npos) << log;
  // The cause, from the system (MCAP) or as SQLite words it.
  EXPECT_TRUE(log.find("File too large") != std::string::npos ||
              log.find("SQLite error: disk I/O error") != std::string::npos)
      << log;
  EXPECT_NE(log.find("messages"), std::string::npos) << log;  // the summary of what was kept

  const test::CommandResult verify =
      test::RunLittermap("info --verify " + test::Quote(dir / "run"));
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
  bag::BagReader reader(dir / "run");
  auto counts = CountsByTopic(reader);
  EXPECT_GE(counts[topics::kScan], 10u) << verify.output;
  EXPECT_GE(counts[topics::kColor], 5u) << verify.output;
}

INSTANTIATE_TEST_SUITE_P(Storages, CaptureCliFullDisk, ::testing::Values("sqlite3", "mcap"),
                         [](const ::testing::TestParamInfo<std::string>& storage) {
                           return storage.param;
                         });

TEST(CaptureCli, RefusesBadSourcesNamingThem) {
  test::TempDir dir;
  const auto bag = test::Quote(dir / "run");
  struct Case {
    std::string arguments, message;
  } cases[] = {
      {"--camera kinect -o " + bag, "camera URI kinect is neither openni2 nor openni2:DEVICE"},
      {"--laser urg://x -o " + bag, "laser URI urg://x is neither scip://HOST:PORT"},
      {"--odometry /dev/ttyUSB0 -o " + bag, "odometry URI /dev/ttyUSB0 is neither tcp://"},
      {"-o " + bag, "nothing to record"},
      {"--laser scip://127.0.0.1:1 --camera-mode 640x480 -o " + bag, "--camera-mode '640x480'"},
      {"--camera sim:a.yaml --laser scip://127.0.0.1:1 -o " + bag, "must simulate the same world"},
      {"--laser scip://127.0.0.1:1 --truth t -o " + bag, "--truth works with sim: sources only"},
  };
  for (const Case& c : cases) {
    const test::CommandResult result = test::RunLittermap("capture " + c.arguments);
    EXPECT_EQ(result.exit_code, 1) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.message), std::string::npos) << c.arguments << "\n"
                                                                << result.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "run"));
}

TEST(CaptureCli, ASensorThatIsNotThereFailsBeforeRecording) {
  test::TempDir dir;
  const test::CommandResult result =
      test::RunLittermap("capture --laser scip://127.0.0.1:1 -o " + test::Quote(dir / "run"));
  EXPECT_EQ(result.exit_code, 4) << result.output;  // the machine's fault, not littermap's
  EXPECT_NE(result.output.find("laser scip://127.0.0.1:1: cannot connect within"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "run"));
}

}  // namespace
}  // namespace littermap
