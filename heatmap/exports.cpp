#include "heatmap/exports.hpp"

#include <cstdio>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/output_file.hpp"

namespace littermap::heatmap {
namespace {

// Formats one or two numbers (b is ignored by a one-number format).
std::string Format(const char* format, double a, double b) {
  char text[96];
  std::snprintf(text, sizeof(text), format, a, b);
  return text;
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
  return Format("%.8f,%.8f", ll.lon_deg, ll.lat_deg);
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
        << Format("%.3f,%.3f", item.site_xy.x, item.site_xy.y) << ','
        << Format("%.3f,%.3f", crs.x, crs.y) << ',' << LonLatColumns(wgs84, crs) << ','
        << Format("%.3f,%.3f", item.size_m, item.confidence) << ',' << item.first_run_id << ','
        << item.last_run_id << ',' << item.times_seen << '\n';
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
        << ",\"geometry\":{\"type\":\"Point\",\"coordinates\":["
        << Format("%.8f,%.8f", ll.lon_deg, ll.lat_deg)
        << "]},\"properties\":{\"class\":" << JsonString(item.class_name)
        << Format(",\"size_m\":%.3f,\"confidence\":%.3f", item.size_m, item.confidence)
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
    out << hotspot.rank << ',' << Format("%.3f,%.3f", site.x, site.y) << ','
        << Format("%.3f,%.3f", hotspot.crs.x, hotspot.crs.y) << ','
        << LonLatColumns(wgs84, hotspot.crs) << ','
        << Format("%.4f", hotspot.density_per_100m2, 0.0) << ',' << CsvField(hotspot.dominant_class)
        << ',' << hotspot.items_nearby() << '\n';
  }
  output.Commit();
}

}  // namespace littermap::heatmap
