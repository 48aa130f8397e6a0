#include "capture/odometry_protocol.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::capture {
namespace {

TEST(OdometryProtocol, ParsesTheDocumentedExample) {
  const auto reading =
      ParseOdometryLine("$ODOM,123456,1.2500,-0.3000,0.785400,0.4000,0.05000*07", "test");
  ASSERT_TRUE(reading.has_value());
  EXPECT_EQ(reading->time_ms, 123456u);
  EXPECT_DOUBLE_EQ(reading->T_odom_base.x_m, 1.25);
  EXPECT_DOUBLE_EQ(reading->T_odom_base.y_m, -0.3);
  EXPECT_DOUBLE_EQ(reading->T_odom_base.theta_rad, 0.7854);
  EXPECT_DOUBLE_EQ(reading->linear_mps, 0.4);
  EXPECT_DOUBLE_EQ(reading->angular_radps, 0.05);
}

TEST(OdometryProtocol, FormatRoundTripsWithinItsPrecision) {
  OdometryReading in;
  in.time_ms = 18446744073709551000ull;
  in.T_odom_base = {-123.45678, 9.87654, -3.1415926};
  in.linear_mps = -0.25;
  in.angular_radps = 1.5;
  const std::string line = FormatOdometryLine(in);
  const auto out = ParseOdometryLine(line + "\r", "test");  // CR LF line ends
  ASSERT_TRUE(out.has_value()) << line;
  EXPECT_EQ(out->time_ms, in.time_ms);
  EXPECT_NEAR(out->T_odom_base.x_m, in.T_odom_base.x_m, 1e-4);
  EXPECT_NEAR(out->T_odom_base.y_m, in.T_odom_base.y_m, 1e-4);
  EXPECT_NEAR(out->T_odom_base.theta_rad, in.T_odom_base.theta_rad, 1e-6);
  EXPECT_NEAR(out->linear_mps, in.linear_mps, 1e-4);
  EXPECT_NEAR(out->angular_radps, in.angular_radps, 1e-5);
}

TEST(OdometryProtocol, IgnoresOtherLines) {
  EXPECT_FALSE(ParseOdometryLine("", "test").has_value());
  EXPECT_FALSE(ParseOdometryLine("# battery 24.1 V", "test").has_value());
  EXPECT_FALSE(ParseOdometryLine("$GPGGA,123519,4807.038,N*47", "test").has_value());
}

TEST(OdometryProtocol, RejectsMalformedLinesQuotingThem) {
  const std::string good = FormatOdometryLine({});
  std::string bad_sum = good;
  bad_sum.back() = bad_sum.back() == '0' ? '1' : '0';
  const char* cases[] = {
      "$ODOM,1,2,3,4,5,6",   // no checksum
      "$ODOM,1,2,3,4,5*ZZ",  // checksum not hex
      "$ODOM,1,2,3,4,5*01",  // wrong sum (and too few fields)
  };
  for (const char* line : cases) {
    EXPECT_THROW(ParseOdometryLine(line, "tcp://base:1"), BadInputError) << line;
  }
  try {
    ParseOdometryLine(bad_sum, "tcp://base:1");
    FAIL() << "a wrong checksum was accepted";
  } catch (const BadInputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("tcp://base:1"), std::string::npos) << what;
    EXPECT_NE(what.find("checksum mismatch"), std::string::npos) << what;
    EXPECT_NE(what.find(bad_sum.substr(0, 20)), std::string::npos) << what;
  }
}

TEST(OdometryProtocol, RejectsBadFieldsWithAValidChecksum) {
  // Right sums over wrong content: field count, number syntax, non-finite values.
  const auto with_sum = [](const std::string& body) {
    unsigned sum = 0;
    for (const char c : body) sum ^= static_cast<unsigned char>(c);
    char text[8];
    std::snprintf(text, sizeof text, "*%02X", sum);
    return "$" + body + text;
  };
  for (const std::string body :
       {"ODOM,1,2,3,4,5", "ODOM,1,2,3,4,5,6,7", "ODOM,-1,2,3,4,5,6", "ODOM,1,2,x,4,5,6",
        "ODOM,1,2,3,nan,5,6", "ODOM,1,2,3,4,inf,6", "ODOM,1,,3,4,5,6"}) {
    EXPECT_THROW(ParseOdometryLine(with_sum(body), "test"), BadInputError) << body;
  }
  EXPECT_TRUE(ParseOdometryLine(with_sum("ODOM,1,2,3,4,5,6"), "test").has_value());
}

}  // namespace
}  // namespace littermap::capture
