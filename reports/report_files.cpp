#include "reports/report_files.hpp"

#include <ctime>
#include <system_error>

#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/time.hpp"
#include "littermap_version.hpp"
#include "reports/plain_words.hpp"
#include "reports/report_json.hpp"

namespace littermap::reports {

ReportFilesOptions StampedReportFilesOptions() {
  ReportFilesOptions options;
  options.html.generated_utc = FormatUtc(static_cast<double>(std::time(nullptr)));
  options.html.version = LITTERMAP_VERSION;
  return options;
}

SiteReport WriteReportFiles(db::SiteDatabase& site, const std::filesystem::path& dir,
                            const ReportFilesOptions& options) {
  PrepareOutputFolder(dir, {"-o", {"index.html", "report.json"}, options.force_output});
  SiteReport report = BuildSiteReport(site, options.figures);
  const SiteMapFigure figure = DrawSiteMap(report, options.map);
  WriteHtmlReport(dir / "index.html", report, figure, options.html);
  WriteReportJson(dir / "report.json", report, options.html.generated_utc);
  return report;
}

SiteReport WriteReportFiles(const db::SiteLocator& site_file, const std::filesystem::path& dir,
                            const ReportFilesOptions& options) {
  db::SiteDatabase site = db::SiteDatabase::OpenReadOnly(site_file);
  return WriteReportFiles(site, dir, options);
}

std::string ReportSummary(const SiteReport& report, const std::filesystem::path& dir) {
  return "Report of " + report.site_name + ": " + CountOf(report.runs.size(), "run", "runs") +
         ", " + CountOf(report.items, "litter item", "litter items") + ", " +
         CountOf(report.hotspots.size(), "hotspot", "hotspots") + "\n" +
         (dir / "index.html").string();
}

}  // namespace littermap::reports
