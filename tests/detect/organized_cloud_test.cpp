// Normals of the organized cloud, by each estimator, on a ray-cast ground with a box on it: the
// ground's and the box top's point up, a box side's sideways, and a pixel next to a depth step
// (the box's top edge against the ground behind it) has none rather than a blend of the two.

#include "detect/organized_cloud.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "synthetic_scene.hpp"

namespace littermap::detect {
namespace {

using test::SceneBox;
using test::SyntheticScene;

double AngleDeg(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0f, 1.0f)) * 180.0 /
         std::numbers::pi;
}

double Percentile(std::vector<double> values, double share) {
  const auto k = static_cast<std::size_t>(share * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

// The depth image of a 30 cm box standing on the ground 1.2 m ahead.
cv::Mat BoxOnTheGround(const CameraIntrinsics& K) {
  SyntheticScene scene;
  scene.boxes.push_back({{1.2, -0.15, 0.0}, {1.5, 0.15, 0.3}, {30, 30, 200}});
  cv::Mat colour, depth_mm;
  RenderScene(scene, K, &colour, &depth_mm);
  return depth_mm;
}

class OrganizedCloudTest : public ::testing::TestWithParam<NormalMethod> {};

std::string MethodName(const ::testing::TestParamInfo<NormalMethod>& method) {
  return method.param == NormalMethod::kFals ? "Fals" : "Covariance";
}

INSTANTIATE_TEST_SUITE_P(Methods, OrganizedCloudTest,
                         ::testing::Values(NormalMethod::kCovariance, NormalMethod::kFals),
                         MethodName);

TEST_P(OrganizedCloudTest, GroundAndBoxFacesPointTheirWayAndADepthStepHasNone) {
  const CameraIntrinsics K;
  const cv::Mat depth_mm = BoxOnTheGround(K);
  OrganizedCloudOptions options;
  options.normal_method = GetParam();
  OrganizedCloudBuilder builder(options);
  OrganizedCloud cloud;
  builder.Build(depth_mm, K, test::CameraPose().cast<float>(), &cloud);

  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  std::vector<double> ground, top, front;  // each normal's angle from the face's, deg
  int next_to_step = 0, next_to_step_with_normal = 0;
  for (int v = 12; v < cloud.height - 12; ++v) {
    for (int u = 12; u < cloud.width - 12; ++u) {
      const int i = cloud.Index(u, v);
      if (!cloud.HasPoint(i)) continue;
      const Eigen::Vector3f& p = cloud.points_m[static_cast<std::size_t>(i)];
      const bool inside_x = p.x() > 1.25 && p.x() < 1.45, inside_y = std::abs(p.y()) < 0.1;
      // Where the box's top edge hides the ground behind it: a step of a metre or so in depth.
      const int below = cloud.Index(u, v - 1);
      if (cloud.HasPoint(below) && std::abs(cloud.depth_m[static_cast<std::size_t>(below)] -
                                            cloud.depth_m[static_cast<std::size_t>(i)]) > 0.3f) {
        ++next_to_step;
        next_to_step_with_normal += cloud.HasNormal(i) || cloud.HasNormal(below);
      }
      if (!cloud.HasNormal(i)) continue;
      const Eigen::Vector3f& n = cloud.normals[static_cast<std::size_t>(i)];
      if (std::abs(p.z()) < 0.01 && (p.x() < 1.0 || p.x() > 2.0)) {
        ground.push_back(AngleDeg(n, up));
      } else if (std::abs(p.z() - 0.3) < 0.01 && inside_x && inside_y) {
        top.push_back(AngleDeg(n, up));
      } else if (std::abs(p.x() - 1.2) < 0.01 && inside_y && p.z() > 0.05 && p.z() < 0.25) {
        front.push_back(AngleDeg(n, -Eigen::Vector3f::UnitX()));
      }
    }
  }
  ASSERT_GT(ground.size(), 50000u);
  ASSERT_GT(top.size(), 300u);
  ASSERT_GT(front.size(), 300u);
  ASSERT_GT(next_to_step, 50);
  // The depth has noise (sigma 1 mm at 1 m, 4 mm at 2 m) and millimetre steps: a normal from a
  // few pixels scatters by some degrees (FALS's 5 x 5 window more than PCL's 10 px: 4.9 against
  // 1.4 deg median on the front face), but stays well inside the 25 deg that tell the ground
  // from an object, and far from a blend of two faces (tens of degrees).
  for (const auto& [name, angles] :
       {std::pair("ground", &ground), std::pair("top", &top), std::pair("front", &front)}) {
    EXPECT_LT(Percentile(*angles, 0.5), 6.0) << name;
    EXPECT_LT(Percentile(*angles, 0.95), 15.0) << name;
    std::printf("%s: median %.2f deg, 95%% %.2f deg over %zu pixels\n", name,
                Percentile(*angles, 0.5), Percentile(*angles, 0.95), angles->size());
  }
  EXPECT_EQ(next_to_step_with_normal, 0);
}

// The cloud of points alone holds the same points as the cloud with normals, and no normals.
TEST(OrganizedCloudPoints, AreTheCloudsPointsWithoutNormals) {
  const CameraIntrinsics K;
  const cv::Mat depth_mm = BoxOnTheGround(K);
  const Eigen::Isometry3f T_level_camera = test::CameraPose().cast<float>();
  OrganizedCloudBuilder builder{OrganizedCloudOptions{}};
  OrganizedCloud cloud, points;
  builder.Build(depth_mm, K, T_level_camera, &cloud);
  BuildPoints(depth_mm, K, T_level_camera, OrganizedCloudOptions{}, &points);
  ASSERT_EQ(points.width, cloud.width);
  ASSERT_EQ(points.height, cloud.height);
  EXPECT_TRUE(points.normals.empty());
  ASSERT_EQ(points.points_m.size(), cloud.points_m.size());
  std::size_t with_depth = 0;
  for (std::size_t i = 0; i < cloud.points_m.size(); ++i) {
    ASSERT_EQ(points.depth_m[i], cloud.depth_m[i]) << i;
    if (!(cloud.depth_m[i] > 0)) continue;
    ++with_depth;
    ASSERT_TRUE(points.points_m[i].isApprox(cloud.points_m[i])) << i;
  }
  EXPECT_GT(with_depth, 200000u);
  // A depth image of the wrong size is refused as Build refuses it.
  cv::Mat half;
  cv::resize(depth_mm, half, {320, 240}, 0, 0, cv::INTER_NEAREST);
  EXPECT_THROW(BuildPoints(half, K, T_level_camera, OrganizedCloudOptions{}, &points), UsageError);
}

}  // namespace
}  // namespace littermap::detect
