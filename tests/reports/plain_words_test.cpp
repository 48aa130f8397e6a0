// Figures in words: the noun's number follows the count, directions say east/west and
// north/south instead of negative metres, kinds are lower case mid-sentence.

#include "reports/plain_words.hpp"

#include <gtest/gtest.h>

namespace littermap::reports {
namespace {

TEST(PlainWords, CountsTakeTheRightNoun) {
  EXPECT_EQ(CountOf(1, "item", "items"), "1 item");
  EXPECT_EQ(CountOf(0, "item", "items"), "0 items");
  EXPECT_EQ(CountOf(1204, "item", "items"), "1\u2009204 items");  // a thin space
  EXPECT_EQ(ClassCount("bottle", 1), "1 bottle");
  EXPECT_EQ(ClassCount("food_container", 2), "2 food containers");
  EXPECT_EQ(ClassCount("other", 1), "1 other item");
  EXPECT_EQ(ClassCount("traffic_cone", 3), "3 traffic cone") << "an unknown class: its name";
}

TEST(PlainWords, PositionsAreDirectionsFromTheDock) {
  EXPECT_EQ(FromTheDock(12.04, -1.8, 1), "12.0 m east and 1.8 m south of the dock");
  EXPECT_EQ(FromTheDock(-3.0, 7.25, 0), "3 m west and 7 m north of the dock");
  EXPECT_EQ(FromTheDock(0.04, -2.0, 1), "2.0 m south of the dock");
  EXPECT_EQ(FromTheDock(-5.0, 0.2, 0), "5 m west of the dock");
  EXPECT_EQ(FromTheDock(0.3, -0.4, 0), "at the dock");
}

}  // namespace
}  // namespace littermap::reports
