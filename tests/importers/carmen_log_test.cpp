// The CARMEN line parser and log reader: every record type, and malformed lines reported by
// file, line and field.

#include "importers/carmen_log.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::importers {
namespace {

// The message of the BadInputError that parsing `line` throws ("" if it does not throw).
std::string ParseError(const std::string& line) {
  try {
    ParseCarmenLine(line);
  } catch (const BadInputError& error) {
    return error.what();
  }
  return "";
}

TEST(CarmenLog, ParsesFlaser) {
  // A line of intel-corrected.log, shortened to 4 beams.
  const CarmenRecord record = ParseCarmenLine(
      "FLASER 4 1.09 1.08 81.83 1.1 0.600266 -0.0320327 -0.354665 0.5 -0.03 -0.35 32.9068 "
      "pippo 32.9068");
  const auto scan = std::get<CarmenLaserRecord>(record);
  EXPECT_EQ(scan.kind, CarmenLaserRecord::Kind::kFlaser);
  EXPECT_FALSE(scan.has_geometry);
  ASSERT_EQ(scan.ranges_m.size(), 4u);
  EXPECT_FLOAT_EQ(scan.ranges_m[2], 81.83f);
  EXPECT_DOUBLE_EQ(scan.laser_pose.x_m, 0.600266);
  EXPECT_DOUBLE_EQ(scan.laser_pose.theta_rad, -0.354665);
  EXPECT_DOUBLE_EQ(scan.robot_pose.x_m, 0.5);
  EXPECT_DOUBLE_EQ(scan.robot_pose.theta_rad, -0.35);
  EXPECT_DOUBLE_EQ(scan.timestamp_s, 32.9068);
}

TEST(CarmenLog, TrailingHostAndLoggerStampAreOptional) {
  const auto scan = std::get<CarmenLaserRecord>(ParseCarmenLine("FLASER 1 2.5 0 0 0 0 0 0 7.5"));
  EXPECT_DOUBLE_EQ(scan.timestamp_s, 7.5);
}

TEST(CarmenLog, ParsesRobotLaser1WithItsAngles) {
  const CarmenRecord record = ParseCarmenLine(
      "ROBOTLASER1 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 3 1.0 2.0 3.0 2 0.5 0.6 "
      "1.0 2.0 0.1 0.8 2.0 0.1 0.3 0.02 0.5 0.4 0.0 1134863807.66 b21 1134863807.67");
  const auto scan = std::get<CarmenLaserRecord>(record);
  EXPECT_EQ(scan.kind, CarmenLaserRecord::Kind::kRobotLaser1);
  EXPECT_TRUE(scan.has_geometry);
  EXPECT_DOUBLE_EQ(scan.start_angle_rad, -1.5708);
  EXPECT_DOUBLE_EQ(scan.angular_resolution_rad, 0.0174533);
  EXPECT_DOUBLE_EQ(scan.max_range_m, 81.9);
  EXPECT_EQ(scan.ranges_m, (std::vector<float>{1, 2, 3}));
  EXPECT_DOUBLE_EQ(scan.laser_pose.x_m, 1.0);
  EXPECT_DOUBLE_EQ(scan.robot_pose.x_m, 0.8);
  EXPECT_DOUBLE_EQ(scan.timestamp_s, 1134863807.66);
}

TEST(CarmenLog, ParsesOdomParamCommentsAndUnknownTypes) {
  const auto odom = std::get<CarmenOdomRecord>(
      ParseCarmenLine("ODOM 0.255856 0.0163473 0.618883 0.1 0.2 0.3 6.979 pippo 6.979"));
  EXPECT_DOUBLE_EQ(odom.pose.y_m, 0.0163473);
  EXPECT_DOUBLE_EQ(odom.rv_radps, 0.2);
  EXPECT_DOUBLE_EQ(odom.timestamp_s, 6.979);
  const auto param =
      std::get<CarmenParamRecord>(ParseCarmenLine("PARAM robot_frontlaser_offset 0.0 nohost 0"));
  EXPECT_EQ(param.name, "robot_frontlaser_offset");
  EXPECT_EQ(param.value, "0.0");
  EXPECT_TRUE(std::holds_alternative<CarmenCommentRecord>(ParseCarmenLine("# PARAM x y")));
  EXPECT_TRUE(std::holds_alternative<CarmenCommentRecord>(ParseCarmenLine("#PARAM x y")));
  EXPECT_TRUE(std::holds_alternative<CarmenCommentRecord>(ParseCarmenLine("   \t")));
  EXPECT_EQ(std::get<CarmenOtherRecord>(ParseCarmenLine("NEFF 30")).type, "NEFF");
}

TEST(CarmenLog, MalformedLinesNameTheField) {
  EXPECT_EQ(ParseError("FLASER 2 1.0 x 0 0 0 0 0 0 1"),
            "FLASER field 'range[1]': 'x' is not a finite number");
  EXPECT_EQ(ParseError("FLASER 2 1.0 2.0 0 0 0 0 0"), "FLASER field 'odom_theta': is missing");
  EXPECT_EQ(ParseError("ODOM 1 2 nan 0 0 0 5"), "ODOM field 'theta': 'nan' is not a finite number");
  EXPECT_NE(ParseError("FLASER 99999999 1 2").find("'num_readings'"), std::string::npos);
  EXPECT_NE(ParseError("FLASER -3 1 2").find("'num_readings'"), std::string::npos);
  EXPECT_NE(ParseError("FLASER 0 0 0 0 0 0 0 1").find("'num_readings'"), std::string::npos);
  EXPECT_NE(ParseError("FLASER 1 -2 0 0 0 0 0 0 1").find("'range[0]'"), std::string::npos);
  EXPECT_NE(ParseError("ODOM 1 2 3 0 0 0 5 host 5 extra").find("unexpected"), std::string::npos);
  EXPECT_NE(ParseError("PARAM lonely").find("'param_value'"), std::string::npos);
  EXPECT_NE(ParseError("ROBOTLASER1 0 -1.5 3.1 0.01 80 0.01 0 1 1.0 5").find("remission"),
            std::string::npos);
}

TEST(CarmenLog, ReadsAWholeLogWithParamsAndCommentsAnywhere) {
  test::TempDir dir;
  std::ofstream(dir / "a.log") << "# header\nPARAM robot_frontlaser_offset 0.1 nohost 0\n"
                                  "ODOM 0 0 0 0 0 0 1 h 1\nFLASER 2 1 2 0 0 0 0 0 0 1.5 h 1.5\n"
                                  "NEFF 30\nPARAM robot_frontlaser_offset 0.2\n# more\n\n"
                                  "FLASER 2 1 2 0 0 0 0 0 0 2.5 h 2.5\nRLASER 1 2\nNEFF 29\n";
  const CarmenLog log = ReadCarmenLog(dir / "a.log");
  EXPECT_EQ(log.line_count, 11u);
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.scan_line_numbers, (std::vector<std::uint64_t>{4, 9}));
  EXPECT_EQ(log.odometry.size(), 1u);
  EXPECT_EQ(log.params.at("robot_frontlaser_offset"), "0.2");
  EXPECT_EQ(log.skipped_types.at("NEFF"), 2u);
  EXPECT_EQ(log.skipped_types.at("RLASER"), 1u);
  EXPECT_EQ(log.comment_line_count, 3u);
}

TEST(CarmenLog, MalformedLineErrorNamesFileAndLine) {
  test::TempDir dir;
  std::ofstream(dir / "bad.log") << "# ok\nFLASER 2 1 2 0 0 0 0 0 0 1.5\nFLASER 2 1 2 0 0 0 0 0\n";
  try {
    ReadCarmenLog(dir / "bad.log");
    FAIL() << "expected BadInputError";
  } catch (const BadInputError& error) {
    EXPECT_EQ(std::string(error.what()),
              (dir / "bad.log").string() + ":3: FLASER field 'odom_theta': is missing");
  }
}

}  // namespace
}  // namespace littermap::importers
