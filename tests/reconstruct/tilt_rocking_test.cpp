// Landmark sightings are skipped while the base rocks off the ground's slope, not on a hillside.

#include "reconstruct/tilt_rocking.hpp"

#include <gtest/gtest.h>

namespace littermap::reconstruct {
namespace {

constexpr TimestampNs kScanPeriodNs = 25'000'000;  // 40 Hz

// Adds scan i's tilt and returns the rocking at it.
double AddScan(TiltRocking* rocking, int i, const Tilt& tilt) {
  rocking->Add(i * kScanPeriodNs, tilt);
  return rocking->LatestRockingRad();
}

TEST(TiltRocking, NothingSeenIsNoRocking) { EXPECT_EQ(TiltRocking(2).LatestRockingRad(), 0); }

TEST(TiltRocking, ASteadySlopeIsNoRocking) {
  TiltRocking rocking(2);
  double last = 1;
  // Pitching up a hill at 0.01 rad/s for 20 s, rolling 0.12 rad to the side.
  for (int i = 0; i < 800; ++i) last = AddScan(&rocking, i, {0.12, 0.00025 * i});
  // The median lags the steady climb by half the window: 1 s x 0.01 rad/s.
  EXPECT_NEAR(last, 0.01, 1e-4);
}

TEST(TiltRocking, ARootRocksTheBaseForAFractionOfASecond) {
  TiltRocking rocking(2);
  for (int i = 0; i < 200; ++i) EXPECT_NEAR(AddScan(&rocking, i, {0.05, -0.03}), 0, 1e-12);
  // 0.25 s over a root: rolled 0.2 rad further.
  for (int i = 200; i < 210; ++i) EXPECT_NEAR(AddScan(&rocking, i, {0.25, -0.03}), 0.2, 1e-9);
  // Back on the ground, and 2 s later the root has left the window.
  EXPECT_NEAR(AddScan(&rocking, 210, {0.05, -0.03}), 0, 1e-12);
  for (int i = 211; i < 300; ++i) rocking.Add(i * kScanPeriodNs, {0.05, -0.03});
  EXPECT_NEAR(AddScan(&rocking, 300, {0.05, 0.02}), 0.05, 1e-9);
}

}  // namespace
}  // namespace littermap::reconstruct
