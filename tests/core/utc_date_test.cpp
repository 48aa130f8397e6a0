// Dates as users type them: a day the month does not have is refused, not carried over.

#include "core/utc_date.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap {
namespace {

TEST(UtcDate, ReadsDatesAndTimesAsUtc) {
  EXPECT_EQ(ParseUtcDate("", "--from"), std::nullopt);
  EXPECT_EQ(ParseUtcDate("1970-01-02", "--from"), 86400.0);
  EXPECT_EQ(ParseUtcDate("2026-11-22T14:30", "--from"), 1795357800.0);
  EXPECT_EQ(ParseUtcDate("2026-11-22 14:30:05", "--from"), 1795357805.0);
  EXPECT_EQ(ParseUtcDate("2024-02-29", "--from"), 1709164800.0);  // a leap day
}

TEST(UtcDate, RefusesDaysAndTimesThatDoNotExist) {
  for (const char* text :
       {"2026-02-30", "2025-02-29", "2026-04-31", "2026-13-01", "2026-00-10", "2026-11-22T24:00",
        "2026-11-22T12:60", "2026-11-22T-1:00", "22.11.2026", "2026-11-22T12:00Z", " 2026-11-22",
        "2026-11-22T 9:05", "2026-+1-22", "2026-11-22T-0:00"}) {
    try {
      ParseUtcDate(text, "--start-time");
      ADD_FAILURE() << text << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(std::string("--start-time ") + text + ": ", 0), 0u)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace littermap
