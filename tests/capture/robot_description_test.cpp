#include "capture/robot_description.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "bag/message_header.hpp"
#include "bag/topics.hpp"
#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::capture {
namespace {

std::filesystem::path Write(const test::TempDir& dir, const std::string& text) {
  const auto path = dir / "robot.yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(RobotDescription, MountsBecomeStaticTransforms) {
  test::TempDir dir;
  const RobotDescription robot = ReadRobotDescription(Write(dir, R"(
laser:
  mount: {x_m: 0.15, z_m: 0.30, yaw_deg: 90}
camera:
  mount: {x_m: 0.20, y_m: -0.05, z_m: 0.50, pitch_deg: 25}
)"));
  EXPECT_TRUE(robot.T_base_laser.translation().isApprox(Eigen::Vector3d(0.15, 0, 0.30)));
  // Laser yawed 90°: its x axis points along base_link's y.
  EXPECT_TRUE((robot.T_base_laser.linear() * Eigen::Vector3d::UnitX())
                  .isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  // Optical z (viewing direction) is the body's x pitched 25° down; optical x points right.
  const Eigen::Vector3d view = robot.T_base_optical.linear() * Eigen::Vector3d::UnitZ();
  const double pitch = 25 * M_PI / 180;
  EXPECT_TRUE(view.isApprox(Eigen::Vector3d(std::cos(pitch), 0, -std::sin(pitch)), 1e-12));
  EXPECT_TRUE((robot.T_base_optical.linear() * Eigen::Vector3d::UnitX())
                  .isApprox(-Eigen::Vector3d::UnitY(), 1e-12));

  const msg::TFMessage tf = StaticTransforms(1'700'000'000'000'000'000, robot);
  ASSERT_EQ(tf.transforms.size(), 2u);
  EXPECT_EQ(tf.transforms[0].header.frame_id, frames::kBase);
  EXPECT_EQ(tf.transforms[0].child_frame_id, frames::kLaser);
  EXPECT_EQ(tf.transforms[1].child_frame_id, frames::kCamera);
  EXPECT_TRUE(bag::ToIsometry(tf.transforms[1].transform).isApprox(robot.T_base_optical, 1e-12));
}

TEST(RobotDescription, ErrorsNameTheFileAndKey) {
  test::TempDir dir;
  const auto expect_error = [&](const std::string& text, const std::string& part) {
    const auto path = Write(dir, text);
    try {
      ReadRobotDescription(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const BadInputError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      EXPECT_NE(what.find(part), std::string::npos) << what;
    }
  };
  expect_error("laser:\n  mount: {x_m: forward}\n", "laser.mount.x_m");
  expect_error("laser:\n  mount: {z: 0.3}\n", "laser.mount.z");
  expect_error("lidar:\n  mount: {}\n", "lidar");
  expect_error("laser: [1, 2\n", "not valid YAML");
  try {
    ReadRobotDescription(dir / "missing.yaml");
    ADD_FAILURE() << "a missing file was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kBadInput) << e.what();
    EXPECT_NE(std::string(e.what()).find("missing.yaml: cannot read: No such file"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace littermap::capture
