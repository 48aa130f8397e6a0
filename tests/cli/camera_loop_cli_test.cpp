// A survey that drives its first leg again, in the same direction, at the end: the camera sees the
// ground it saw at the start, and its frames close RGB-D loops to the key frames taken there
// (beside the loops that scan matching closes on the trees).

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "support/survey_runs.hpp"
#include "support/temp_dir.hpp"
#include "support/trajectory_ate.hpp"

namespace littermap {
namespace {

using test::Ate;

constexpr const char* kLawnWorldYaml = R"(name: lawn
seed: 7
size_x_m: 24
size_y_m: 16
start_time_s: 1700000000
terrain: {hill_amplitude_m: 0.1, hill_wavelength_m: 25, roots: 0}
structure: {trees: 30, rocks: 0, benches: 0, bins: 0, fence_segments: 0, bushes: 0,
            open_areas: 0, route_clearance_m: 1.5}
litter: {count: 20}
natural: {count: 0}
robot:
  laser: {preset: urg-04lx}
  camera: {rate_hz: 5}
  odometry: {rate_hz: 50, scale_error: 0.02, yaw_drift_deg_per_m: 0.3}
  imu: {rate_hz: 50}
route:
  waypoints_m: [[3, 3], [21, 3], [21, 13], [3, 13], [3, 3], [12, 3]]
  speed_mps: 0.8
truth: {mask_every_n_frames: 0}
)";

TEST(CameraLoopCli, FramesThatSeeTheStartAgainCloseLoops) {
  test::TempDir d;
  ASSERT_NO_FATAL_FAILURE(
      test::SimulateAndReconstructTwice(d.path(), kLawnWorldYaml, "rgbd_loops: false\n"));

  std::ifstream in(d / "run" / "quality.json");
  const auto rgbd = nlohmann::json::parse(in).at("rgbd");
  // Measured: 17 frames aligned to old key frames, 2 loops found, both accepted.
  EXPECT_GE(rgbd.at("loop_alignments").get<int>(), 5);
  EXPECT_GE(rgbd.at("loops_accepted").get<int>(), 1);
  EXPECT_EQ(rgbd.at("loops_found").get<int>(),
            rgbd.at("loops_accepted").get<int>() + rgbd.at("loops_rejected").get<int>());
  std::ifstream plain_in(d / "plain" / "quality.json");
  EXPECT_EQ(nlohmann::json::parse(plain_in).at("rgbd").at("loops_found").get<int>(), 0);

  // The scan-matched loops already hold this run (measured 0.007 m either way): the camera's
  // loops must agree with them, not pull the graph away.
  const auto truth = d / "truth" / "trajectory.tum";
  const double ate = Ate(d / "run" / "trajectory.tum", truth);
  EXPECT_LT(ate, 0.03);
  EXPECT_LT(ate, Ate(d / "plain" / "trajectory.tum", truth) + 0.005);
  EXPECT_LT(ate, Ate(d / "run" / "odometry.tum", truth));
}

}  // namespace
}  // namespace littermap
