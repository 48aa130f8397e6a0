// The RGB-D camera's clock in a simulated run (CameraSpec): frame k is exposed at
// clock_offset_ms + k / rate_hz plus per-frame jitter N(0, jitter_sigma_ms) clipped to ±3σ, so
// the camera is neither synchronised with the laser nor perfectly periodic.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

TEST(CameraTiming, OffsetAndClippedGaussianJitter) {
  WorldSpec spec = LoadWorldSpec(test::SampleWorld());
  spec.robot.camera.rate_hz = 20;
  spec.robot.camera.clock_offset_ms = 13;
  spec.robot.camera.jitter_sigma_ms = 2;
  const Simulation simulation(spec, {60});
  // 20 Hz from 13 ms over 0..60 s: 0.013 + k / 20 <= 60 for k = 0..1199.
  ASSERT_EQ(simulation.camera_frame_count(), 1200u);
  double sum = 0, sum2 = 0;
  for (std::size_t k = 0; k < simulation.camera_frame_count(); ++k) {
    const double jitter_ms =
        (simulation.CameraFrameTime(k) - 0.013 - static_cast<double>(k) / 20) * 1000;
    ASSERT_LE(std::abs(jitter_ms), 6.0 + 1e-9) << "frame " << k;  // clipped at 3σ
    if (k > 0) {
      ASSERT_GT(simulation.CameraFrameTime(k), simulation.CameraFrameTime(k - 1));
    }
    sum += jitter_ms;
    sum2 += jitter_ms * jitter_ms;
  }
  // 1200 samples: the standard error of the mean is 0.06 ms and the sample σ of N(0, 2 ms) is
  // within ±5 % at 2.5 standard errors; clipping at 3σ lowers σ by 1.3 %.
  const double n = static_cast<double>(simulation.camera_frame_count());
  const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0, 0.2);
  EXPECT_NEAR(sigma, 2.0 * 0.987, 0.1);
}

TEST(CameraTiming, NoJitterIsPeriodicAndSeedsDiffer) {
  WorldSpec spec = LoadWorldSpec(test::SampleWorld());
  spec.robot.camera.jitter_sigma_ms = 0;
  const Simulation periodic(spec, {2});
  for (std::size_t k = 0; k < periodic.camera_frame_count(); ++k) {
    EXPECT_NEAR(periodic.CameraFrameTime(k), 0.013 + 0.1 * static_cast<double>(k), 1e-12);
  }
  spec = LoadWorldSpec(test::SampleWorld());
  const Simulation a(spec, {2});
  spec.seed += 1;
  const Simulation b(spec, {2});
  EXPECT_NE(a.CameraFrameTime(1), b.CameraFrameTime(1));
}

}  // namespace
}  // namespace littermap::sim
