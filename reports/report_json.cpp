#include "reports/report_json.hpp"

#include <nlohmann/json.hpp>

#include "core/output_file.hpp"
#include "core/time.hpp"

namespace littermap::reports {
namespace {

using Json = nlohmann::ordered_json;

Json Counts(const ClassCounts& counts) {
  Json json = Json::object();
  for (const auto& [name, count] : counts) json[name] = count;
  return json;
}

Json Time(double unix_s) {
  return {{"unix_s", unix_s}, {"utc", FormatUtc(unix_s, "%Y-%m-%dT%H:%M:%SZ")}};
}

Json RunJson(const RunFigures& run) {
  Json json;
  json["run_id"] = run.run_id;
  json["name"] = run.name;
  json["start"] = Time(run.start_time_s);
  json["end"] = Time(run.end_time_s);
  json["length_m"] = run.length_m;
  json["observed_area_m2"] = run.observed_area_m2;
  json["coverage_fraction"] = run.coverage_fraction;
  json["detections"] = run.detections;
  json["items_found"] = run.items_found;
  json["new_items"] = run.new_items;
  json["items_still_there"] = run.items_still_there;
  json["items_gone"] = run.items_gone;
  json["items_per_100m2"] = run.items_per_100m2;
  json["items_by_class"] = Counts(run.items_by_class);
  json["registration_quality"] =
      run.registration_quality ? Json(*run.registration_quality) : Json(nullptr);
  Json quality;
  quality["known"] = run.quality.known;
  quality["scans"] = run.quality.scans;
  Json routines = Json::object();
  for (const auto& [name, count] : run.quality.routines) routines[name] = count;
  quality["routines"] = routines;
  quality["key_frames"] = run.quality.key_frames;
  quality["loop_closures_found"] = run.quality.loop_closures_found;
  quality["loop_closures_accepted"] = run.quality.loop_closures_accepted;
  json["reconstruction"] = quality;
  json["warnings"] = run.warnings;
  return json;
}

Json HotspotJson(const HotspotFigures& h) {
  Json json;
  json["rank"] = h.rank;
  json["site_x_m"] = h.site_xy.x;
  json["site_y_m"] = h.site_xy.y;
  json["crs_x"] = h.crs.x;
  json["crs_y"] = h.crs.y;
  json["lon_deg"] = h.wgs84 ? Json(h.wgs84->lon_deg) : Json(nullptr);
  json["lat_deg"] = h.wgs84 ? Json(h.wgs84->lat_deg) : Json(nullptr);
  json["density_per_100m2"] = h.density_per_100m2;
  json["dominant_class"] = h.dominant_class;
  json["items_by_class"] = Counts(h.items_by_class);
  Json trend = Json::array();
  for (const auto& v : h.density_by_run) trend.push_back(v ? Json(*v) : Json(nullptr));
  json["density_by_run"] = trend;
  return json;
}

}  // namespace

std::string ReportJson(const SiteReport& report, const std::string& generated_utc) {
  Json json;
  json["site"] = {
      {"name", report.site_name},
      {"epsg_code", report.frame.georeferenced() ? Json(report.frame.epsg_code) : Json(nullptr)}};
  json["generated_utc"] = generated_utc;
  json["period"] = {{"from", report.from_time_s ? Time(*report.from_time_s) : Json(nullptr)},
                    {"to", report.to_time_s ? Time(*report.to_time_s) : Json(nullptr)}};
  json["totals"] = {{"runs", report.runs.size()},
                    {"items", report.items},
                    {"detections", report.detections},
                    {"surveyed_area_m2", report.surveyed_area_m2},
                    {"length_m", report.length_m},
                    {"peak_density_per_100m2", report.peak_density_per_100m2},
                    {"kernel_bandwidth_m", report.bandwidth_m},
                    {"min_confidence", report.min_confidence}};
  json["items_by_class"] = Counts(report.items_by_class);
  json["hotspots"] = Json::array();
  for (const HotspotFigures& h : report.hotspots) json["hotspots"].push_back(HotspotJson(h));
  json["runs"] = Json::array();
  for (const RunFigures& run : report.runs) json["runs"].push_back(RunJson(run));
  json["warnings"] = report.warnings;
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void WriteReportJson(const std::filesystem::path& file, const SiteReport& report,
                     const std::string& generated_utc) {
  WriteFileAtomically(file, ReportJson(report, generated_utc));
}

}  // namespace littermap::reports
