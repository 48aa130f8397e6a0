// A capture set up from the command line's URIs and options: which sources are simulated, the
// errors that name the option at fault, and a short recording from an emulated laser.

#include "capture/live_capture.hpp"

#include <gtest/gtest.h>

#include "bag/bag_reader.hpp"
#include "core/error.hpp"
#include "support/never_stop.hpp"
#include "support/scip_emulator.hpp"
#include "support/temp_dir.hpp"

namespace littermap::capture {
namespace {

using test::kNeverStop;

// The UsageError message of `call`, or "" when it throws none.
template <typename Call>
std::string UsageMessage(Call call) {
  try {
    call();
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

std::string SimulatedWorldError(const CaptureSources& sources) {
  return UsageMessage([&sources] { SimulatedWorld(sources); });
}

std::string MakeSourcesError(const CaptureSources& sources) {
  return UsageMessage([&sources] { MakeSources(sources, {}); });
}

TEST(CaptureSources, RealSensorsAreNotSimulated) {
  EXPECT_FALSE(SimulatedWorld({}));
  EXPECT_FALSE(SimulatedWorld({"openni2", "scip://127.0.0.1:10940", "none"}));
}

TEST(CaptureSources, SimulatedSourcesNameOneWorld) {
  const std::string world = std::string(LITTERMAP_SOURCE_DIR) + "/samples/worlds/park_small.yaml";
  const std::string same =
      std::string(LITTERMAP_SOURCE_DIR) + "/samples/../samples/worlds/park_small.yaml";
  EXPECT_EQ(SimulatedWorld({"sim:" + world, "sim:" + world, ""}), world);
  EXPECT_EQ(SimulatedWorld({"sim:" + world, "sim:" + same, "sim:" + world}), world);
  EXPECT_EQ(SimulatedWorld({"sim:" + world, "sim:" + world, "none"}), world);
}

TEST(CaptureSources, MixedOrIncompleteSimulatedSourcesAreUsageErrors) {
  EXPECT_EQ(SimulatedWorldError({"", "sim:w.yaml", ""}),
            "--camera '': a simulated capture needs --camera sim:WORLD.yaml as well");
  EXPECT_EQ(SimulatedWorldError({"sim:", "sim:", ""}), "--camera 'sim:' names no world file");
  EXPECT_EQ(SimulatedWorldError({"sim:w.yaml", "", ""}),
            "--laser '' and --camera 'sim:w.yaml' must simulate the same world (a simulated and "
            "a real sensor do not record together)");
  EXPECT_EQ(SimulatedWorldError({"sim:w.yaml", "sim:v.yaml", ""})
                .find("--laser 'sim:v.yaml' and --camera 'sim:w.yaml' must simulate the same"),
            0u);
  EXPECT_EQ(SimulatedWorldError({"sim:w.yaml", "sim:w.yaml", "tcp://h:1"})
                .find("--odometry 'tcp://h:1' and --camera 'sim:w.yaml' must"),
            0u);
}

TEST(CaptureSources, MakesTheSensorsGivenAndRefusesNone) {
  const auto sources = MakeSources({"none", "scip://127.0.0.1:1", "tcp://127.0.0.1:1"}, {});
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[0]->kind(), SensorKind::kLaser);
  EXPECT_EQ(sources[1]->kind(), SensorKind::kOdometry);
  EXPECT_EQ(MakeSourcesError({"none", "", "none"}),
            "nothing to record: give --camera, --laser or --odometry");
  EXPECT_EQ(MakeSourcesError({"", "", "/dev/ttyUSB0"}),
            "odometry URI /dev/ttyUSB0 is neither tcp://HOST:PORT nor serial:/DEVICE");
}

TEST(LiveCapture, WarnsWithoutARobotBeforeRefusingBadOptions) {
  test::TempDir dir;
  LiveCaptureOptions options;
  options.sources.laser_uri = "scip://127.0.0.1:1";
  std::vector<std::string> warnings;
  const auto warn = [&warnings](const std::string& warning) { warnings.push_back(warning); };
  options.duration_s = 0;
  EXPECT_EQ(UsageMessage([&] { CaptureLive(dir / "bag", options, kNeverStop, {}, warn); }),
            "--duration: must be positive");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "no --robot description: the bag has no /tf_static, and later stages place the "
            "sensors at base_link");
  options.duration_s.reset();
  options.min_free_disk_mb = -1;
  EXPECT_EQ(UsageMessage([&] { CaptureLive(dir / "bag", options, kNeverStop, {}, warn); }),
            "--min-free-disk-mb: must be >= 0");
  options.min_free_disk_mb = 0;
  options.camera_mode = "640x480";
  EXPECT_NE(UsageMessage([&] {
              CaptureLive(dir / "bag", options, kNeverStop, {}, warn);
            }).find("--camera-mode '640x480'"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

class LiveCaptureStorage : public ::testing::TestWithParam<std::string> {};

TEST_P(LiveCaptureStorage, RecordsAnEmulatedLaserForTheDurationAsked) {
  test::ScipEmulatorOptions laser_options;
  laser_options.scan_period_ms = 25;  // 40 Hz
  test::ScipEmulator laser(test::ScipEmulator::Link::kTcp, laser_options);
  test::TempDir dir;
  LiveCaptureOptions options;
  options.storage = GetParam();
  options.sources.laser_uri = laser.uri();
  options.robot_yaml = std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "robot.yaml";
  options.duration_s = 1.0;
  options.min_free_disk_mb = 0;
  bool warned = false;
  const RecordingResult result = CaptureLive(dir / "bag", options, kNeverStop, {},
                                             [&warned](const std::string&) { warned = true; });
  EXPECT_FALSE(warned);
  EXPECT_EQ(result.stop, RecordingStop::kDuration);
  ASSERT_EQ(result.sources.size(), 1u);
  EXPECT_GT(result.sources[0].written, 20u);  // 40 Hz for 1 s, less the connection
  bag::BagReader reader(dir / "bag");
  EXPECT_EQ(reader.info().storage_identifier, GetParam());
  ASSERT_NE(reader.info().FindTopic("/tf_static"), nullptr);
  EXPECT_EQ(reader.info().FindTopic("/tf_static")->message_count, 1u);
  ASSERT_NE(reader.info().FindTopic("/scan"), nullptr);
  EXPECT_EQ(reader.info().FindTopic("/scan")->message_count, result.sources[0].written);
}

INSTANTIATE_TEST_SUITE_P(Storages, LiveCaptureStorage, ::testing::Values("sqlite3", "mcap"));

TEST(LiveCapture, SummaryHasOneLinePerSource) {
  RecordingResult result;
  result.stop_reason = "stopped on request";
  result.duration_s = 12.34;
  result.messages = 250;
  result.sources.resize(2);
  result.sources[0].name = "camera";
  result.sources[0].uri = "openni2:Dummy";
  result.sources[1].name = "laser";
  result.sources[1].uri = "scip://h:1";
  EXPECT_EQ(RecordingSummary("run", result),
            "run: stopped on request after 12.3 s, 250 messages\n  " +
                FormatSummary(result.sources[0]) + "\n  " + FormatSummary(result.sources[1]) +
                "\n");
}

}  // namespace
}  // namespace littermap::capture
