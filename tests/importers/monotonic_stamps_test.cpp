// Time stamp repair of logs: missing, repeated and out-of-range stamps.

#include "importers/monotonic_stamps.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace littermap::importers {
namespace {

void ExpectIncreasing(const std::vector<TimestampNs>& stamps) {
  for (std::size_t i = 1; i < stamps.size(); ++i) ASSERT_GT(stamps[i], stamps[i - 1]) << i;
}

TEST(MonotonicStamps, GoodStampsPassUnchanged) {
  const std::vector<double> raw = {10.0, 10.1, 10.25, 10.3};
  const MonotonicStampResult result = MakeMonotonicStamps(raw);
  EXPECT_EQ(result.changed, 0u);
  EXPECT_FALSE(result.synthesised);
  EXPECT_EQ(result.out_of_range, 0u);
  EXPECT_EQ(result.stamps_ns[2], FromSeconds(10.25));
}

TEST(MonotonicStamps, ARepeatedStampMovesAfterItsPredecessor) {
  const MonotonicStampResult result = MakeMonotonicStamps(std::vector<double>{5, 6, 6, 7});
  EXPECT_EQ(result.changed, 1u);
  EXPECT_EQ(result.stamps_ns[2], FromSeconds(6.001));
  EXPECT_FALSE(result.synthesised);
}

TEST(MonotonicStamps, AllZeroStampsAreSynthesised) {
  const MonotonicStampResult result = MakeMonotonicStamps(std::vector<double>(5, 0.0));
  EXPECT_TRUE(result.synthesised);
  EXPECT_EQ(result.stamps_ns.front(), FromSeconds(1.0));
  EXPECT_EQ(result.stamps_ns.back(), FromSeconds(5.0));
}

// A clock that wrapped (4.29e9 s), ran backwards past zero or printed nan: such stamps carry no
// time, like missing ones, and are never a reason to refuse a log.
TEST(MonotonicStamps, AFewOutOfRangeStampsAreRepairedInPlace) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> raw = {100, 101, 4.29e9, 103, -5, 105, nan, 107, 108, 109, 110, 111};
  const MonotonicStampResult result = MakeMonotonicStamps(raw);
  EXPECT_FALSE(result.synthesised);
  EXPECT_EQ(result.out_of_range, 3u);
  EXPECT_EQ(result.changed, 3u);
  ExpectIncreasing(result.stamps_ns);
  EXPECT_EQ(result.stamps_ns[2], FromSeconds(101.001));
  EXPECT_EQ(result.stamps_ns[3], FromSeconds(103));
  EXPECT_EQ(result.stamps_ns[6], FromSeconds(105.001));
}

TEST(MonotonicStamps, OutOfRangeStampsEverywhereAreSynthesised) {
  const std::vector<double> raw = {4.29e9, 4.29e9 + 0.1, 4.29e9 + 0.2, 4.29e9 + 0.3};
  const MonotonicStampResult result = MakeMonotonicStamps(raw);
  EXPECT_TRUE(result.synthesised);
  EXPECT_EQ(result.out_of_range, 4u);
  EXPECT_EQ(result.changed, 4u);
  EXPECT_EQ(result.stamps_ns.front(), FromSeconds(1.0));  // not the wrapped clock's start
  ExpectIncreasing(result.stamps_ns);
}

TEST(MonotonicStamps, LeadingOutOfRangeStampsGoJustBeforeTheFirstGoodOne) {
  const MonotonicStampResult result =
      MakeMonotonicStamps(std::vector<double>{-1, 4.29e9, 3, 4, 5, 6, 7});
  EXPECT_FALSE(result.synthesised);
  EXPECT_EQ(result.out_of_range, 2u);
  EXPECT_EQ(result.stamps_ns[0], FromSeconds(2.998));
  EXPECT_EQ(result.stamps_ns[1], FromSeconds(2.999));
  ExpectIncreasing(result.stamps_ns);
}

TEST(MonotonicStamps, NoRoomBeforeTheFirstGoodStampMeansSynthesised) {
  const MonotonicStampResult result =
      MakeMonotonicStamps(std::vector<double>{-1, 0.0005, 3, 4, 5, 6, 7});
  EXPECT_TRUE(result.synthesised);
  ExpectIncreasing(result.stamps_ns);
  EXPECT_GT(result.stamps_ns.front(), 0);
}

}  // namespace
}  // namespace littermap::importers
