#include "db/geometry_blob.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "core/error.hpp"

namespace littermap::db {
namespace {

constexpr std::uint8_t kFlagLittleEndian = 0x01;
constexpr std::uint8_t kEnvelopeXY = 1;  // envelope contents indicator: minx, maxx, miny, maxy
constexpr std::uint8_t kFlagEmpty = 0x10;
constexpr std::uint8_t kFlagExtended = 0x20;

static_assert(std::endian::native == std::endian::little, "writer assumes a little-endian host");

class Writer {
 public:
  template <typename T>
  void Put(T value) {
    std::uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.insert(out.end(), bytes, bytes + sizeof(T));
  }
  std::vector<std::uint8_t> out;
};

void PutHeader(Writer& writer, std::int32_t srs_id, const Envelope& envelope) {
  writer.Put<std::uint8_t>('G');
  writer.Put<std::uint8_t>('P');
  writer.Put<std::uint8_t>(0);  // version 1 of the binary format is encoded as 0
  writer.Put<std::uint8_t>(static_cast<std::uint8_t>((kEnvelopeXY << 1) | kFlagLittleEndian));
  writer.Put(srs_id);
  writer.Put(envelope.min_x);
  writer.Put(envelope.max_x);
  writer.Put(envelope.min_y);
  writer.Put(envelope.max_y);
}

void PutWkb(Writer& writer, WkbType type, std::span<const PointXY> points) {
  if (type == WkbType::kPoint && points.size() != 1) {
    throw UsageError("a POINT geometry has exactly one point");
  }
  if (type == WkbType::kLineString && points.size() < 2) {
    throw UsageError("a LINESTRING geometry needs at least two points");
  }
  writer.Put<std::uint8_t>(1);  // WKB little-endian
  writer.Put(static_cast<std::uint32_t>(type));
  if (type == WkbType::kLineString) writer.Put(static_cast<std::uint32_t>(points.size()));
  for (const PointXY& p : points) {
    writer.Put(p.x);
    writer.Put(p.y);
  }
}

class Reader {
 public:
  Reader(std::span<const std::uint8_t> bytes, const std::string& where, const char* format)
      : bytes_(bytes), where_(where), format_(format) {}

  template <typename T>
  T Get(bool little_endian) {
    if (offset_ + sizeof(T) > bytes_.size()) Fail("blob is truncated");
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + offset_, sizeof(T));
    if (!little_endian) std::reverse(raw, raw + sizeof(T));
    offset_ += sizeof(T);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }
  std::uint8_t Byte() { return Get<std::uint8_t>(true); }
  [[noreturn]] void Fail(const std::string& what) const {
    throw BadInputError(where_ + ": not " + format_ + ": " + what);
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::string where_;
  const char* format_;
  std::size_t offset_ = 0;
};

// The WKB that follows the reader's position: a 2D POINT or LINESTRING.
void GetWkb(Reader& reader, std::size_t size, GeometryBlob& geometry) {
  const std::uint8_t wkb_order = reader.Byte();
  if (wkb_order > 1) reader.Fail("WKB byte order " + std::to_string(wkb_order) + " is invalid");
  const bool wkb_le = wkb_order == 1;
  const auto type = reader.Get<std::uint32_t>(wkb_le);
  std::uint32_t count = 1;
  if (type == static_cast<std::uint32_t>(WkbType::kLineString)) {
    count = reader.Get<std::uint32_t>(wkb_le);
  } else if (type != static_cast<std::uint32_t>(WkbType::kPoint)) {
    reader.Fail("WKB type " + std::to_string(type) + " is not a 2D POINT or LINESTRING");
  }
  if (count > size / 16) reader.Fail("point count " + std::to_string(count) + " exceeds blob");
  geometry.type = static_cast<WkbType>(type);
  geometry.points.resize(count);
  for (PointXY& p : geometry.points) {
    p.x = reader.Get<double>(wkb_le);
    p.y = reader.Get<double>(wkb_le);
  }
}

std::size_t EnvelopeDoubles(std::uint8_t indicator, const Reader& reader) {
  switch (indicator) {
    case 0:
      return 0;
    case 1:
      return 4;
    case 2:
    case 3:
      return 6;
    case 4:
      return 8;
    default:
      reader.Fail("envelope indicator " + std::to_string(indicator) + " is invalid");
  }
}

}  // namespace

Envelope EnvelopeOf(std::span<const PointXY> points) {
  Envelope envelope;
  if (points.empty()) return envelope;
  envelope = {points[0].x, points[0].x, points[0].y, points[0].y};
  for (const PointXY& p : points) {
    envelope.min_x = std::min(envelope.min_x, p.x);
    envelope.max_x = std::max(envelope.max_x, p.x);
    envelope.min_y = std::min(envelope.min_y, p.y);
    envelope.max_y = std::max(envelope.max_y, p.y);
  }
  return envelope;
}

std::vector<std::uint8_t> EncodeWkb(WkbType type, std::span<const PointXY> points) {
  Writer writer;
  PutWkb(writer, type, points);
  return std::move(writer.out);
}

std::vector<std::uint8_t> EncodePoint(const PointXY& point, std::int32_t srs_id) {
  Writer writer;
  PutHeader(writer, srs_id, {point.x, point.x, point.y, point.y});
  PutWkb(writer, WkbType::kPoint, std::span(&point, 1));
  return std::move(writer.out);
}

std::vector<std::uint8_t> EncodeLineString(std::span<const PointXY> points, std::int32_t srs_id) {
  Writer writer;
  PutHeader(writer, srs_id, EnvelopeOf(points));
  PutWkb(writer, WkbType::kLineString, points);
  return std::move(writer.out);
}

GeometryBlob DecodeGeometry(std::span<const std::uint8_t> blob, const std::string& where) {
  Reader reader(blob, where, "a GeoPackage geometry");
  if (reader.Byte() != 'G' || reader.Byte() != 'P') reader.Fail("magic is not 'GP'");
  if (const std::uint8_t version = reader.Byte(); version != 0) {
    reader.Fail("version " + std::to_string(version) + " is not 0");
  }
  const std::uint8_t flags = reader.Byte();
  if (flags & kFlagExtended) reader.Fail("extended geometry types are not supported");
  if (flags & kFlagEmpty) reader.Fail("the geometry is empty");
  const bool header_le = flags & kFlagLittleEndian;
  GeometryBlob geometry;
  geometry.srs_id = reader.Get<std::int32_t>(header_le);
  const std::size_t doubles =
      EnvelopeDoubles(static_cast<std::uint8_t>((flags >> 1) & 0x07), reader);
  double envelope[8] = {};
  for (std::size_t i = 0; i < doubles; ++i) envelope[i] = reader.Get<double>(header_le);
  geometry.has_envelope = doubles > 0;
  geometry.envelope = {envelope[0], envelope[1], envelope[2], envelope[3]};

  GetWkb(reader, blob.size(), geometry);
  return geometry;
}

GeometryBlob DecodeWkb(std::span<const std::uint8_t> wkb, const std::string& where) {
  Reader reader(wkb, where, "a WKB geometry");
  GeometryBlob geometry;
  GetWkb(reader, wkb.size(), geometry);
  return geometry;
}

}  // namespace littermap::db
