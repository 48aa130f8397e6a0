#include "run/run_name.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace littermap::run {
namespace {

TEST(RunName, IsTheFolderNameWithOrWithoutATrailingSlash) {
  EXPECT_EQ(RunNameFromPath("/data/week1"), "week1");
  EXPECT_EQ(RunNameFromPath("/data/week1/"), "week1");
  EXPECT_EQ(RunNameFromPath("/data/week1/."), "week1");
  EXPECT_EQ(RunNameFromPath("/data/x/../week 2"), "week 2");
}

TEST(RunName, AFolderCalledRunOrBagIsNamedAfterTheFolderHoldingIt) {
  EXPECT_EQ(RunNameFromPath("/data/week1-survey/run"), "week1");
  EXPECT_EQ(RunNameFromPath("/data/week1-survey/run/"), "week1");
  EXPECT_EQ(RunNameFromPath("/park/week2/bag"), "week2");
  EXPECT_EQ(RunNameFromPath("/park/week2/run"), "week2");
}

TEST(RunName, APathWithoutAFolderNameIsRefused) {
  EXPECT_THROW(RunNameFromPath("/"), UsageError);
  EXPECT_THROW(RunNameFromPath("/.."), UsageError);
}

TEST(RunName, GivenNamesAreNonEmptyShortUtf8) {
  EXPECT_NO_THROW(CheckRunName("Woche 1 – Südwiese", "--name"));
  EXPECT_THROW(CheckRunName("", "--name"), UsageError);
  EXPECT_THROW(CheckRunName(std::string(kMaxRunNameBytes + 1, 'x'), "--name"), UsageError);
  try {
    CheckRunName("week \xff", "--name");
    ADD_FAILURE() << "invalid UTF-8 accepted";
  } catch (const BadInputError& e) {
    EXPECT_EQ(std::string(e.what()), "--name is not valid UTF-8 (byte 6 of 6)");
  }
}

}  // namespace
}  // namespace littermap::run
