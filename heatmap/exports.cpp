#include "heatmap/exports.hpp"

#include <charconv>
#include <cstdio>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/output_file.hpp"

namespace littermap::heatmap {
namespace {

// `value` with `digits` decimals, as %.Nf writes it (both round the exact binary value), without
// printf's format parsing: the item exports write millions of numbers.
std::string Fixed(double value, int digits) {
  char text[400];
  const auto result =
      std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, digits);
  return std::string(text, result.ptr);
}

std::string Fixed(double a, double b, int digits) {
  return Fixed(a, digits) + ',' + Fixed(b, digits);
}

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

std::string LonLatColumns(const Wgs84Transform* wgs84, const db::PointXY& crs) {
  if (wgs84 == nullptr) return ",";
  const LonLat ll = (*wgs84)(crs);
  return Fixed(ll.lon_deg, ll.lat_deg, 8);
}

}  // namespace

void WriteItemsCsv(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                   const db::SiteFrame& frame, const Wgs84Transform* wgs84) {
  OutputFile output(file);
  std::ostream& out = output.stream();
  out << "fid,class,site_x_m,site_y_m,easting_m,northing_m,lon_deg,lat_deg,size_m,confidence,"
         "first_run_id,last_run_id,times_seen\n";
  for (const db::ItemRecord& item : items) {
    const db::PointXY crs = frame.ToCrs(item.site_xy);
    out << item.fid << ',' << CsvField(item.class_name) << ','
        << Fixed(item.site_xy.x, item.site_xy.y, 3) << ',' << Fixed(crs.x, crs.y, 3) << ','
        << LonLatColumns(wgs84, crs) << ',' << Fixed(item.size_m, item.confidence, 3) << ','
        << item.first_run_id << ',' << item.last_run_id << ',' << item.times_seen << '\n';
  }
  output.Commit();
}

void WriteItemsGeoJson(const std::filesystem::path& file, std::span<const db::ItemRecord> items,
                       const db::SiteFrame& frame, const Wgs84Transform& wgs84) {
  OutputFile output(file);
  std::ostream& out = output.stream();
  out << "{\"type\":\"FeatureCollection\",\"features\":[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const db::ItemRecord& item = items[i];
    const LonLat ll = wgs84(frame.ToCrs(item.site_xy));
    out << (i ? ",\n" : "\n") << "{\"type\":\"Feature\",\"id\":" << item.fid
        << ",\"geometry\":{\"type\":\"Point\",\"coordinates\":[" << Fixed(ll.lon_deg, ll.lat_deg, 8)
        << "]},\"properties\":{\"class\":" << JsonString(item.class_name)
        << ",\"size_m\":" << Fixed(item.size_m, 3)
        << ",\"confidence\":" << Fixed(item.confidence, 3)
        << ",\"first_run_id\":" << item.first_run_id << ",\"last_run_id\":" << item.last_run_id
        << ",\"times_seen\":" << item.times_seen << "}}";
  }
  out << "\n]}\n";
  output.Commit();
}

void WriteHotspotsCsv(const std::filesystem::path& file, std::span<const Hotspot> hotspots,
                      const db::SiteFrame& frame, const Wgs84Transform* wgs84) {
  OutputFile output(file);
  std::ostream& out = output.stream();
  out << "rank,site_x_m,site_y_m,easting_m,northing_m,lon_deg,lat_deg,density_per_100m2_per_survey,"
         "dominant_class,items_nearby\n";
  for (const Hotspot& hotspot : hotspots) {
    const db::PointXY site = frame.FromCrs(hotspot.crs);
    out << hotspot.rank << ',' << Fixed(site.x, site.y, 3) << ','
        << Fixed(hotspot.crs.x, hotspot.crs.y, 3) << ',' << LonLatColumns(wgs84, hotspot.crs) << ','
        << Fixed(hotspot.density_per_100m2, 4) << ',' << CsvField(hotspot.dominant_class) << ','
        << hotspot.items_nearby() << '\n';
  }
  output.Commit();
}

}  // namespace littermap::heatmap
