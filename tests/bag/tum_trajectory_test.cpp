// TUM trajectory files: exact time stamps, round trips, and malformed lines named by line and
// field.

#include "bag/tum_trajectory.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

TEST(TumTrajectory, StampsAreExactDecimalSeconds) {
  EXPECT_EQ(FormatTumStamp(1'305'031'102'175'304'000), "1305031102.175304000");
  EXPECT_EQ(FormatTumStamp(5), "0.000000005");
  EXPECT_EQ(FormatTumStamp(-1'500'000'000), "-1.500000000");
  TimestampNs stamp = 0;
  ASSERT_TRUE(ParseTumStamp("1305031102.175304", &stamp));
  EXPECT_EQ(stamp, 1'305'031'102'175'304'000);  // no binary floating point on the way
  ASSERT_TRUE(ParseTumStamp("32.9068", &stamp));
  EXPECT_EQ(stamp, 32'906'800'000);
  ASSERT_TRUE(ParseTumStamp("7", &stamp));
  EXPECT_EQ(stamp, 7'000'000'000);
  ASSERT_TRUE(ParseTumStamp("0.0000000016", &stamp));  // rounded at the 10th digit
  EXPECT_EQ(stamp, 2);
  ASSERT_TRUE(ParseTumStamp("1.13486e+09", &stamp));
  EXPECT_EQ(stamp, 1'134'860'000'000'000'000);
  for (const char* bad : {"", ".", "-", "1.2.3", "12a", "nan", "1e300", "99999999999"}) {
    EXPECT_FALSE(ParseTumStamp(bad, &stamp)) << bad;
  }
}

TEST(TumTrajectory, WriteThenReadRoundTrips) {
  test::TempDir dir;
  std::vector<StampedPose> poses = {StampedPoseFromPlanar(1'000'000'001, {1.5, -2.25, 0.75}),
                                    StampedPoseFromPlanar(2'500'000'000, {0, 0, -3.0})};
  poses[1].position_m.z() = 0.125;
  WriteTumTrajectory(dir / "t.tum", poses);
  const std::vector<StampedPose> read = ReadTumTrajectory(dir / "t.tum");
  ASSERT_EQ(read.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(read[i].stamp_ns, poses[i].stamp_ns);
    EXPECT_LT((read[i].position_m - poses[i].position_m).norm(), 1e-6);
    EXPECT_LT(read[i].orientation.angularDistance(poses[i].orientation), 1e-8);
  }
  // Yaw about z, as planar poses are: theta = 0.75 gives qz = sin(0.375), qw = cos(0.375).
  EXPECT_NEAR(read[0].orientation.z(), std::sin(0.375), 1e-9);
  EXPECT_NEAR(read[0].orientation.w(), std::cos(0.375), 1e-9);
}

TEST(TumTrajectory, ReadsTumGroundTruthStyleFiles) {
  test::TempDir dir;
  std::ofstream(dir / "groundtruth.txt")
      << "# ground truth trajectory\n# file: 'rgbd_dataset_freiburg2_desk.bag'\n"
         "# timestamp tx ty tz qx qy qz qw\n"
         "1311868164.3646 -0.1346 -0.8521 1.4866 0.6513 0.6485 -0.2785 -0.2801\n\n"
         "1311868164.3746 -0.1345 -0.8524 1.4864 0.6514 0.6485 -0.2782 -0.2801\n";
  const std::vector<StampedPose> poses = ReadTumTrajectory(dir / "groundtruth.txt");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].stamp_ns, 1'311'868'164'364'600'000);
  EXPECT_DOUBLE_EQ(poses[1].position_m.z(), 1.4864);
  EXPECT_NEAR(poses[0].orientation.norm(), 1.0, 1e-12);  // normalised on reading
}

std::string ReadError(const std::filesystem::path& path) {
  try {
    ReadTumTrajectory(path);
  } catch (const BadInputError& error) {
    return error.what();
  }
  return "";
}

TEST(TumTrajectory, MalformedLinesNameLineAndField) {
  test::TempDir dir;
  std::ofstream(dir / "a.tum") << "# c\n1.0 0 0 0 0 0 0 1\n2.0 0 zero 0 0 0 0 1\n";
  EXPECT_EQ(ReadError(dir / "a.tum"),
            (dir / "a.tum").string() + ":3: field 'ty': 'zero' is not a finite number");
  std::ofstream(dir / "b.tum") << "1.0 0 0 0 0 0 0\n";
  EXPECT_NE(ReadError(dir / "b.tum").find(":1: expected 8 fields"), std::string::npos);
  std::ofstream(dir / "c.tum") << "1.0 0 0 0 0 0 0 2\n";
  EXPECT_NE(ReadError(dir / "c.tum").find("norm"), std::string::npos);
  std::ofstream(dir / "d.tum") << "yesterday 0 0 0 0 0 0 1\n";
  EXPECT_NE(ReadError(dir / "d.tum").find("'timestamp'"), std::string::npos);
  EXPECT_THROW(ReadTumTrajectory(dir / "missing.tum"), BadInputError);
  try {  // a folder that is not there: the path is at fault
    WriteTumTrajectory(dir / "no" / "such" / "dir.tum", {});
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput) << error.what();
  }
}

}  // namespace
}  // namespace littermap::bag
