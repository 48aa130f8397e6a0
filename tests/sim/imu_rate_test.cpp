// The simulated IMU's yaw rate is the rate the robot turned at: sample k reports the turn rate of
// the drive step that ends at its time, plus the gyro's noise (N(0, 0.01 rad/s)). A sample that
// reported the step before's rate at a turn's start or end put a whole step of turning (1.1
// degrees at 1 rad/s) into the gyro that the robot never turned.

#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

TEST(ImuRate, EverySampleReportsTheTurnRateOfItsStep) {
  WorldSpec spec = LoadWorldSpec(test::SampleWorld());
  // A zigzag of 40 turns on the spot, each starting at 1 rad/s from standstill.
  spec.route.waypoints_m.clear();
  for (int i = 0; i < 41; ++i) {
    spec.route.waypoints_m.push_back({4.0 + 0.75 * i, i % 2 == 0 ? 4.0 : 6.0});
  }
  spec.route.come_home = false;
  const Simulation simulation(spec);
  ASSERT_EQ(spec.robot.imu.rate_hz, spec.robot.odometry.rate_hz);  // sample k is step k
  const auto& states = simulation.states();
  std::size_t turn_starts = 0;
  for (std::size_t k = 1; k < std::min(simulation.imu_count(), states.size()); ++k) {
    const double rate = simulation.Imu(k).angular_velocity_radps.z();
    // 6 sigma of the gyro noise: no sample of the run's should come near it by chance.
    ASSERT_NEAR(rate, states[k].angular_radps, 0.06) << "sample " << k;
    if (std::abs(states[k].angular_radps - states[k - 1].angular_radps) > 0.5) ++turn_starts;
  }
  EXPECT_GE(turn_starts, 30u);  // the route did turn (39 rate jumps over 0.5 rad/s)
}

}  // namespace
}  // namespace littermap::sim
