#include "heatmap/exports.hpp"

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/output_file.hpp"

namespace littermap::heatmap {
namespace {

// The text of one export, built in memory and handed to the stream in large pieces: the item
// exports write millions of numbers, and a stream insertion per field was most of their time.
class ExportText {
 public:
  explicit ExportText(std::ostream& out) : out_(out) { text_.reserve(kFlushBytes + 4096); }

  ExportText& operator<<(std::string_view text) {
    text_ += text;
    return *this;
  }
  ExportText& operator<<(char c) {
    text_ += c;
    return *this;
  }
  ExportText& operator<<(std::int64_t value) {
    char digits[24];
    text_.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
    return *this;
  }
  ExportText& operator<<(int value) { return *this << static_cast<std::int64_t>(value); }

  // `value` with `digits` decimals, as %.Nf writes it (both round the exact binary value).
  ExportText& Fixed(double value, int digits) {
    char text[400];
    text_.append(
        text, std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, digits).ptr);
    return *this;
  }
  ExportText& Fixed(double a, double b, int digits) {
    Fixed(a, digits);
    text_ += ',';
    return Fixed(b, digits);
  }

  // Ends a record: hands the text over once enough has gathered.
  void EndRecord() {
    if (text_.size() >= kFlushBytes) Flush();
  }
  void Flush() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  static constexpr std::size_t kFlushBytes = 1 << 20;
  std::ostream& out_;
  std::string text_;
};

// A JSON string literal (class names come from files).
std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", c);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// RFC 4180: a field with a comma, quote or line break is quoted, its quotes doubled. A field a
// spreadsheet would run as a formula (it begins with =, +, -, @, a tab or a carriage return) is
// also quoted, behind a leading apostrophe that makes it text (OWASP's CSV injection advice).
std::string CsvField(const std::string& text) {
  const bool formula =
      !text.empty() && std::string_view("=+-@\t\r").find(text[0]) != std::string_view::npos;
  if (!formula && text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = formula ? "\"'" : "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

void LonLatColumns(ExportText& out, std::span<const LonLat> lonlat, std::size_t i) {
  if (lonlat.empty()) {
    out << ',';
  } else {
    out.Fixed(lonlat[i].lon_deg, lonlat[i].lat_deg, 8);
  }
}

void CheckLonLat(const std::filesystem::path& file, std::size_t points, std::size_t lonlat) {
  if (lonlat != 0 && lonlat != points) {
    throw UsageError(file.string() + ": " + std::to_string(lonlat) + " WGS 84 positions for " +
                     std::to_string(points) + " points");
  }
}

}  // namespace

std::vector<LonLat> ItemsLonLat(std::span<const db::ItemRecord> items, const db::SiteFrame& frame,
                                const Wgs84Transform* wgs84) {
  if (wgs84 == nullptr) return {};
  std::vector<db::PointXY> crs;
  crs.reserve(items.size());
  for (const db::ItemRecord& item : items) crs.push_back(frame.ToCrs(item.site_xy));
  return (*wgs84)(crs);
}

void WriteItemsCsv(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                   const db::SiteFrame& frame, std::span<const LonLat> lonlat) {
  CheckLonLat(file, items.size(), lonlat.size());
  OutputFile output(file);
  ExportText out(output.stream());
  out << "fid,class,site_x_m,site_y_m,easting_m,northing_m,lon_deg,lat_deg,size_m,confidence,"
         "first_run_id,last_run_id,times_seen\n";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const db::ItemRecord& item = items[i];
    const db::PointXY crs = frame.ToCrs(item.site_xy);
    out << item.fid << ',' << CsvField(item.class_name) << ',';
    out.Fixed(item.site_xy.x, item.site_xy.y, 3) << ',';
    out.Fixed(crs.x, crs.y, 3) << ',';
    LonLatColumns(out, lonlat, i);
    out << ',';
    out.Fixed(item.size_m, item.confidence, 3)
        << ',' << item.first_run_id << ',' << item.last_run_id << ',' << item.times_seen << '\n';
    out.EndRecord();
  }
  out.Flush();
  output.Commit();
}

void WriteItemsGeoJson(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                       std::span<const LonLat> lonlat) {
  if (lonlat.size() != items.size()) {
    throw UsageError(file.string() + ": GeoJSON needs the WGS 84 position of every item (" +
                     std::to_string(lonlat.size()) + " for " + std::to_string(items.size()) + ")");
  }
  OutputFile output(file);
  ExportText out(output.stream());
  out << "{\"type\":\"FeatureCollection\",\"features\":[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const db::ItemRecord& item = items[i];
    out << (i ? ",\n" : "\n") << "{\"type\":\"Feature\",\"id\":" << item.fid
        << ",\"geometry\":{\"type\":\"Point\",\"coordinates\":[";
    out.Fixed(lonlat[i].lon_deg, lonlat[i].lat_deg, 8)
        << "]},\"properties\":{\"class\":" << JsonString(item.class_name) << ",\"size_m\":";
    out.Fixed(item.size_m, 3) << ",\"confidence\":";
    out.Fixed(item.confidence, 3) << ",\"first_run_id\":" << item.first_run_id
                                  << ",\"last_run_id\":" << item.last_run_id
                                  << ",\"times_seen\":" << item.times_seen << "}}";
    out.EndRecord();
  }
  out << "\n]}\n";
  out.Flush();
  output.Commit();
}

void WriteHotspotsCsv(const std::filesystem::path& file, std::span<const Hotspot> hotspots,
                      const db::SiteFrame& frame, const Wgs84Transform* wgs84) {
  std::vector<db::PointXY> crs;
  for (const Hotspot& hotspot : hotspots) crs.push_back(hotspot.crs);
  const std::vector<LonLat> lonlat = wgs84 ? (*wgs84)(crs) : std::vector<LonLat>();
  OutputFile output(file);
  ExportText out(output.stream());
  out << "rank,site_x_m,site_y_m,easting_m,northing_m,lon_deg,lat_deg,density_per_100m2_per_survey,"
         "dominant_class,items_nearby\n";
  for (std::size_t i = 0; i < hotspots.size(); ++i) {
    const Hotspot& hotspot = hotspots[i];
    const db::PointXY site = frame.FromCrs(hotspot.crs);
    out << hotspot.rank << ',';
    out.Fixed(site.x, site.y, 3) << ',';
    out.Fixed(hotspot.crs.x, hotspot.crs.y, 3) << ',';
    LonLatColumns(out, lonlat, i);
    out << ',';
    out.Fixed(hotspot.density_per_100m2, 4)
        << ',' << CsvField(hotspot.dominant_class) << ',' << hotspot.items_nearby() << '\n';
  }
  out.Flush();
  output.Commit();
}

}  // namespace littermap::heatmap
