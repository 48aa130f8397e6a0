// Simulated runs as bags: the topics of a real capture (laser, odometry, IMU and the RGB-D camera
// as the TUM importer writes it), the camera's unsynchronised clock, and the same seed gives the
// same bag, images included.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <variant>
#include <vector>

#include "bag/bag_reader.hpp"
#include "bag/image_codec.hpp"
#include "bag/message_stream.hpp"
#include "bag/topics.hpp"
#include "core/error.hpp"
#include "sim/recorder.hpp"
#include "sim/sim_test_support.hpp"
#include "sim/world_spec.hpp"
#include "support/temp_dir.hpp"

namespace littermap::sim {
namespace {

struct Decoded {
  std::vector<TimestampNs> stamps;
  std::vector<msg::LaserScan> scans;
  std::vector<msg::Odometry> odometry;
  std::vector<msg::Imu> imu;
  std::vector<msg::TFMessage> tf;
  std::vector<msg::CompressedImage> colour, depth;
  std::vector<msg::CameraInfo> colour_info, depth_info;
};

Decoded ReadBag(const std::filesystem::path& path) {
  bag::BagReader reader(path);
  bag::MessageStream stream(reader);
  Decoded decoded;
  while (auto message = stream.Next()) {
    decoded.stamps.push_back(message->timestamp_ns);
    if (auto* scan = std::get_if<msg::LaserScan>(&message->message)) decoded.scans.push_back(*scan);
    if (auto* odom = std::get_if<msg::Odometry>(&message->message))
      decoded.odometry.push_back(*odom);
    if (auto* imu = std::get_if<msg::Imu>(&message->message)) decoded.imu.push_back(*imu);
    if (auto* tf = std::get_if<msg::TFMessage>(&message->message)) decoded.tf.push_back(*tf);
    const std::string& topic = message->topic->name;
    if (auto* image = std::get_if<msg::CompressedImage>(&message->message)) {
      (topic == topics::kColor ? decoded.colour : decoded.depth).push_back(*image);
    }
    if (auto* info = std::get_if<msg::CameraInfo>(&message->message)) {
      (topic == topics::kCameraInfo ? decoded.colour_info : decoded.depth_info).push_back(*info);
    }
  }
  return decoded;
}

SimRecordResult Record(const std::filesystem::path& dir, std::uint64_t seed, double duration_s) {
  SimRecordOptions options;
  options.seed = seed;
  options.max_duration_s = duration_s;
  return RecordSimulation(LoadWorldSpec(test::SampleWorld()), dir / "bag", dir / "truth", options);
}

// One 3-second recording of the sample park (seed 7) shared by the tests that only read it.
class SimRecorderRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir;
    result_ = new SimRecordResult(Record(dir_->path(), 7, 3));
    bag_ = new Decoded(ReadBag(*dir_ / "bag"));
  }
  static void TearDownTestSuite() {
    delete bag_;
    delete result_;
    delete dir_;
  }
  static test::TempDir* dir_;
  static SimRecordResult* result_;
  static Decoded* bag_;
};
test::TempDir* SimRecorderRun::dir_ = nullptr;
SimRecordResult* SimRecorderRun::result_ = nullptr;
Decoded* SimRecorderRun::bag_ = nullptr;

TEST_F(SimRecorderRun, WritesTheTopicsOfARealCapture) {
  const SimRecordResult& result = *result_;
  const Decoded& bag = *bag_;
  EXPECT_EQ(result.scans, 31u);      // 10 Hz over 0..3 s
  EXPECT_EQ(result.odometry, 151u);  // 50 Hz
  EXPECT_EQ(result.imu, 151u);
  ASSERT_EQ(bag.scans.size(), 31u);
  EXPECT_EQ(bag.scans[0].ranges.size(), 682u);
  EXPECT_EQ(bag.scans[0].header.frame_id, "laser");
  EXPECT_FLOAT_EQ(bag.scans[0].range_max, 5.6f);
  EXPECT_EQ(bag.odometry.size(), 151u);
  EXPECT_EQ(bag.odometry[0].header.frame_id, "odom");
  EXPECT_EQ(bag.odometry[0].child_frame_id, "base_link");
  EXPECT_DOUBLE_EQ(bag.odometry[0].pose.pose.position.x, 0);  // odometry starts at its origin
  EXPECT_GT(bag.odometry.back().pose.pose.position.x, 0.8);   // ~0.6 m/s ahead after a start
  ASSERT_EQ(bag.tf.size(), 1u);
  ASSERT_EQ(bag.tf[0].transforms.size(), 2u);
  EXPECT_EQ(bag.tf[0].transforms[0].child_frame_id, frames::kLaser);
  EXPECT_DOUBLE_EQ(bag.tf[0].transforms[0].transform.translation.z, 0.3);
  EXPECT_EQ(bag.tf[0].transforms[1].child_frame_id, frames::kCamera);
  // Level robot: the IMU's gravity points up the base z axis.
  EXPECT_NEAR(bag.imu[0].linear_acceleration.z, 9.81, 0.1);
  EXPECT_TRUE(std::is_sorted(bag.stamps.begin(), bag.stamps.end()));
  EXPECT_TRUE(std::filesystem::exists(*dir_ / "truth" / "trajectory.tum"));
}

TEST_F(SimRecorderRun, RecordsTheRgbdCameraLikeTheTumImporter) {
  const SimRecordResult& result = *result_;
  const Decoded& bag = *bag_;
  // 10 Hz from the 13 ms clock offset: 0.013, 0.113, ..., 2.913 s.
  EXPECT_EQ(result.frames, 30u);
  EXPECT_EQ(result.masks, 3u);  // frames 0, 10, 20 (park_small: every 10th)
  ASSERT_EQ(bag.colour.size(), 30u);
  ASSERT_EQ(bag.depth.size(), 30u);
  ASSERT_EQ(bag.colour_info.size(), 30u);
  ASSERT_EQ(bag.depth_info.size(), 30u);
  const msg::CameraInfo& info = bag.colour_info[0];
  EXPECT_EQ(info.header.frame_id, frames::kCamera);
  EXPECT_EQ(info.width, 640u);
  EXPECT_EQ(info.height, 480u);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_EQ(info.k, (std::array<double, 9>{525, 0, 319.5, 0, 525, 239.5, 0, 0, 1}));
  EXPECT_EQ(bag.depth_info[0], info);  // depth is registered to colour
  EXPECT_EQ(bag.colour[0].format, "bgr8; jpeg compressed bgr8");
  EXPECT_EQ(bag.depth[0].format, "16UC1; png compressed");
  EXPECT_EQ(bag.colour[0].header, info.header);
  EXPECT_EQ(bag.depth[0].header, info.header);
  // The camera's clock (sim/simulation.hpp, tested in tests/sim/camera_timing_test.cpp): frame k
  // at 13 ms + k * 100 ms ± 6 ms, so off the laser's 100 ms ticks.
  for (std::size_t k = 0; k < bag.colour.size(); ++k) {
    const auto& stamp = bag.colour[k].header.stamp;
    const double t = (stamp.sec - 1700000000) + stamp.nanosec * 1e-9;
    EXPECT_NEAR(t, 0.013 + 0.1 * static_cast<double>(k), 0.006 + 1e-6) << "frame " << k;
    EXPECT_NE(stamp, bag.scans[k].header.stamp);
    EXPECT_EQ(bag.depth[k].header.stamp, stamp);
  }
  const cv::Mat colour = bag::DecodeColor(bag.colour[0]);
  const cv::Mat depth = bag::DecodeDepthMm(bag.depth[0]);
  EXPECT_EQ(colour.size(), cv::Size(640, 480));
  EXPECT_EQ(depth.size(), cv::Size(640, 480));
  // Pitched 25° down from 0.5 m: the bottom row sees the ground ~0.6 m ahead (in range, a few
  // dropouts), the top row looks 0.4° below the horizon at ground ~70 m away (out of range: only
  // the odd object has depth there).
  const std::uint16_t ground_mm = depth.at<std::uint16_t>(400, 320);
  EXPECT_GT(ground_mm, 700);
  EXPECT_LT(ground_mm, 2000);
  EXPECT_GT(cv::countNonZero(depth.row(479)), 0.9 * 640);
  EXPECT_LT(cv::countNonZero(depth.row(0)), 0.5 * 640);
}

TEST(SimRecorder, SameSeedSameBagOtherSeedOtherBag) {
  test::TempDir dir;
  Record(dir / "a", 3, 1);
  Record(dir / "b", 3, 1);
  Record(dir / "c", 4, 1);
  const Decoded a = ReadBag(dir / "a" / "bag"), b = ReadBag(dir / "b" / "bag"),
                c = ReadBag(dir / "c" / "bag");
  EXPECT_EQ(a.stamps, b.stamps);
  EXPECT_EQ(a.scans, b.scans);
  EXPECT_EQ(a.odometry, b.odometry);
  EXPECT_EQ(a.imu, b.imu);
  EXPECT_EQ(a.tf, b.tf);
  ASSERT_EQ(a.colour.size(), 10u);
  EXPECT_EQ(a.colour, b.colour);  // the same JPEG and PNG bytes, so the same decoded images
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.colour_info, b.colour_info);
  EXPECT_NE(a.scans, c.scans);
  ASSERT_EQ(c.colour.size(), a.colour.size());
  for (std::size_t k = 0; k < a.colour.size(); ++k) {
    // Another seed is another park: the decoded images differ, not just their bytes.
    EXPECT_GT(cv::norm(bag::DecodeColor(a.colour[k]), bag::DecodeColor(c.colour[k]), cv::NORM_L1),
              0);
    EXPECT_GT(cv::norm(bag::DecodeDepthMm(a.depth[k]), bag::DecodeDepthMm(c.depth[k]), cv::NORM_L1),
              0);
  }
}

TEST(SimRecorder, ExistingBagIsAUsageErrorAndTruthIsNotWritten) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "bag");
  std::ofstream(dir / "bag" / "keep.txt") << "mine";
  EXPECT_THROW(Record(dir.path(), 1, 1), UsageError);
  EXPECT_TRUE(std::filesystem::exists(dir / "bag" / "keep.txt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "truth"));
}

}  // namespace
}  // namespace littermap::sim
