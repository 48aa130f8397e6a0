// Tests of the simulated RGB-D camera against analytic geometry and the Kinect noise model.

#include "sim/rgbd_camera.hpp"
#include "sim/noiseless_camera.hpp"
#include "support/angles.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

namespace littermap::sim {
namespace {

using test::kDeg;

// Camera at `position` looking along world heading `yaw`, pitched down by `pitch_down` (rad).
Eigen::Isometry3d CameraPose(const Eigen::Vector3d& position, double yaw, double pitch_down) {
  Eigen::Matrix3d R_body_optical;  // optical z = body x, optical x = -body y, optical y = -body z
  R_body_optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = RotationFromRpy({0, pitch_down, yaw}) * R_body_optical;
  T.translation() = position;
  return T;
}

World FlatWorld() {
  World world;  // default Terrain: flat at height 0, all grass
  world.spec.size_x_m = 20;
  world.spec.size_y_m = 20;
  return world;
}

WorldObject Primitive(Shape shape, const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
                      const RollPitchYaw& rpy = {}) {
  WorldObject o;
  o.kind = ObjectKind::kLitter;
  o.label = "test";
  o.shape = shape;
  o.center_m = centre;
  o.size_m = size;
  o.orientation = rpy;
  o.colour_rgb = {0.8, 0.1, 0.1};
  o.texture = "aluminium";
  return o;
}

// Depth (m) along the optical axis at which pixel (u, v)'s ray meets the plane z = 0.
double AnalyticGroundDepth(const Eigen::Isometry3d& T, const PinholeCamera& k, int u, int v) {
  const Eigen::Vector3d ray = T.linear() * k.Ray(u, v);
  return -T.translation().z() / ray.z();
}

TEST(RgbdCameraTest, GroundDepthMatchesRayPlaneIntersection) {
  const World world = FlatWorld();
  const Eigen::Isometry3d T = CameraPose({5, 10, 0.5}, 0, 25 * kDeg);
  for (const bool quantise : {false, true}) {
    RgbdCameraOptions options = NoiselessCameraOptions();
    options.depth.quantise = quantise;
    const RgbdRender render = RenderRgbd(world, T, options, 1);
    const PinholeCamera& k = options.intrinsics;
    int checked = 0;
    for (int v = 240; v < 480; v += 20) {
      for (int u = 10; u < 640; u += 60) {
        const double z = AnalyticGroundDepth(T, k, u, v);
        if (z < 0.6 || z > 4.4) continue;
        // Quantisation error is at most half a disparity step: z²/(f b) · step / 2.
        const double step = quantise ? z * z / (580 * 0.075) / 8 : 0;
        const double tolerance_m = 0.0006 + 0.5 * step + 1e-5 * z;
        EXPECT_NEAR(render.depth_mm.at<std::uint16_t>(v, u) / 1000.0, z, tolerance_m)
            << "pixel " << u << "," << v << " quantise " << quantise;
        EXPECT_EQ(render.instance_ids.at<std::int32_t>(v, u), kGroundInstance);
        ++checked;
      }
    }
    EXPECT_GT(checked, 50);
  }
}

TEST(RgbdCameraTest, NoDepthBeyondMaxRangeAndAtGrazingIncidence) {
  const World world = FlatWorld();
  RgbdCameraOptions options;  // full noise model
  const Eigen::Isometry3d T = CameraPose({2, 10, 0.5}, 0, 5 * kDeg);
  const RgbdRender render = RenderRgbd(world, T, options, 7);
  double max_mm = 0;
  cv::minMaxLoc(render.depth_mm, nullptr, &max_mm);
  EXPECT_LE(max_mm, 4500);
  EXPECT_GT(render.stats.depth.grazing, 1000);  // ground beyond ~2.8 m meets the rays at > 80°
  EXPECT_GT(render.stats.depth.out_of_range, 1000);
  // A pixel whose ray meets the ground at 3.5 m lies at 82° incidence: no reading.
  const PinholeCamera& k = options.intrinsics;
  for (int v = 240; v < 480; ++v) {
    const double z = AnalyticGroundDepth(T, k, 320, v);
    if (z > 3.4 && z < 3.6) {
      EXPECT_EQ(render.depth_mm.at<std::uint16_t>(v, 320), 0);
    }
  }
  // The sky is above the horizon, with no depth and instance id -1.
  EXPECT_EQ(render.instance_ids.at<std::int32_t>(0, 320), kSkyInstance);
  EXPECT_EQ(render.depth_mm.at<std::uint16_t>(0, 320), 0);
}

TEST(RgbdCameraTest, DepthNoiseFollowsKhoshelhamElberink) {
  const World world = FlatWorld();
  RgbdCameraOptions options;
  options.depth.quantise = false;
  for (const double z : {1.0, 2.0, 3.5}) {
    // Straight down at flat ground: every pixel sees the same depth z.
    const Eigen::Isometry3d T = CameraPose({10, 10, z}, 0, 90 * kDeg);
    const RgbdRender render = RenderRgbd(world, T, options, 3);
    double sum = 0, sum2 = 0;
    int n = 0;
    for (int v = 100; v < 380; ++v) {
      for (int u = 100; u < 540; ++u) {
        const std::uint16_t mm = render.depth_mm.at<std::uint16_t>(v, u);
        ASSERT_GT(mm, 0) << "unexpected dropout at " << u << "," << v;
        const double e = mm / 1000.0 - z;
        sum += e;
        sum2 += e * e;
        ++n;
      }
    }
    const double mean = sum / n, std = std::sqrt(sum2 / n - mean * mean);
    const double expected = 1.425e-3 * z * z;
    EXPECT_NEAR(std, expected, 0.2 * expected) << "z = " << z;
    EXPECT_NEAR(mean, 0, 0.1 * expected + 0.0005) << "z = " << z;
  }
}

TEST(RgbdCameraTest, ObjectAppearsWhereItsCentreProjects) {
  World world = FlatWorld();
  // Pitched down 10°: a ball 1.5 m ahead on the optical axis floats 9 cm above the ground.
  const Eigen::Isometry3d T = CameraPose({5, 10, 0.5}, 0, 10 * kDeg);
  const Eigen::Vector3d forward = T.linear().col(2);
  const Eigen::Vector3d sphere_centre = T.translation() + 1.5 * forward;
  AddObject(world, Primitive(Shape::kEllipsoid, sphere_centre, {0.3, 0.3, 0.3}));
  // A can standing on the ground 1.5 m ahead and 0.3 m to the left.
  const Eigen::Vector3d can_centre(6.5, 10.3, 0.06);
  AddObject(world, Primitive(Shape::kCylinder, can_centre, {0.066, 0.066, 0.12}));
  const RgbdCameraOptions options = NoiselessCameraOptions();
  const RgbdRender render = RenderRgbd(world, T, options, 1);
  const PinholeCamera& k = options.intrinsics;
  for (int id = 0; id < 2; ++id) {
    const cv::Mat mask = render.instance_ids == InstanceIdOf(world.objects[std::size_t(id)]);
    const cv::Moments m = cv::moments(mask, true);
    ASSERT_GT(m.m00, 50) << "object " << id;
    const Eigen::Vector3d c = T.inverse() * world.objects[std::size_t(id)].center_m;
    const Eigen::Vector2d expected = k.Project(c);
    EXPECT_NEAR(m.m10 / m.m00, expected.x(), 2.0) << "object " << id;
    EXPECT_NEAR(m.m01 / m.m00, expected.y(), 2.0) << "object " << id;
  }
  // The sphere's nearest point is 1.5 m - 0.15 m away on the optical axis.
  EXPECT_NEAR(render.depth_mm.at<std::uint16_t>(240, 320) / 1000.0, 1.35, 0.005);
  const Eigen::Vector2d can_px = k.Project(T.inverse() * can_centre);
  const double can_depth = render.depth_mm.at<std::uint16_t>(int(std::lround(can_px.y())),
                                                             int(std::lround(can_px.x()))) /
                           1000.0;
  EXPECT_NEAR(can_depth, (T.inverse() * can_centre).z(), 0.04);
}

// The silhouette of a convex primitive computed independently of the rasteriser: the convex hull
// of many projected surface points.
cv::Mat ProjectedSilhouette(const WorldObject& o, const Eigen::Isometry3d& T,
                            const PinholeCamera& k) {
  std::vector<cv::Point> points;
  const Eigen::Matrix3d R = RotationFromRpy(o.orientation);
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j < 80; ++j) {
      const double polar = std::numbers::pi * i / 40, a = 2 * std::numbers::pi * j / 80;
      Eigen::Vector3d q(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a),
                        std::cos(polar));
      if (o.shape == Shape::kBox) q = q.cwiseSign();  // the eight corners, many times
      if (o.shape == Shape::kCylinder) q = {std::cos(a), std::sin(a), i < 20 ? -1.0 : 1.0};
      const Eigen::Vector2d uv =
          k.Project(T.inverse() * (o.center_m + R * (0.5 * o.size_m).cwiseProduct(q)));
      points.emplace_back(int(std::lround(uv.x())), int(std::lround(uv.y())));
    }
  }
  std::vector<cv::Point> hull;
  cv::convexHull(points, hull);
  cv::Mat mask(k.height, k.width, CV_8UC1, cv::Scalar(0));
  cv::fillConvexPoly(mask, hull, cv::Scalar(255));
  return mask;
}

TEST(RgbdCameraTest, InstanceMaskMatchesProjectedPrimitive) {
  const Eigen::Isometry3d T = CameraPose({5, 10, 0.5}, 0, 25 * kDeg);
  const RgbdCameraOptions options = NoiselessCameraOptions();
  const std::vector<WorldObject> objects = {
      Primitive(Shape::kBox, {6.2, 10.1, 0.2}, {0.3, 0.2, 0.15}, {0.3, 0.2, 0.7}),
      Primitive(Shape::kCylinder, {6.0, 9.8, 0.1}, {0.1, 0.1, 0.25}, {1.2, 0, 0.4}),
      Primitive(Shape::kEllipsoid, {7.0, 10.3, 0.15}, {0.4, 0.2, 0.25}, {0, 0.3, 1.0})};
  for (const WorldObject& object : objects) {
    World world = FlatWorld();
    AddObject(world, object);
    const RgbdRender render = RenderRgbd(world, T, options, 1);
    const cv::Mat rendered = render.instance_ids == InstanceIdOf(world.objects[0]);
    const cv::Mat expected = ProjectedSilhouette(world.objects[0], T, options.intrinsics);
    const double intersection = cv::countNonZero(rendered & expected);
    const double uni = cv::countNonZero(rendered | expected);
    ASSERT_GT(uni, 100) << ShapeName(object.shape);
    EXPECT_GE(intersection / uni, 0.8) << ShapeName(object.shape);
    RecordProperty(std::string("iou_") + ShapeName(object.shape),
                   std::to_string(intersection / uni));
  }
}

TEST(RgbdCameraTest, DropsAboutHalfTheDepthAtObjectEdges) {
  World world = FlatWorld();
  // A box floating 2 m ahead: all its outline is a depth discontinuity against the ground behind.
  AddObject(world, Primitive(Shape::kBox, {7.0, 10.0, 0.5}, {0.3, 0.5, 0.4}));
  RgbdCameraOptions options = NoiselessCameraOptions();
  options.depth.edge_dropout_probability = 0.5;
  const Eigen::Isometry3d T = CameraPose({5, 10, 0.5}, 0, 10 * kDeg);
  const RgbdRender render = RenderRgbd(world, T, options, 9);
  const cv::Mat box = render.instance_ids == InstanceIdOf(world.objects[0]);
  cv::Mat inner;
  cv::erode(box, inner, cv::Mat());
  const cv::Mat rim = box & ~inner;  // the box's outermost pixels
  const double rim_pixels = cv::countNonZero(rim);
  const double dropped = cv::countNonZero(rim & (render.depth_mm == 0));
  ASSERT_GT(rim_pixels, 100);
  EXPECT_NEAR(dropped / rim_pixels, 0.5, 0.15);
  EXPECT_GT(render.stats.depth.edge, 0);
  // Inside the silhouette every pixel has its reading.
  EXPECT_EQ(cv::countNonZero(inner & (render.depth_mm == 0)), 0);
}

TEST(RgbdCameraTest, DeterministicPerSeed) {
  World world = FlatWorld();
  AddObject(world, Primitive(Shape::kCylinder, {6.5, 10.0, 0.06}, {0.066, 0.066, 0.12}));
  const Eigen::Isometry3d T = CameraPose({5, 10, 0.5}, 0.1, 25 * kDeg);
  const RgbdCameraOptions options;
  RgbdCamera camera(world, options);
  const RgbdRender a = camera.Render(T, 5);
  const RgbdRender b = camera.Render(T, 5);
  const RgbdRender c = RenderRgbd(world, T, options, 6);
  EXPECT_EQ(cv::norm(a.colour_bgr, b.colour_bgr, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a.depth_mm, b.depth_mm, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(a.instance_ids, b.instance_ids, cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(a.colour_bgr, c.colour_bgr, cv::NORM_L1), 0);
  EXPECT_GT(cv::norm(a.depth_mm, c.depth_mm, cv::NORM_L1), 0);
  // Ground truth does not depend on the noise.
  EXPECT_EQ(cv::norm(a.instance_ids, c.instance_ids, cv::NORM_INF), 0);
}

TEST(RgbdCameraTest, InstanceMaskSubset) {
  RgbdCameraOptions options;
  options.instance_mask_every_n_frames = 5;
  EXPECT_TRUE(WantsInstanceMask(0, options));
  EXPECT_FALSE(WantsInstanceMask(3, options));
  EXPECT_TRUE(WantsInstanceMask(10, options));
  options.output_instance_ids = false;
  const RgbdRender render = RenderRgbd(FlatWorld(), CameraPose({5, 10, 0.5}, 0, 0.4), options, 1);
  EXPECT_TRUE(render.instance_ids.empty());
  EXPECT_EQ(render.colour_bgr.type(), CV_8UC3);
  EXPECT_EQ(render.depth_mm.type(), CV_16UC1);
}

TEST(RgbdCameraTest, RejectsInvalidOptions) {
  RgbdCameraOptions options;
  options.depth.max_depth_m = 0.1;
  EXPECT_THROW(RgbdCamera(FlatWorld(), options), std::invalid_argument);
}

}  // namespace
}  // namespace littermap::sim
