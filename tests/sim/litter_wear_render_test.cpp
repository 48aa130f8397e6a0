// How worn litter looks to the simulated camera: a dirty item is darker, greyer and browner than
// the same item clean, a clear bottle takes the colour of the ground behind it, a crushed can is
// low in the depth image. Noise-free renders of single items, compared pixel by pixel.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/litter_wear.hpp"
#include "sim/noiseless_camera.hpp"
#include "sim/rgbd_camera.hpp"
#include "support/angles.hpp"

namespace littermap::sim {
namespace {

using test::kDeg;

// The robot's camera, 0.5 m up looking along +x and pitched 25° down, at (5, 10).
Eigen::Isometry3d RobotCamera() {
  Eigen::Matrix3d R_body_optical;  // optical z = body x, optical x = -body y, optical y = -body z
  R_body_optical << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = RotationFromRpy({0, 25 * kDeg, 0}) * R_body_optical;
  T.translation() = Eigen::Vector3d(5, 10, 0.5);
  return T;
}

// A flat 20 m x 20 m park of grass, or of gravel (hundreds of overlapping 3 m gravel patches).
World FlatPark(bool gravel) {
  World world;
  world.spec.size_x_m = world.spec.size_y_m = 20;
  world.spec.terrain.hill_amplitude_m = 0;
  world.spec.terrain.roots = 0;
  world.spec.terrain.leaf_patches = 0;
  world.spec.terrain.gravel_patches = gravel ? 400 : 0;
  world.terrain = Terrain(world.spec, 1);
  return world;
}

// A litter item made as the generator makes it, lying or standing 1.2 m ahead of the camera.
WorldObject Item(const char* label, const Eigen::Vector3d& size_m, const Eigen::Vector3d& colour,
                 const char* texture, bool lying) {
  WorldObject o;
  o.kind = ObjectKind::kLitter;
  o.label = label;
  o.shape = Shape::kCylinder;
  o.size_m = size_m;
  o.colour_rgb = colour;
  o.texture = texture;
  o.orientation.yaw_rad = 1.2;
  if (lying) o.orientation.pitch_rad = std::numbers::pi / 2;
  return o;
}

RgbdRender RenderWith(World world, WorldObject item) {
  const double height =
      std::abs(item.orientation.pitch_rad) > 1 ? item.size_m.x() : item.size_m.z();
  item.center_m = {6.2, 10, 0.5 * height};
  AddObject(world, item);
  return RenderRgbd(world, RobotCamera(), NoiselessCameraOptions(), 1);
}

struct PixelStats {  // means over a mask, 8-bit sRGB
  int pixels = 0;
  double luma = 0;        // Rec. 709 weights
  double saturation = 0;  // (max - min) / max, HSV
  double red_minus_blue = 0;
  Eigen::Vector3d rgb = Eigen::Vector3d::Zero();
};

PixelStats Stats(const cv::Mat& bgr, const cv::Mat& mask) {
  PixelStats s;
  for (int v = 0; v < bgr.rows; ++v) {
    for (int u = 0; u < bgr.cols; ++u) {
      if (mask.at<std::uint8_t>(v, u) == 0) continue;
      const cv::Vec3b p = bgr.at<cv::Vec3b>(v, u);
      const Eigen::Vector3d rgb(p[2], p[1], p[0]);
      s.rgb += rgb;
      s.luma += rgb.dot(Eigen::Vector3d(0.2126, 0.7152, 0.0722));
      s.saturation += rgb.maxCoeff() > 0 ? (rgb.maxCoeff() - rgb.minCoeff()) / rgb.maxCoeff() : 0;
      s.red_minus_blue += rgb.x() - rgb.z();
      ++s.pixels;
    }
  }
  const double n = std::max(s.pixels, 1);
  s.rgb /= n;
  s.luma /= n;
  s.saturation /= n;
  s.red_minus_blue /= n;
  return s;
}

// Mean over the mask of the largest per-channel difference of two images, in 8-bit levels.
double MeanDifference(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  double sum = 0;
  int n = 0;
  for (int v = 0; v < a.rows; ++v) {
    for (int u = 0; u < a.cols; ++u) {
      if (mask.at<std::uint8_t>(v, u) == 0) continue;
      const cv::Vec3b d = difference.at<cv::Vec3b>(v, u);
      sum += std::max({d[0], d[1], d[2]});
      ++n;
    }
  }
  return sum / std::max(n, 1);
}

cv::Mat MaskOf(const RgbdRender& render) { return render.instance_ids == 1; }  // object id 0

TEST(LitterWearRender, DirtyItemIsDarkerGreyerAndBrowner) {
  for (const bool gravel : {false, true}) {
    // A blue can standing, whose clean colour is far from mud's brown.
    const WorldObject clean =
        Item("can", {0.066, 0.066, 0.12}, {0.1, 0.2, 0.7}, "aluminium", false);
    WorldObject dirty = clean;
    LitterWear wear;
    wear.dirt = 0.8;
    ApplyLitterWear(wear, dirty);
    const RgbdRender a = RenderWith(FlatPark(gravel), clean);
    const RgbdRender b = RenderWith(FlatPark(gravel), dirty);
    const cv::Mat mask = MaskOf(a);
    ASSERT_GT(cv::countNonZero(mask), 1000);
    EXPECT_EQ(cv::countNonZero(mask != MaskOf(b)), 0);  // dirt changes colours, not the shape
    const PixelStats s_clean = Stats(a.colour_bgr, mask), s_dirty = Stats(b.colour_bgr, mask);
    // The ground does not change the item's own pixels: the same numbers on grass and gravel.
    // Wet soil darkens by 0.5 x dirt in linear light and dark mud covers about half of the
    // surface, but the sRGB curve compresses it: measured 0.76 of the clean luma.
    EXPECT_LT(s_dirty.luma, 0.85 * s_clean.luma) << "gravel " << gravel;
    // Greyed by half of dirt and partly covered in brown mud: measured 0.60 of the saturation.
    EXPECT_LT(s_dirty.saturation, 0.75 * s_clean.saturation) << "gravel " << gravel;
    // Browner: red gains on blue (mud is red-brown), measured -51 → -19 levels.
    EXPECT_GT(s_dirty.red_minus_blue, s_clean.red_minus_blue + 20) << "gravel " << gravel;
  }
}

TEST(LitterWearRender, ClearBottleTakesTheColourOfTheGroundBehind) {
  for (const bool gravel : {true, false}) {
    const World world = FlatPark(gravel);
    ASSERT_EQ(world.terrain.GroundAt({6.2, 10}), gravel ? GroundType::kGravel : GroundType::kGrass);
    // The catalog's pale bottle, lying: opaque as made, then clear.
    const WorldObject opaque =
        Item("bottle", {0.07, 0.07, 0.25}, {0.8, 0.85, 0.9}, "plastic", true);
    WorldObject clear = opaque;
    LitterWear wear;
    wear.transmission = 0.85;
    ApplyLitterWear(wear, clear);
    const RgbdRender empty = RenderRgbd(world, RobotCamera(), NoiselessCameraOptions(), 1);
    const RgbdRender a = RenderWith(world, opaque), b = RenderWith(world, clear);
    // The ground behind each of the bottle's pixels is that pixel of the render without it.
    const cv::Mat mask = MaskOf(b);
    ASSERT_GT(cv::countNonZero(mask), 1000);
    const double opaque_difference = MeanDifference(a.colour_bgr, empty.colour_bgr, mask);
    const double clear_difference = MeanDifference(b.colour_bgr, empty.colour_bgr, mask);
    // What remains is the plastic's own pale 15 %, the sky it mirrors at the rims (Fresnel),
    // the cap and the highlights. Measured per pixel: clear 17 / 39 levels, opaque 55 / 105 on
    // gravel / grass (0.31 / 0.37 of it).
    EXPECT_LT(clear_difference, 0.5 * opaque_difference) << "gravel " << gravel;
    // Its mean colour is the ground's, paler: within 20 levels per channel on mid-grey gravel
    // (measured 14), within 50 on dark grass, where the pale share shows most (measured 39).
    const PixelStats ground = Stats(empty.colour_bgr, mask), bottle = Stats(b.colour_bgr, mask);
    EXPECT_LT((bottle.rgb - ground.rgb).cwiseAbs().maxCoeff(), gravel ? 20 : 50)
        << "gravel " << gravel;
    // And no more saturated than what lies behind (measured 0.05 against 0.07 on gravel, 0.29
    // against 0.51 on grass).
    EXPECT_LT(bottle.saturation, ground.saturation + 0.02) << "gravel " << gravel;
  }
}

TEST(LitterWearRender, CrushedCanIsLowInTheDepthImage) {
  for (const bool lying : {false, true}) {
    WorldObject can = Item("can", {0.066, 0.066, 0.12}, {0.8, 0.1, 0.1}, "aluminium", lying);
    LitterWear wear;
    wear.crushed_to = 0.3;
    ApplyLitterWear(wear, can);
    const RgbdRender render = RenderWith(FlatPark(false), can);
    const cv::Mat mask = MaskOf(render);
    ASSERT_GT(cv::countNonZero(mask), 200) << "lying " << lying;
    // Highest point of the can seen in the (noise-free) depth image, above the flat ground.
    const Eigen::Isometry3d T = RobotCamera();
    const PinholeCamera k;
    double top = 0;
    for (int v = 0; v < mask.rows; ++v) {
      for (int u = 0; u < mask.cols; ++u) {
        const std::uint16_t mm = render.depth_mm.at<std::uint16_t>(v, u);
        if (mask.at<std::uint8_t>(v, u) == 0 || mm == 0) continue;
        top = std::max(top, (T * k.BackProject(u, v, mm / 1000.0)).z());
      }
    }
    // 30 % of 12 cm standing or of 6.6 cm lying, plus 2 mm of millimetre depth steps.
    const double crushed_height = 0.3 * (lying ? 0.066 : 0.12);
    EXPECT_LT(top, crushed_height + 0.002) << "lying " << lying;
    EXPECT_GT(top, crushed_height - 0.005) << "lying " << lying;
  }
}

}  // namespace
}  // namespace littermap::sim
