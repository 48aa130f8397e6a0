// World files: the samples load; unknown keys and bad values name the file and the key.

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "sim/world_spec.hpp"
#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

using test::SampleWorld;

constexpr const char* kRoute = "route: {waypoints_m: [[0, 0], [5, 0]]}\n";

std::string ErrorOf(const std::string& yaml) {
  try {
    ParseWorldSpec(yaml, "w.yaml");
  } catch (const BadInputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WorldSpec, SamplesLoad) {
  const WorldSpec small = LoadWorldSpec(SampleWorld("park_small.yaml"));
  EXPECT_EQ(small.name, "park_small");
  EXPECT_EQ(small.litter.count, 60);
  EXPECT_EQ(small.bumps.size(), 2u);
  EXPECT_EQ(small.robot.laser.preset, "urg-04lx");
  const WorldSpec large = LoadWorldSpec(SampleWorld("park_large.yaml"));
  EXPECT_EQ(large.route.type, "lawnmower");
  ASSERT_EQ(large.routes.size(), 2u);
  EXPECT_EQ(large.routes[0].first, "perimeter");
  EXPECT_EQ(large.robot.laser.preset, "utm-30lx");
  EXPECT_DOUBLE_EQ(large.size_x_m, 150);
  // The Kinect mount: about 0.5 m up, pitched about 25° down, 10 Hz.
  EXPECT_DOUBLE_EQ(small.robot.camera.mount.z_m, 0.5);
  EXPECT_DOUBLE_EQ(small.robot.camera.mount.pitch_deg, 25);
  EXPECT_DOUBLE_EQ(small.robot.camera.rate_hz, 10);
  EXPECT_EQ(small.truth.mask_every_n_frames, 10);
  // Every shipped survey ends at the dock.
  EXPECT_TRUE(small.route.come_home);
  EXPECT_TRUE(large.route.come_home);
  for (const auto& [name, route] : large.routes) EXPECT_TRUE(route.come_home) << name;
  EXPECT_TRUE(LoadWorldSpec(SampleWorld("park_tilts.yaml")).route.come_home);
  const WorldSpec hard = LoadWorldSpec(SampleWorld("park_hard.yaml"));
  EXPECT_EQ(hard.name, "park_hard");
  EXPECT_TRUE(hard.route.come_home);
  EXPECT_DOUBLE_EQ(hard.litter.dirty_fraction, 0.4);
  EXPECT_DOUBLE_EQ(hard.litter.crushed_fraction, 0.5);
  EXPECT_DOUBLE_EQ(hard.litter.clear_bottle_fraction, 0.6);
}

TEST(WorldSpec, HardLitterKeys) {
  // Absent, they keep every world as it was: no wear, sunk by 30-60 % as before the keys.
  const LitterSpec defaults = ParseWorldSpec(kRoute).litter;
  EXPECT_EQ(defaults.dirty_fraction, 0);
  EXPECT_EQ(defaults.crushed_fraction, 0);
  EXPECT_EQ(defaults.clear_bottle_fraction, 0);
  EXPECT_EQ(defaults.on_gravel_fraction, 0);
  EXPECT_EQ(defaults.half_hidden_depth_min, 0.3);
  EXPECT_EQ(defaults.half_hidden_depth_max, 0.6);
  const LitterSpec litter =
      ParseWorldSpec(std::string(kRoute) +
                     "litter: {dirty_fraction: 0.4, crushed_fraction: 0.5, clear_bottle_fraction: "
                     "0.6, on_gravel_fraction: 0.25, half_hidden_depth_min: 0.4, "
                     "half_hidden_depth_max: 0.7}\n")
          .litter;
  EXPECT_DOUBLE_EQ(litter.dirty_fraction, 0.4);
  EXPECT_DOUBLE_EQ(litter.crushed_fraction, 0.5);
  EXPECT_DOUBLE_EQ(litter.clear_bottle_fraction, 0.6);
  EXPECT_DOUBLE_EQ(litter.on_gravel_fraction, 0.25);
  EXPECT_DOUBLE_EQ(litter.half_hidden_depth_min, 0.4);
  EXPECT_DOUBLE_EQ(litter.half_hidden_depth_max, 0.7);
  const auto litter_error = [](const std::string& keys) {
    return ErrorOf(std::string(kRoute) + "litter: {" + keys + "}\n");
  };
  EXPECT_EQ(litter_error("dirty_fraction: 1.5"),
            "w.yaml: litter.dirty_fraction: must be in [0, 1]");
  EXPECT_EQ(litter_error("crushed_fraction: -0.1"),
            "w.yaml: litter.crushed_fraction: must be in [0, 1]");
  EXPECT_EQ(litter_error("clear_bottle_fraction: .nan"),
            "w.yaml: litter.clear_bottle_fraction: must be finite");
  EXPECT_EQ(litter_error("on_gravel_fraction: many"),
            "w.yaml: litter.on_gravel_fraction: expected a number");
  EXPECT_EQ(litter_error("on_gravel_fraction: 2"),
            "w.yaml: litter.on_gravel_fraction: must be in [0, 1]");
  EXPECT_EQ(litter_error("half_hidden_fraction: 1.2"),
            "w.yaml: litter.half_hidden_fraction: must be in [0, 1]");
  EXPECT_EQ(litter_error("half_hidden_depth_min: 0.95"),
            "w.yaml: litter.half_hidden_depth_min: must be in [0, 0.9]");
  EXPECT_EQ(litter_error("half_hidden_depth_max: 0.2"),  // below the default min 0.3
            "w.yaml: litter.half_hidden_depth_max: must be in [half_hidden_depth_min, 0.9]");
  EXPECT_EQ(litter_error("half_hidden_depth_max: .inf"),
            "w.yaml: litter.half_hidden_depth_max: must be finite");
  EXPECT_EQ(litter_error("dirt_fraction: 0.4"), "w.yaml: litter.dirt_fraction: unknown key");
  EXPECT_EQ(litter_error("half_hidden_depth_min: 0, half_hidden_depth_max: 0.9"), "no error");
}

TEST(WorldSpec, CameraAndTruthSections) {
  const WorldSpec spec = ParseWorldSpec(
      std::string(kRoute) +
      "robot: {camera: {rate_hz: 30, clock_offset_ms: 5, jitter_sigma_ms: 1, jpeg_quality: 80,"
      " mount: {z_m: 0.6, pitch_deg: 30}}}\ntruth: {mask_every_n_frames: 0}\n");
  EXPECT_DOUBLE_EQ(spec.robot.camera.rate_hz, 30);
  EXPECT_DOUBLE_EQ(spec.robot.camera.clock_offset_ms, 5);
  EXPECT_DOUBLE_EQ(spec.robot.camera.jitter_sigma_ms, 1);
  EXPECT_EQ(spec.robot.camera.jpeg_quality, 80);
  EXPECT_DOUBLE_EQ(spec.robot.camera.mount.z_m, 0.6);
  EXPECT_EQ(spec.truth.mask_every_n_frames, 0);
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "robot: {camera: {rate_hz: 30, jitter_sigma_ms: 2}}\n"),
            "w.yaml: robot.camera.jitter_sigma_ms: must be in [0, 1000 / rate_hz / 18]");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "robot: {camera_mount: {z_m: 1}}\n"),
            "w.yaml: robot.camera_mount: unknown key");
  // A map as a key (YAML's "? key"), found by the fuzzer: named, not a yaml-cpp exception.
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "robot:\n  ? {camera: 1}\n  : 2\n"),
            "w.yaml: robot: a key at line 3 is not a plain name (a list or a map used as a key)");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "truth: {mask_every_n_frames: -1}\n"),
            "w.yaml: truth.mask_every_n_frames: must not be negative");
}

TEST(WorldSpec, CountsAreBoundedWhenTheFileIsRead) {
  // 1e9 trees or items ran until the memory was gone; they are refused with the bound.
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "structure: {trees: 1000000000}\n"),
            "w.yaml: structure.trees: must be at most 20000");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "litter: {count: 20001}\n"),
            "w.yaml: litter.count: must be at most 20000");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "natural: {count: 1000000000}\n"),
            "w.yaml: natural.count: must be at most 20000");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "terrain: {roots: 1000000000}\n"),
            "w.yaml: terrain.roots: must be at most 100000");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "litter: {daily_new: -1}\n"),
            "w.yaml: litter.daily_new: must not be negative");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "structure: {trees: 20000}\n"), "no error");
}

TEST(WorldSpec, UnknownKeysNameFileAndKey) {
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "sise_x_m: 3\n"), "w.yaml: sise_x_m: unknown key");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "robot: {laser: {rate: 10}}\n"),
            "w.yaml: robot.laser.rate: unknown key");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "litter: {class_weights: {tyre: 1}}\n"),
            "w.yaml: litter.class_weights.tyre: unknown class");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "bumps: [{x_m: 1, height_m: 2}]\n"),
            "w.yaml: bumps[0].height_m: unknown key");
}

TEST(WorldSpec, BadValuesNameTheKey) {
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "size_x_m: wide\n"),
            "w.yaml: size_x_m: expected a number");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "robot: {laser: {preset: lms100}}\n"),
            "w.yaml: robot.laser.preset: must be urg-04lx or utm-30lx");
  EXPECT_EQ(ErrorOf("route: {waypoints_m: [[0, 0]]}\n"),
            "w.yaml: route.waypoints_m: needs at least two points");
  EXPECT_EQ(ErrorOf("route: {waypoints_m: [[0, 0], [.nan, 5]]}\n"),
            "w.yaml: route.waypoints_m[1]: must be finite");
  EXPECT_EQ(ErrorOf("route: {waypoints_m: [[0, 0], [5, .inf]]}\n"),
            "w.yaml: route.waypoints_m[1]: must be finite");
  EXPECT_EQ(ErrorOf(std::string(kRoute) + "litter: {class_weights: {can: .inf}}\n"),
            "w.yaml: litter.class_weights.can: must be finite and not negative");
  EXPECT_EQ(ErrorOf("route: {waypoints_m: [[0, 0], [5, 0]], come_home: maybe}\n"),
            "w.yaml: route.come_home: expected true or false");
  EXPECT_NE(ErrorOf("[1, 2"), "no error");
  EXPECT_EQ(ErrorOf(kRoute), "no error");
}

}  // namespace
}  // namespace littermap::sim
