// The recorder against in-process fake sources (exact counts, failure injection) and against
// the real source classes on emulated sensors: a SCIP 2.0 laser over TCP and a pseudo-terminal,
// a robot base's $ODOM stream, and OpenNI2's DummyDevice driver.

#include "capture/recorder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <thread>

#include "bag/bag_reader.hpp"
#include "bag/image_codec.hpp"
#include "bag/ros_codec.hpp"
#include "bag/topics.hpp"
#include "capture/byte_stream.hpp"
#include "capture/odometry_source.hpp"
#include "capture/openni2_camera.hpp"
#include "capture/scip_laser_source.hpp"
#include "core/error.hpp"
#include "support/never_stop.hpp"
#include "support/odometry_emulator.hpp"
#include "support/scip_emulator.hpp"
#include "support/temp_dir.hpp"

namespace littermap::capture {
namespace {

using namespace std::chrono_literals;

// Odometry readings at a fixed rate; scripted failures.
struct FakeScript {
  double rate_hz = 100;
  int burst = 0;                 // readings delivered at once before the steady rate
  int disconnect_after = -1;     // Read throws SensorDisconnectedError once after this many
  int silent_after = -1;         // then stays silent (nothing) until reconnected
  int malformed_every = 0;       // every Nth Read throws BadInputError
  int refuse_connects = 0;       // Connect fails this many times (after the first success)
  int* connect_calls = nullptr;  // counts every Connect, if set
};

class FakeSource : public SensorSource {
 public:
  explicit FakeSource(FakeScript script, std::string uri = "fake://odometry")
      : script_(script), uri_(std::move(uri)) {}

  SensorKind kind() const override { return SensorKind::kOdometry; }
  const std::string& uri() const override { return uri_; }
  void Connect() override {
    if (script_.connect_calls != nullptr) ++*script_.connect_calls;
    if (connects_ > 0 && refused_ < script_.refuse_connects) {
      ++refused_;
      throw SensorDisconnectedError(uri_ + ": still unplugged");
    }
    ++connects_;
    connected_ = true;
    next_ = std::chrono::steady_clock::now();
  }
  std::optional<SensorSample> Read(double timeout_s) override {
    if (!connected_) throw SensorDisconnectedError(uri_ + ": not connected");
    ++reads_;
    if (script_.malformed_every > 0 && reads_ % script_.malformed_every == 0) {
      throw BadInputError(uri_ + ": garbled reading");
    }
    if (sent_ == script_.disconnect_after && !disconnected_) {
      disconnected_ = true;
      throw SensorDisconnectedError(uri_ + ": cable pulled");
    }
    if (sent_ == script_.silent_after && !silenced_) {
      std::this_thread::sleep_for(std::chrono::duration<double>(timeout_s));
      if (connects_ < 2) return std::nullopt;
      silenced_ = true;
    }
    if (sent_ >= script_.burst) {
      next_ += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(1.0 / script_.rate_hz));
      std::this_thread::sleep_until(next_);
    }
    msg::Odometry odometry;
    odometry.header.stamp.sec = 1'700'000'000;
    odometry.header.stamp.nanosec = static_cast<std::uint32_t>(sent_ * 1000);
    odometry.header.frame_id = "odom";
    ++sent_;
    return odometry;
  }
  void Disconnect() override { connected_ = false; }

 private:
  FakeScript script_;
  std::string uri_;
  bool connected_ = false, disconnected_ = false, silenced_ = false;
  int connects_ = 0, refused_ = 0, reads_ = 0, sent_ = 0;
  std::chrono::steady_clock::time_point next_;
};

std::vector<std::unique_ptr<SensorSource>> One(std::unique_ptr<SensorSource> source) {
  std::vector<std::unique_ptr<SensorSource>> sources;
  sources.push_back(std::move(source));
  return sources;
}

RecorderOptions FastOptions(double duration_s) {
  RecorderOptions options;
  options.max_duration_s = duration_s;
  options.min_free_disk_bytes = 0;
  options.reconnect_interval_s = 0.1;
  options.read_timeout_s = 0.05;
  options.silence_timeout_s = 0.3;
  options.connect_timeout_s = 1.0;
  return options;
}

std::map<std::string, std::uint64_t> CountsByTopic(const std::filesystem::path& bag) {
  bag::BagReader reader(bag);
  std::map<std::string, std::uint64_t> counts;
  for (const bag::TopicInfo& topic : reader.info().topics) counts[topic.name] = topic.message_count;
  return counts;
}

std::vector<std::string> Events(const std::filesystem::path& bag) {
  bag::BagReader reader(bag);
  reader.SetTopicFilter({"/capture/events"});
  std::vector<std::string> events;
  while (auto message = reader.Next())
    events.push_back(bag::Decode<msg::String>(message->data).data);
  return events;
}

bool AnyContains(const std::vector<std::string>& texts, const std::string& part) {
  for (const std::string& text : texts) {
    if (text.find(part) != std::string::npos) return true;
  }
  return false;
}

using test::kNeverStop;

TEST(Recorder, WritesEveryReadingAndACompleteBag) {
  test::TempDir dir;
  const RecordingResult result =
      Record(dir / "bag", One(std::make_unique<FakeSource>(FakeScript{})), {}, FastOptions(1.0),
             kNeverStop);
  EXPECT_EQ(result.stop, RecordingStop::kDuration);
  ASSERT_EQ(result.sources.size(), 1u);
  const SourceStatus& odometry = result.sources[0];
  EXPECT_NEAR(static_cast<double>(odometry.received), 100, 15);  // 100 Hz for 1 s
  EXPECT_EQ(odometry.written, odometry.received);
  EXPECT_EQ(odometry.dropped, 0u);
  EXPECT_TRUE(std::filesystem::exists(dir / "bag" / "metadata.yaml"));
  bag::BagReader reader(dir / "bag");
  EXPECT_FALSE(reader.metadata_rebuilt());
  EXPECT_EQ(CountsByTopic(dir / "bag")[topics::kOdometry], odometry.written);
}

TEST(Recorder, AFullQueueDropsAndCountsTheNewest) {
  test::TempDir dir;
  FakeScript script;
  script.burst = 5000;  // far faster than anything is written
  RecorderOptions options = FastOptions(0.5);
  options.queue_capacity = 4;
  const RecordingResult result =
      Record(dir / "bag", One(std::make_unique<FakeSource>(script)), {}, options, kNeverStop);
  const SourceStatus& odometry = result.sources[0];
  EXPECT_GT(odometry.dropped, 0u);
  EXPECT_LE(odometry.max_queue_depth, 4u);
  EXPECT_EQ(odometry.written + odometry.dropped, odometry.received);
  EXPECT_EQ(CountsByTopic(dir / "bag")[topics::kOdometry], odometry.written);
}

TEST(Recorder, ReconnectsALostSensorAndNotesTheGap) {
  test::TempDir dir;
  FakeScript script;
  script.disconnect_after = 20;
  script.refuse_connects = 3;  // unplugged for about 3 reconnect intervals
  const RecordingResult result = Record(dir / "bag", One(std::make_unique<FakeSource>(script)), {},
                                        FastOptions(1.5), kNeverStop);
  const SourceStatus& odometry = result.sources[0];
  EXPECT_EQ(odometry.disconnects, 1u);
  EXPECT_TRUE(odometry.connected);
  EXPECT_NEAR(odometry.gap_s, 0.4, 0.25);  // 4 × 0.1 s reconnect intervals
  EXPECT_GT(odometry.received, 80u);       // kept recording after the gap
  const std::vector<std::string> events = Events(dir / "bag");
  EXPECT_TRUE(AnyContains(events, "odometry: lost (fake://odometry: cable pulled)"));
  EXPECT_TRUE(AnyContains(events, "odometry: reconnected after"));
  EXPECT_EQ(events, result.events);
}

TEST(Recorder, ASilentSensorIsReconnected) {
  test::TempDir dir;
  FakeScript script;
  script.silent_after = 10;
  const RecordingResult result = Record(dir / "bag", One(std::make_unique<FakeSource>(script)), {},
                                        FastOptions(1.5), kNeverStop);
  EXPECT_EQ(result.sources[0].disconnects, 1u);
  EXPECT_GE(result.sources[0].gap_s, 0.3);
  EXPECT_TRUE(AnyContains(result.events, "odometry: lost (silent for"));
  EXPECT_GT(result.sources[0].received, 50u);
}

TEST(Recorder, SkipsMalformedReadingsAndReconnectsAConfusedStream) {
  test::TempDir dir;
  FakeScript script;
  script.malformed_every = 4;
  const RecordingResult result = Record(dir / "bag", One(std::make_unique<FakeSource>(script)), {},
                                        FastOptions(1.0), kNeverStop);
  EXPECT_NEAR(static_cast<double>(result.sources[0].malformed),
              static_cast<double>(result.sources[0].received) / 3.0, 3.0);
  EXPECT_EQ(result.sources[0].disconnects, 0u);
  EXPECT_TRUE(
      AnyContains(result.events, "odometry: malformed reading #1: fake://odometry: garbled"));

  script.malformed_every = 1;  // nothing but garbage
  RecorderOptions options = FastOptions(1.0);
  options.max_consecutive_malformed = 5;
  const RecordingResult garbage =
      Record(dir / "garbage", One(std::make_unique<FakeSource>(script)), {}, options, kNeverStop);
  EXPECT_GE(garbage.sources[0].disconnects, 1u);
  EXPECT_TRUE(AnyContains(garbage.events, "5 malformed readings in a row"));
}

TEST(Recorder, StopsCleanlyWhenTheDiskIsNearlyFull) {
  test::TempDir dir;
  RecorderOptions options = FastOptions(30);
  options.min_free_disk_bytes = std::numeric_limits<std::uint64_t>::max();
  const RecordingResult result =
      Record(dir / "bag", One(std::make_unique<FakeSource>(FakeScript{})), {}, options, kNeverStop);
  EXPECT_EQ(result.stop, RecordingStop::kDiskFull);
  EXPECT_LT(result.duration_s, 5.0);
  EXPECT_NE(result.stop_reason.find("disk nearly full"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "bag" / "metadata.yaml"));
  EXPECT_TRUE(AnyContains(Events(dir / "bag"), "stopped: disk nearly full"));
}

TEST(Recorder, StopsOnRequestAndWritesWhatWasQueued) {
  test::TempDir dir;
  std::atomic<bool> stop{false};
  std::thread stopper([&] {
    std::this_thread::sleep_for(400ms);
    stop = true;
  });
  const RecordingResult result = Record(
      dir / "bag", One(std::make_unique<FakeSource>(FakeScript{})), {}, FastOptions(30), stop);
  stopper.join();
  EXPECT_EQ(result.stop, RecordingStop::kRequested);
  EXPECT_LT(result.duration_s, 2.0);
  EXPECT_EQ(result.sources[0].written, result.sources[0].received);
  EXPECT_EQ(CountsByTopic(dir / "bag")[topics::kOdometry], result.sources[0].written);
}

TEST(Recorder, ASensorThatNeverConnectsFailsAtTheStartLeavingNothing) {
  test::TempDir dir;
  RecorderOptions options = FastOptions(1);
  options.connect_timeout_s = 0.3;
  std::vector<std::unique_ptr<SensorSource>> sources;
  sources.push_back(std::make_unique<OdometrySource>("tcp://127.0.0.1:1"));  // nobody listens
  try {
    Record(dir / "bag", std::move(sources), {}, options, kNeverStop);
    FAIL() << "recorded without the sensor";
  } catch (const SensorDisconnectedError& error) {
    EXPECT_NE(std::string(error.what()).find("odometry tcp://127.0.0.1:1: cannot connect"),
              std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

TEST(Recorder, ASensorThatNeverConnectsLeavesAnEmptyOutputDirectoryEmpty) {
  test::TempDir dir;
  const std::filesystem::path prepared = dir / "prepared";
  std::filesystem::create_directory(prepared);  // a bag writer accepts an empty directory
  RecorderOptions options = FastOptions(1);
  options.connect_timeout_s = 0.3;
  std::vector<std::unique_ptr<SensorSource>> sources;
  sources.push_back(std::make_unique<OdometrySource>("tcp://127.0.0.1:1"));  // nobody listens
  EXPECT_THROW(Record(prepared, std::move(sources), {}, options, kNeverStop),
               SensorDisconnectedError);
  ASSERT_TRUE(std::filesystem::is_directory(prepared));
  EXPECT_TRUE(std::filesystem::is_empty(prepared));
}

TEST(Recorder, ABadOutputPathFailsBeforeAnySensorIsWoken) {
  test::TempDir dir;
  const std::filesystem::path taken = dir / "taken";
  std::filesystem::create_directory(taken);
  std::ofstream(taken / "earlier_0.db3") << "an earlier run";
  int connect_calls = 0;
  FakeScript script;
  script.connect_calls = &connect_calls;
  try {
    Record(taken, One(std::make_unique<FakeSource>(script)), {}, FastOptions(1), kNeverStop);
    FAIL() << "recorded into an existing path";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("taken: output bag already exists"), std::string::npos)
        << error.what();
  }
  EXPECT_EQ(connect_calls, 0);
  // What was there is left alone.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(taken), {}), 1);
  EXPECT_EQ(std::filesystem::file_size(taken / "earlier_0.db3"), 14u);
}

TEST(Recorder, RecordsEmulatedLaserOdometryAndOpenNi2Camera) {
  test::ScipEmulatorOptions laser_options;
  laser_options.scan_period_ms = 25;  // 40 Hz
  test::ScipEmulator laser(test::ScipEmulator::Link::kTcp, laser_options);
  test::OdometryEmulator base(test::OdometryEmulator::Link::kTcp);
  test::TempDir dir;
  std::vector<std::unique_ptr<SensorSource>> sources;
  sources.push_back(std::make_unique<ScipLaserSource>(laser.uri()));
  sources.push_back(std::make_unique<OdometrySource>(base.uri()));
  sources.push_back(std::make_unique<Openni2Camera>("openni2:Dummy"));
  RecorderOptions options = FastOptions(2.0);
  options.silence_timeout_s = 2.0;
  const RecordingResult result = Record(dir / "bag", std::move(sources), {}, options, kNeverStop);

  std::map<std::string, SourceStatus> by_name;
  for (const SourceStatus& source : result.sources) by_name[source.name] = source;
  EXPECT_NEAR(static_cast<double>(by_name["laser"].written), 80, 12);      // 40 Hz × 2 s
  EXPECT_NEAR(static_cast<double>(by_name["odometry"].written), 100, 15);  // 50 Hz × 2 s
  EXPECT_NEAR(static_cast<double>(by_name["camera"].written), 60, 15);     // the dummy's 30 Hz
  for (const auto& [name, source] : by_name) {
    EXPECT_EQ(source.dropped, 0u) << name;
    EXPECT_EQ(source.disconnects, 0u) << name;
  }

  bag::BagReader reader(dir / "bag");
  EXPECT_EQ(CountsByTopic(dir / "bag")[topics::kColor], by_name["camera"].written);
  reader.SetTopicFilter({topics::kScan});
  auto first = reader.Next();
  ASSERT_TRUE(first);
  const auto scan = bag::Decode<msg::LaserScan>(first->data);
  EXPECT_EQ(scan.header.frame_id, frames::kLaser);
  EXPECT_EQ(scan.ranges.size(), 1081u);  // steps 0..1080 of a UTM-30LX
  EXPECT_NEAR(scan.angle_min, -135.0 * M_PI / 180.0, 1e-4);
  EXPECT_NEAR(scan.angle_increment, 2 * M_PI / 1440, 1e-6);
  EXPECT_NEAR(scan.ranges[100], test::ScipEmulatorRangeMm(100, 0) / 1000.0, 0.1);

  reader.SetTopicFilter({topics::kOdometry});
  TimestampNs previous = 0;
  int odometry_count = 0;
  while (auto message = reader.Next()) {
    const auto odometry = bag::Decode<msg::Odometry>(message->data);
    EXPECT_GT(message->timestamp_ns, previous);
    previous = message->timestamp_ns;
    EXPECT_EQ(odometry.child_frame_id, frames::kBase);
    ++odometry_count;
  }
  EXPECT_GT(odometry_count, 0);
  // Host stamps within a second of now: the base's clock (5 s at start) was mapped.
  EXPECT_LT(std::abs(ToSeconds(HostNowNs() - previous)), 2.0);

  reader.SetTopicFilter({topics::kColor, topics::kDepth});
  auto colour = reader.Next(), depth = reader.Next();
  ASSERT_TRUE(colour && depth);
  if (colour->topic->name != topics::kColor) std::swap(colour, depth);
  const cv::Mat bgr = bag::DecodeColor(bag::Decode<msg::CompressedImage>(colour->data));
  const cv::Mat mm = bag::DecodeDepthMm(bag::Decode<msg::CompressedImage>(depth->data));
  EXPECT_EQ(bgr.size(), cv::Size(320, 240));  // the only mode the dummy device offers
  EXPECT_EQ(mm.size(), cv::Size(320, 240));
  EXPECT_TRUE(AnyContains(result.events, "camera: the device reports no field of view"));
}

TEST(Recorder, KeepsRecordingTheOthersWhileTheLaserIsUnplugged) {
  test::ScipEmulatorOptions laser_options;
  laser_options.scan_period_ms = 25;
  laser_options.disconnect_after_frames = 20;  // ~0.5 s in
  test::ScipEmulator laser(test::ScipEmulator::Link::kTcp, laser_options);
  test::OdometryEmulator base(test::OdometryEmulator::Link::kTcp);
  test::TempDir dir;
  std::vector<std::unique_ptr<SensorSource>> sources;
  sources.push_back(std::make_unique<ScipLaserSource>(laser.uri()));
  sources.push_back(std::make_unique<OdometrySource>(base.uri()));
  const RecordingResult result =
      Record(dir / "bag", std::move(sources), {}, FastOptions(2.0), kNeverStop);
  std::map<std::string, SourceStatus> by_name;
  for (const SourceStatus& source : result.sources) by_name[source.name] = source;
  EXPECT_EQ(by_name["laser"].disconnects, 1u);
  EXPECT_TRUE(by_name["laser"].connected);
  EXPECT_GT(by_name["laser"].written, 40u);  // frames before and after the reconnect
  EXPECT_EQ(by_name["odometry"].disconnects, 0u);
  EXPECT_NEAR(static_cast<double>(by_name["odometry"].written), 100, 15);
  EXPECT_TRUE(AnyContains(Events(dir / "bag"), "laser: reconnected after"));
}

TEST(Recorder, ReadsLaserAndOdometryOverPseudoTerminals) {
  test::ScipEmulator laser(test::ScipEmulator::Link::kPseudoTerminal);
  test::OdometryEmulator base(test::OdometryEmulator::Link::kPseudoTerminal);
  test::TempDir dir;
  std::vector<std::unique_ptr<SensorSource>> sources;
  sources.push_back(std::make_unique<ScipLaserSource>(laser.uri()));
  sources.push_back(std::make_unique<OdometrySource>(base.uri()));
  const RecordingResult result =
      Record(dir / "bag", std::move(sources), {}, FastOptions(1.0), kNeverStop);
  for (const SourceStatus& source : result.sources) {
    EXPECT_GT(source.written, 20u) << source.name;
    EXPECT_EQ(source.malformed, 0u) << source.name;
  }
}

}  // namespace
}  // namespace littermap::capture
