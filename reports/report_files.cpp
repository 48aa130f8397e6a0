#include "reports/report_files.hpp"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/time.hpp"
#include "littermap_version.hpp"
#include "reports/plain_words.hpp"
#include "reports/report_json.hpp"

namespace littermap::reports {

namespace {

// Now, or SOURCE_DATE_EPOCH (seconds since 1970, the reproducible-builds convention) when set,
// so that the same site gives byte-identical reports.
double GenerationTimeS() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (epoch == nullptr || *epoch == '\0') return static_cast<double>(std::time(nullptr));
  std::int64_t seconds = 0;
  const char* end = epoch + std::strlen(epoch);
  const auto [stop, error] = std::from_chars(epoch, end, seconds);
  if (error != std::errc() || stop != end || seconds < 0 || seconds > 253402300799) {
    throw UsageError(std::string("SOURCE_DATE_EPOCH: not a time in whole seconds since 1970: '") +
                     epoch + "'");
  }
  return static_cast<double>(seconds);
}

}  // namespace

void StampReportFilesOptions(ReportFilesOptions& options) {
  options.html.generated_utc = FormatUtc(GenerationTimeS());
  options.html.version = LITTERMAP_VERSION;
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
