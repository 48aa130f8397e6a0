// CARMEN import on the real Radish logs of shared/datasets/carmen (README table), read back from
// the bag, plus synthetic logs for the cases the real ones lack (ROBOTLASER1, a laser offset,
// damaged input).

#include "importers/carmen_importer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "bag/bag_reader.hpp"
#include "bag/topics.hpp"
#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::importers {
namespace {

std::filesystem::path CarmenLogPath(const std::string& name) {
  return std::filesystem::path(LITTERMAP_DATASETS_DIR) / "carmen" / name;
}

struct BagContents {
  std::vector<TimestampNs> scan_times;
  std::vector<msg::LaserScan> scans;
  std::vector<msg::Odometry> odometry;
  std::vector<msg::TFMessage> tf_static;
};

BagContents ReadContents(const std::filesystem::path& bag) {
  BagContents contents;
  bag::BagReader reader(bag);
  while (auto message = reader.Next()) {
    const std::string& topic = message->topic->name;
    if (topic == topics::kScan) {
      contents.scan_times.push_back(message->timestamp_ns);
      contents.scans.push_back(bag::Decode<msg::LaserScan>(message->data));
    } else if (topic == topics::kOdometry) {
      contents.odometry.push_back(bag::Decode<msg::Odometry>(message->data));
    } else if (topic == topics::kTfStatic) {
      contents.tf_static.push_back(bag::Decode<msg::TFMessage>(message->data));
    }
  }
  return contents;
}

TimestampNs StampNs(const msg::Time& time) {
  return time.sec * kNanosecondsPerSecond + static_cast<TimestampNs>(time.nanosec);
}

TEST(CarmenImport, IntelReadsBackFromTheBag) {
  const auto log_path = CarmenLogPath("intel-corrected.log.gz");
  ASSERT_TRUE(std::filesystem::exists(log_path)) << "missing data set " << log_path;
  test::TempDir dir;
  CarmenImportOptions options;
  options.reference_path = dir / "ref.tum";
  const CarmenImportResult result = ImportCarmenLog(log_path, dir / "bag", options);
  EXPECT_EQ(result.scan_count, 910u);
  EXPECT_EQ(result.odometry_count, 910u);
  EXPECT_EQ(result.beam_count_min, 180u);
  EXPECT_EQ(result.beam_count_max, 180u);
  EXPECT_EQ(result.skipped_types.at("NEFF"), 910u);
  // intel has 4 stamps that go backwards (README: "a few repeated ones").
  EXPECT_EQ(result.stamps_changed, 4u);
  EXPECT_FALSE(result.stamps_synthesised);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("4 of 910"), std::string::npos) << result.warnings[0];

  const BagContents bag = ReadContents(dir / "bag");
  ASSERT_EQ(bag.scans.size(), 910u);
  ASSERT_EQ(bag.odometry.size(), 910u);
  ASSERT_EQ(bag.tf_static.size(), 1u);
  const msg::LaserScan& first = bag.scans.front();
  EXPECT_EQ(first.header.frame_id, frames::kLaser);
  ASSERT_EQ(first.ranges.size(), 180u);
  EXPECT_FLOAT_EQ(first.ranges[0], 1.09f);  // the first beam of the log's first FLASER line
  EXPECT_FLOAT_EQ(first.angle_min, static_cast<float>(-std::numbers::pi / 2));
  EXPECT_FLOAT_EQ(first.angle_increment, static_cast<float>(std::numbers::pi / 180));
  EXPECT_GT(81.83f, first.range_max) << "intel's 81.83 m readings mean no return";
  EXPECT_GT(first.range_max, 80.0f);
  EXPECT_EQ(StampNs(first.header.stamp), 32'906'800'000);  // FLASER time stamp 32.9068
  for (std::size_t i = 1; i < bag.scan_times.size(); ++i) {
    ASSERT_GT(bag.scan_times[i], bag.scan_times[i - 1]) << "scan " << i;
    ASSERT_EQ(StampNs(bag.scans[i].header.stamp), bag.scan_times[i]);
  }
  const msg::Odometry& odom = bag.odometry.front();
  EXPECT_EQ(odom.header.frame_id, frames::kOdom);
  EXPECT_EQ(odom.child_frame_id, frames::kBase);
  EXPECT_DOUBLE_EQ(odom.pose.pose.position.x, 0.600266);  // odom_x of the first FLASER line
  EXPECT_NEAR(2 * std::atan2(odom.pose.pose.orientation.z, odom.pose.pose.orientation.w), -0.354665,
              1e-12);
  const msg::TransformStamped& laser = bag.tf_static[0].transforms.at(0);
  EXPECT_EQ(laser.header.frame_id, frames::kBase);
  EXPECT_EQ(laser.child_frame_id, frames::kLaser);
  EXPECT_EQ(laser.transform.translation.x, 0.0);  // PARAM robot_frontlaser_offset 0.0

  const std::vector<StampedPose> reference = bag::ReadTumTrajectory(dir / "ref.tum");
  ASSERT_EQ(reference.size(), 910u);
  EXPECT_EQ(reference[0].stamp_ns, bag.scan_times[0]);
  EXPECT_EQ(reference[909].stamp_ns, bag.scan_times[909]);
  EXPECT_NEAR(reference[0].position_m.x(), 0.600266, 1e-6);
}

struct LogFacts {
  const char* file;
  std::uint64_t scans;
  std::size_t beams;
};

// The README's table.
constexpr LogFacts kLogs[] = {
    {"intel-corrected.log.gz", 910, 180},        {"aces-corrected.log.gz", 440, 180},
    {"csail-corrected.log.gz", 406, 361},        {"freiburg-campus-corrected.log.gz", 2008, 360},
    {"seattle-corrected.log.gz", 241, 361},      {"orebro-corrected.log.gz", 237, 181},
    {"freiburg-101-corrected.log.gz", 292, 360}, {"edmonton-corrected.log.gz", 340, 180},
    {"acapulco-corrected.log.gz", 861, 181},
};

TEST(CarmenImport, EveryLogMatchesTheReadmeTable) {
  for (const LogFacts& facts : kLogs) {
    SCOPED_TRACE(facts.file);
    const auto log_path = CarmenLogPath(facts.file);
    ASSERT_TRUE(std::filesystem::exists(log_path)) << "missing data set " << log_path;
    test::TempDir dir;
    const CarmenImportResult result = ImportCarmenLog(log_path, dir / "bag");
    EXPECT_EQ(result.scan_count, facts.scans);
    EXPECT_EQ(result.beam_count_min, facts.beams);
    EXPECT_EQ(result.beam_count_max, facts.beams);
    // In the corrected logs the laser pose is the robot pose: the laser sits at base_link.
    // freiburg-101 and freiburg-campus declare robot_frontlaser_offset -0.04 m all the same:
    // that is warned about, and the poses win (see carmen_laser.cpp).
    EXPECT_TRUE(result.mounting.constant) << result.mounting.note;
    EXPECT_LT(result.mounting.spread_m, 1e-6);
    EXPECT_EQ(result.mounting.source, LaserMounting::Source::kPoses);
    EXPECT_EQ(result.mounting.T_base_laser, PlanarPose{});
    EXPECT_GT(result.ranges.no_return_readings, 0u) << "every log has no-return readings";
    bag::BagReader reader(dir / "bag");
    ASSERT_NE(reader.info().FindTopic(topics::kScan), nullptr);
    EXPECT_EQ(reader.info().FindTopic(topics::kScan)->message_count, facts.scans);
    EXPECT_EQ(reader.info().FindTopic(topics::kOdometry)->message_count, facts.scans);
    EXPECT_EQ(reader.info().FindTopic(topics::kTfStatic)->message_count, 1u);
  }
}

TEST(CarmenImport, CsailGetsSynthesisedMonotonicStamps) {
  const auto log_path = CarmenLogPath("csail-corrected.log.gz");
  ASSERT_TRUE(std::filesystem::exists(log_path)) << "missing data set " << log_path;
  test::TempDir dir;
  const CarmenImportResult result = ImportCarmenLog(log_path, dir / "bag");
  EXPECT_TRUE(result.stamps_synthesised);
  EXPECT_GE(result.stamps_changed, 405u);
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_NE(result.warnings[0].find("synthesised"), std::string::npos) << result.warnings[0];
  const BagContents bag = ReadContents(dir / "bag");
  ASSERT_EQ(bag.scans.size(), 406u);
  for (std::size_t i = 1; i < bag.scans.size(); ++i) {
    ASSERT_GT(bag.scan_times[i], bag.scan_times[i - 1]) << "scan " << i;
  }
  EXPECT_GT(bag.scan_times.front(), 0) << "a zero stamp reads as 'no time' in ROS";
}

TEST(CarmenImport, RobotLaser1AnglesAndLaserOffsetReachTheBag) {
  test::TempDir dir;
  // The laser is 0.2 m ahead of the robot centre, turned by 0.1 rad; the robot turns in place.
  std::ofstream log(dir / "robot.log");
  log.precision(15);
  for (int i = 0; i < 3; ++i) {
    const double theta = 0.3 * i;
    const double laser_x = 1.0 + 0.2 * std::cos(theta);
    const double laser_y = 2.0 + 0.2 * std::sin(theta);
    log << "ROBOTLASER1 0 -1.0 2.0 0.5 30.0 0.01 0 5 1 2 3 30 5 0 " << laser_x << " " << laser_y
        << " " << theta + 0.1 << " 1.0 2.0 " << theta << " 0 0 0 0 0 " << 10 + i << " host 0\n";
  }
  log.close();
  const CarmenImportResult result = ImportCarmenLog(dir / "robot.log", dir / "bag");
  EXPECT_TRUE(result.mounting.constant) << result.mounting.note;
  EXPECT_NEAR(result.mounting.T_base_laser.x_m, 0.2, 1e-9);
  EXPECT_NEAR(result.mounting.T_base_laser.y_m, 0.0, 1e-9);
  EXPECT_NEAR(result.mounting.T_base_laser.theta_rad, 0.1, 1e-9);
  const BagContents bag = ReadContents(dir / "bag");
  ASSERT_EQ(bag.scans.size(), 3u);
  EXPECT_FLOAT_EQ(bag.scans[0].angle_min, -1.0f);
  EXPECT_FLOAT_EQ(bag.scans[0].angle_increment, 0.5f);
  EXPECT_FLOAT_EQ(bag.scans[0].angle_max, 1.0f);
  EXPECT_LT(bag.scans[0].range_max, 30.0f) << "ROBOTLASER1's maximum_range means no return";
  EXPECT_GT(bag.scans[0].range_max, 29.99f);
  EXPECT_NEAR(bag.tf_static.at(0).transforms.at(0).transform.translation.x, 0.2, 1e-9);
}

TEST(CarmenImport, ConstantPoseOffsetWinsOverADisagreeingParam) {
  // As in freiburg-101 and freiburg-campus: the PARAM says -0.04 m, the poses say 0.
  test::TempDir dir;
  std::ofstream(dir / "a.log")
      << "PARAM robot_frontlaser_offset -0.04 nohost 0\n"
         "FLASER 3 1 2 3 0 0 0 0 0 0 1.0\nFLASER 3 1 2 3 1 0 0 1 0 0 2.0\n";
  const CarmenImportResult result = ImportCarmenLog(dir / "a.log", dir / "bag");
  EXPECT_EQ(result.mounting.source, LaserMounting::Source::kPoses);
  EXPECT_TRUE(result.mounting.constant);
  EXPECT_EQ(result.mounting.T_base_laser, PlanarPose{});
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("PARAM robot_frontlaser_offset"), std::string::npos)
      << result.warnings[0];
}

TEST(CarmenImport, ParamOffsetIsUsedWhenThePosesDisagree) {
  test::TempDir dir;
  std::ofstream(dir / "a.log") << "PARAM robot_frontlaser_offset 0.25 nohost 0\n"
                                  "FLASER 3 1 2 3 0.2 0 0 0 0 0 1.0\nFLASER 3 1 2 3 0.3 0 0 0 0 0 "
                                  "2.0\nFLASER 3 1 2 3 0.26 0 0 0 0 0 3.0\n";
  const CarmenImportResult result = ImportCarmenLog(dir / "a.log", dir / "bag");
  EXPECT_EQ(result.mounting.source, LaserMounting::Source::kParam);
  EXPECT_FALSE(result.mounting.constant);
  EXPECT_DOUBLE_EQ(result.mounting.T_base_laser.x_m, 0.25);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("varies between scans"), std::string::npos)
      << result.warnings[0];
}

TEST(CarmenImport, MalformedLogFailsBeforeCreatingTheBag) {
  test::TempDir dir;
  std::ofstream(dir / "bad.log") << "FLASER 3 1 2 3 0 0 0 0 0 0 1.0\nFLASER 3 1 oops 3 0 0 0 0 0 0 "
                                    "2.0\n";
  try {
    ImportCarmenLog(dir / "bad.log", dir / "bag");
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& error) {
    EXPECT_NE(std::string(error.what()).find("bad.log:2: FLASER field 'range[1]'"),
              std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

TEST(CarmenImport, TruncatedGzipIsBadInputAndLeavesNoBag) {
  const auto log_path = CarmenLogPath("aces-corrected.log.gz");
  ASSERT_TRUE(std::filesystem::exists(log_path)) << "missing data set " << log_path;
  test::TempDir dir;
  std::ifstream in(log_path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "cut.log.gz", std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
  try {
    ImportCarmenLog(dir / "cut.log.gz", dir / "bag");
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cut.log.gz"), std::string::npos) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
    EXPECT_NE(message.find("after line"), std::string::npos) << message;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bag"));
}

TEST(CarmenImport, FailedBagLeavesNoReferenceBehind) {
  test::TempDir dir;
  std::ofstream(dir / "a.log") << "FLASER 3 1 2 3 0 0 0 0 0 0 1.0\n";
  std::filesystem::create_directories(dir / "bag");
  std::ofstream(dir / "bag" / "precious.txt") << "not a bag";
  CarmenImportOptions options;
  options.reference_path = dir / "ref.tum";
  EXPECT_THROW(ImportCarmenLog(dir / "a.log", dir / "bag", options), UsageError);
  EXPECT_TRUE(std::filesystem::exists(dir / "bag" / "precious.txt")) << "never touch old files";
  EXPECT_FALSE(std::filesystem::exists(dir / "ref.tum"));
}

TEST(CarmenImport, LogWithoutScansIsBadInput) {
  test::TempDir dir;
  std::ofstream(dir / "odom.log") << "ODOM 0 0 0 0 0 0 1\n";
  EXPECT_THROW(ImportCarmenLog(dir / "odom.log", dir / "bag"), BadInputError);
}

TEST(CarmenImport, NoisyOdometryStartsAtTheReferenceAndDrifts) {
  const auto log_path = CarmenLogPath("orebro-corrected.log.gz");
  ASSERT_TRUE(std::filesystem::exists(log_path)) << "missing data set " << log_path;
  test::TempDir dir;
  CarmenImportOptions options;
  options.odometry_noise_seed = 7;
  options.reference_path = dir / "ref.tum";
  const CarmenImportResult result = ImportCarmenLog(log_path, dir / "bag", options);
  EXPECT_TRUE(result.noisy_odometry);
  const BagContents bag = ReadContents(dir / "bag");
  const std::vector<StampedPose> reference = bag::ReadTumTrajectory(dir / "ref.tum");
  ASSERT_EQ(bag.odometry.size(), reference.size());
  EXPECT_NEAR(bag.odometry[0].pose.pose.position.x, reference[0].position_m.x(), 1e-6);
  const auto& last = bag.odometry.back().pose.pose.position;
  EXPECT_GT(std::hypot(last.x - reference.back().position_m.x(),
                       last.y - reference.back().position_m.y()),
            0.1);
  for (std::size_t i = 0; i < bag.odometry.size(); ++i) {
    ASSERT_EQ(StampNs(bag.odometry[i].header.stamp), reference[i].stamp_ns);
  }
}

}  // namespace
}  // namespace littermap::importers
