// Simulated runs as bags: the topics of a real capture, and the same seed gives the same bag.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <variant>
#include <vector>

#include "capture/bag_reader.hpp"
#include "capture/message_stream.hpp"
#include "capture/sim_recorder.hpp"
#include "capture/topics.hpp"
#include "core/error.hpp"
#include "sim/world_spec.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

const std::filesystem::path kWorld =
    std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" / "worlds" / "park_small.yaml";

struct Decoded {
  std::vector<TimestampNs> stamps;
  std::vector<msg::LaserScan> scans;
  std::vector<msg::Odometry> odometry;
  std::vector<msg::Imu> imu;
  std::vector<msg::TFMessage> tf;
};

Decoded ReadBag(const std::filesystem::path& path) {
  BagReader reader(path);
  MessageStream stream(reader);
  Decoded decoded;
  while (auto message = stream.Next()) {
    decoded.stamps.push_back(message->timestamp_ns);
    if (auto* scan = std::get_if<msg::LaserScan>(&message->message)) decoded.scans.push_back(*scan);
    if (auto* odom = std::get_if<msg::Odometry>(&message->message))
      decoded.odometry.push_back(*odom);
    if (auto* imu = std::get_if<msg::Imu>(&message->message)) decoded.imu.push_back(*imu);
    if (auto* tf = std::get_if<msg::TFMessage>(&message->message)) decoded.tf.push_back(*tf);
  }
  return decoded;
}

SimRecordResult Record(const std::filesystem::path& dir, std::uint64_t seed, double duration_s) {
  SimRecordOptions options;
  options.seed = seed;
  options.max_duration_s = duration_s;
  return RecordSimulation(sim::LoadWorldSpec(kWorld), dir / "bag", dir / "truth", options);
}

TEST(SimRecorder, WritesTheTopicsOfARealCapture) {
  testing::TempDir dir;
  const SimRecordResult result = Record(dir.path(), 7, 5);
  EXPECT_EQ(result.scans, 51u);      // 10 Hz over 0..5 s
  EXPECT_EQ(result.odometry, 251u);  // 50 Hz
  EXPECT_EQ(result.imu, 251u);
  const Decoded bag = ReadBag(dir / "bag");
  ASSERT_EQ(bag.scans.size(), 51u);
  EXPECT_EQ(bag.scans[0].ranges.size(), 682u);
  EXPECT_EQ(bag.scans[0].header.frame_id, "laser");
  EXPECT_FLOAT_EQ(bag.scans[0].range_max, 5.6f);
  EXPECT_EQ(bag.odometry.size(), 251u);
  EXPECT_EQ(bag.odometry[0].header.frame_id, "odom");
  EXPECT_EQ(bag.odometry[0].child_frame_id, "base_link");
  EXPECT_DOUBLE_EQ(bag.odometry[0].pose.pose.position.x, 0);  // odometry starts at its origin
  EXPECT_GT(bag.odometry.back().pose.pose.position.x, 1.5);   // ~0.6 m/s ahead
  ASSERT_EQ(bag.tf.size(), 1u);
  ASSERT_EQ(bag.tf[0].transforms.size(), 2u);
  EXPECT_EQ(bag.tf[0].transforms[0].child_frame_id, frames::kLaser);
  EXPECT_DOUBLE_EQ(bag.tf[0].transforms[0].transform.translation.z, 0.3);
  EXPECT_EQ(bag.tf[0].transforms[1].child_frame_id, frames::kCamera);
  // Level robot: the IMU's gravity points up the base z axis.
  EXPECT_NEAR(bag.imu[0].linear_acceleration.z, 9.81, 0.1);
  EXPECT_TRUE(std::is_sorted(bag.stamps.begin(), bag.stamps.end()));
  EXPECT_TRUE(std::filesystem::exists(dir / "truth" / "trajectory.tum"));
}

TEST(SimRecorder, SameSeedSameBagOtherSeedOtherBag) {
  testing::TempDir dir;
  Record(dir / "a", 3, 3);
  Record(dir / "b", 3, 3);
  Record(dir / "c", 4, 3);
  const Decoded a = ReadBag(dir / "a" / "bag"), b = ReadBag(dir / "b" / "bag"),
                c = ReadBag(dir / "c" / "bag");
  EXPECT_EQ(a.stamps, b.stamps);
  EXPECT_EQ(a.scans, b.scans);
  EXPECT_EQ(a.odometry, b.odometry);
  EXPECT_EQ(a.imu, b.imu);
  EXPECT_EQ(a.tf, b.tf);
  EXPECT_NE(a.scans, c.scans);
}

TEST(SimRecorder, ExistingBagIsAUsageErrorAndTruthIsNotWritten) {
  testing::TempDir dir;
  std::filesystem::create_directories(dir / "bag");
  std::ofstream(dir / "bag" / "keep.txt") << "mine";
  EXPECT_THROW(Record(dir.path(), 1, 1), UsageError);
  EXPECT_TRUE(std::filesystem::exists(dir / "bag" / "keep.txt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "truth"));
}

}  // namespace
}  // namespace littermap
