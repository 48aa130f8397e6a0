#pragma once
// GeoPackage binary geometry (OGC 12-128r18, clause 2.1.3): the 'GP' header (version 0, flags,
// srs_id, an XY envelope) followed by little-endian ISO WKB. Only the 2D types littermap stores:
// POINT (litter items, hotspots) and LINESTRING (run tracks).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace littermap::db {

struct PointXY {
  double x = 0.0;
  double y = 0.0;
};

enum class WkbType : std::uint32_t { kPoint = 1, kLineString = 2 };

struct Envelope {
  double min_x = 0.0;
  double max_x = 0.0;
  double min_y = 0.0;
  double max_y = 0.0;
};

struct GeometryBlob {
  std::int32_t srs_id = 0;
  WkbType type = WkbType::kPoint;
  bool has_envelope = false;
  Envelope envelope;
  std::vector<PointXY> points;  // one for a POINT
};

std::vector<std::uint8_t> EncodePoint(const PointXY& point, std::int32_t srs_id);
// A LINESTRING needs at least two points (OGC simple features); throws UsageError otherwise.
std::vector<std::uint8_t> EncodeLineString(std::span<const PointXY> points, std::int32_t srs_id);

// Plain little-endian ISO WKB (what PostGIS's ST_GeomFromWKB reads and ST_AsBinary writes).
// Throws UsageError for a POINT without exactly one point or a LINESTRING of fewer than two.
std::vector<std::uint8_t> EncodeWkb(WkbType type, std::span<const PointXY> points);
// Reads either byte order; srs_id stays 0 and there is no envelope.
GeometryBlob DecodeWkb(std::span<const std::uint8_t> wkb, const std::string& where);

// Reads either byte order in header and WKB. Throws BadInputError naming `where` (table and fid)
// when the blob is not a 2D POINT/LINESTRING GeoPackage geometry.
GeometryBlob DecodeGeometry(std::span<const std::uint8_t> blob, const std::string& where);

Envelope EnvelopeOf(std::span<const PointXY> points);

}  // namespace littermap::db
