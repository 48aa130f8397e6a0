#include "reports/report_files.hpp"

#include <system_error>

#include "core/error.hpp"
#include "reports/report_json.hpp"

namespace littermap::reports {

SiteReport WriteReportFiles(db::SiteDatabase& site, const std::filesystem::path& dir,
                            const ReportFilesOptions& options) {
  SiteReport report = BuildSiteReport(site, options.figures);
  const SiteMapFigure figure = DrawSiteMap(report, options.map);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw UsageError(dir.string() + ": cannot create the directory: " + error.message());
  WriteHtmlReport(dir / "index.html", report, figure, options.html);
  WriteReportJson(dir / "report.json", report, options.html.generated_utc);
  return report;
}

}  // namespace littermap::reports
