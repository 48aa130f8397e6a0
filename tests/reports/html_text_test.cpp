#include "reports/html_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace littermap::reports {
namespace {

TEST(EscapeHtml, EscapesEveryCharacterThatEndsTextOrAnAttribute) {
  EXPECT_EQ(EscapeHtml(R"(<script>alert("x") & 'y'</script>)"),
            "&lt;script&gt;alert(&quot;x&quot;) &amp; &#39;y&#39;&lt;/script&gt;");
  EXPECT_EQ(EscapeHtml("Stadtpark Süd"), "Stadtpark Süd");  // UTF-8 passes through
  EXPECT_EQ(EscapeHtml(""), "");
}

TEST(Base64, MatchesTheRfc4648TestVectors) {
  const std::vector<std::pair<std::string, std::string>> vectors = {{"", ""},
                                                                    {"f", "Zg=="},
                                                                    {"fo", "Zm8="},
                                                                    {"foo", "Zm9v"},
                                                                    {"foob", "Zm9vYg=="},
                                                                    {"fooba", "Zm9vYmE="},
                                                                    {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors) {
    const std::vector<unsigned char> bytes(plain.begin(), plain.end());
    EXPECT_EQ(Base64(bytes), encoded) << plain;
  }
  const std::vector<unsigned char> high = {0xff, 0xfe, 0x00};
  EXPECT_EQ(Base64(high), "//4A");
}

TEST(FormatNumber, RoundsAndGroupsThousands) {
  EXPECT_EQ(FormatNumber(3.14159, 2), "3.14");
  EXPECT_EQ(FormatNumber(999, 0), "999");
  EXPECT_EQ(FormatNumber(1234567.26, 1), "1\u2009234\u2009567.3");
  EXPECT_EQ(FormatNumber(-4500, 0), "-4\u2009500");
}

}  // namespace
}  // namespace littermap::reports
