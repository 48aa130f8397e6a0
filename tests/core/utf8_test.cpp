#include "core/utf8.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace littermap {
namespace {

TEST(Utf8, AcceptsWellFormedText) {
  EXPECT_TRUE(IsUtf8(""));
  EXPECT_TRUE(IsUtf8("North park"));
  EXPECT_TRUE(IsUtf8("Südwiese – Ørsted 公园 🌳"));
  EXPECT_TRUE(IsUtf8("\xF4\x8F\xBF\xBF"));  // U+10FFFF, the last code point
}

TEST(Utf8, RefusesMalformedSequences) {
  EXPECT_FALSE(IsUtf8("\xFF"));                 // never a UTF-8 byte
  EXPECT_FALSE(IsUtf8("caf\xE9"));              // Latin-1 é
  EXPECT_FALSE(IsUtf8("\xC0\xAF"));             // overlong '/'
  EXPECT_FALSE(IsUtf8("\xE0\x80\xAF"));         // overlong, three bytes
  EXPECT_FALSE(IsUtf8("\xED\xA0\x80"));         // a UTF-16 surrogate
  EXPECT_FALSE(IsUtf8("\xF4\x90\x80\x80"));     // above U+10FFFF
  EXPECT_FALSE(IsUtf8("\xE2\x80"));             // cut short
  EXPECT_FALSE(IsUtf8("\xE2\x28\xA1"));         // continuation byte missing
  EXPECT_FALSE(IsUtf8(std::string("a\x80z")));  // a stray continuation byte
}

TEST(Utf8, RequireNamesWhatAndWhere) {
  EXPECT_NO_THROW(RequireUtf8("Park", "--name"));
  try {
    RequireUtf8("ab\xC3", "site.gpkg: site name");
    ADD_FAILURE() << "accepted";
  } catch (const BadInputError& e) {
    EXPECT_EQ(std::string(e.what()), "site.gpkg: site name is not valid UTF-8 (byte 3 of 3)");
  }
}

}  // namespace
}  // namespace littermap
