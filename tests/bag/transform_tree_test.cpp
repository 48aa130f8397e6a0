// Fixed transforms from /tf_static and /tf: chains are composed, moving transforms left out,
// and a bag with its extrinsics on /tf only gives the same camera set-up as /tf_static.

#include <gtest/gtest.h>

#include "bag/bag_reader.hpp"
#include "bag/bag_writer.hpp"
#include "bag/camera_setup.hpp"
#include "bag/sensor_messages.hpp"
#include "bag/transform_tree.hpp"
#include "support/temp_dir.hpp"

namespace littermap::bag {
namespace {

msg::TransformStamped Edge(const std::string& parent, const std::string& child, double x,
                           double yaw_rad) {
  msg::TransformStamped t;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.rotation.z = std::sin(yaw_rad / 2);
  t.transform.rotation.w = std::cos(yaw_rad / 2);
  return t;
}

TEST(TransformTree, ComposesChainsAndSkipsMovingTransforms) {
  TransformTree tree;
  tree.Add({{Edge("base_link", "mast", 0.1, M_PI / 2)}}, true);
  tree.Add({{Edge("mast", "laser_front", 0.2, 0)}}, false);
  tree.Add({{Edge("odom", "base_link", 1.0, 0)}}, false);
  tree.Add({{Edge("mast", "laser_front", 0.2, 0)}}, false);  // again, unchanged: fixed
  tree.Add({{Edge("odom", "base_link", 1.5, 0)}}, false);    // moved: not fixed

  const auto T_base_laser = tree.Lookup("base_link", "laser_front");
  ASSERT_TRUE(T_base_laser);
  // mast is turned 90° left: its x axis is base_link's y axis.
  EXPECT_NEAR(T_base_laser->translation().x(), 0.1, 1e-12);
  EXPECT_NEAR(T_base_laser->translation().y(), 0.2, 1e-12);
  const auto T_laser_base = tree.Lookup("laser_front", "base_link");
  ASSERT_TRUE(T_laser_base);
  EXPECT_TRUE((*T_laser_base * *T_base_laser).isApprox(Eigen::Isometry3d::Identity(), 1e-12));
  EXPECT_FALSE(tree.Lookup("odom", "laser_front")) << "odom -> base_link moves";
  EXPECT_FALSE(tree.Lookup("base_link", "camera"));
  EXPECT_TRUE(tree.Lookup("camera", "camera")) << "a frame is its own parent";
}

TEST(TransformTree, CameraExtrinsicFromTfLikeFromTfStatic) {
  test::TempDir dir;
  Eigen::Isometry3d T_base_optical = Eigen::Isometry3d::Identity();
  T_base_optical.translation() = Eigen::Vector3d(0.2, 0.0, 0.5);
  T_base_optical.linear() =
      Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  msg::CameraInfo info;
  info.header.frame_id = "cam_optical";
  info.width = 640;
  {
    BagWriter writer(dir / "tf");
    writer.AddTopic<msg::CameraInfo>("/camera/color/camera_info");
    writer.AddTopic<msg::TFMessage>("/tf");
    for (int i = 0; i < 3; ++i) {
      msg::TFMessage tf{
          {Edge("odom", "base_link", 0.1 * i, 0),
           sensor_messages::TransformFromBase(i * 100, "cam_optical", T_base_optical)}};
      writer.WriteMessage("/tf", i * 100, tf);
    }
    writer.WriteMessage("/camera/color/camera_info", 50, info);
  }
  const CameraSetup setup = ReadCameraSetup(dir / "tf", RunTopics{});
  EXPECT_EQ(setup.info.width, 640u);
  EXPECT_TRUE(setup.T_base_camera.isApprox(T_base_optical, 1e-12));

  {
    BagWriter writer(dir / "none");
    writer.AddTopic<msg::CameraInfo>("/camera/color/camera_info");
    writer.WriteMessage("/camera/color/camera_info", 50, info);
  }
  try {
    ReadCameraSetup(dir / "none", RunTopics{});
    FAIL() << "no extrinsic, no error";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("(or cam_optical) transform on /tf_static or /tf"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(ReadCameraSetup(dir / "none", RunTopics{}, Extrinsic::kOptional)
                  .T_base_camera.isApprox(Eigen::Isometry3d::Identity()));
}

}  // namespace
}  // namespace littermap::bag
