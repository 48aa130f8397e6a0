#include "db/geometry_blob.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "core/error.hpp"

namespace littermap::db {
namespace {

TEST(GeometryBlob, PointHeaderIsLittleEndianWithXYEnvelope) {
  const auto blob = EncodePoint({12.5, -3.25}, 32633);
  // 8 header bytes + 32 envelope + 21 WKB point bytes.
  ASSERT_EQ(blob.size(), 61u);
  EXPECT_EQ(blob[0], 'G');
  EXPECT_EQ(blob[1], 'P');
  EXPECT_EQ(blob[2], 0);     // version 1 is encoded as 0
  EXPECT_EQ(blob[3], 0x03);  // envelope indicator 1 (bits 1-3), little-endian (bit 0)
  std::int32_t srs_id = 0;
  std::memcpy(&srs_id, blob.data() + 4, 4);
  EXPECT_EQ(srs_id, 32633);
  EXPECT_EQ(blob[40], 1);  // WKB byte order
  std::uint32_t type = 0;
  std::memcpy(&type, blob.data() + 41, 4);
  EXPECT_EQ(type, 1u);
}

TEST(GeometryBlob, PointRoundTrip) {
  const GeometryBlob decoded = DecodeGeometry(EncodePoint({12.5, -3.25}, 100000), "test");
  EXPECT_EQ(decoded.srs_id, 100000);
  EXPECT_EQ(decoded.type, WkbType::kPoint);
  ASSERT_EQ(decoded.points.size(), 1u);
  EXPECT_EQ(decoded.points[0].x, 12.5);
  EXPECT_EQ(decoded.points[0].y, -3.25);
  EXPECT_TRUE(decoded.has_envelope);
  EXPECT_EQ(decoded.envelope.min_x, 12.5);
  EXPECT_EQ(decoded.envelope.max_y, -3.25);
}

TEST(GeometryBlob, LineStringRoundTripWithEnvelope) {
  const std::vector<PointXY> points = {{0, 0}, {10, 5}, {-2, 7}};
  const GeometryBlob decoded = DecodeGeometry(EncodeLineString(points, -1), "test");
  EXPECT_EQ(decoded.type, WkbType::kLineString);
  ASSERT_EQ(decoded.points.size(), 3u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(decoded.points[i].x, points[i].x);
    EXPECT_EQ(decoded.points[i].y, points[i].y);
  }
  EXPECT_EQ(decoded.envelope.min_x, -2);
  EXPECT_EQ(decoded.envelope.max_x, 10);
  EXPECT_EQ(decoded.envelope.min_y, 0);
  EXPECT_EQ(decoded.envelope.max_y, 7);
}

TEST(GeometryBlob, ReadsBigEndianWithoutEnvelope) {
  // GP, version 0, flags 0 (no envelope, big-endian), srs_id 4326, WKB big-endian POINT(1 2).
  std::vector<std::uint8_t> blob = {'G', 'P', 0, 0, 0x00, 0x00, 0x10, 0xE6, 0, 0, 0, 0, 1};
  const std::uint8_t one[8] = {0x3F, 0xF0, 0, 0, 0, 0, 0, 0};
  const std::uint8_t two[8] = {0x40, 0x00, 0, 0, 0, 0, 0, 0};
  blob.insert(blob.end(), one, one + 8);
  blob.insert(blob.end(), two, two + 8);
  const GeometryBlob decoded = DecodeGeometry(blob, "test");
  EXPECT_EQ(decoded.srs_id, 4326);
  EXPECT_FALSE(decoded.has_envelope);
  ASSERT_EQ(decoded.points.size(), 1u);
  EXPECT_EQ(decoded.points[0].x, 1.0);
  EXPECT_EQ(decoded.points[0].y, 2.0);
}

TEST(GeometryBlob, DamagedBlobsNameTheirPlace) {
  const auto blob = EncodePoint({1, 2}, 4326);
  const std::span<const std::uint8_t> truncated(blob.data(), blob.size() - 4);
  try {
    DecodeGeometry(truncated, "site.gpkg: litter_items fid 7");
    FAIL() << "a truncated blob decoded";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("litter_items fid 7"), std::string::npos) << e.what();
  }
  std::vector<std::uint8_t> wrong_magic = EncodePoint({1, 2}, 4326);
  wrong_magic[0] = 'X';
  EXPECT_THROW(DecodeGeometry(wrong_magic, "x"), BadInputError);
  EXPECT_THROW(EncodeLineString(std::vector<PointXY>{{1, 2}}, 4326), UsageError);
}

}  // namespace
}  // namespace littermap::db
