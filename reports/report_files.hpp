#pragma once
// A site report as files: DIR/index.html (for people) and DIR/report.json (for tools), from one
// set of figures.

#include <filesystem>
#include <string>

#include "reports/html_report.hpp"
#include "reports/site_map_figure.hpp"
#include "reports/site_report.hpp"

namespace littermap::reports {

struct ReportFilesOptions {
  SiteReportOptions figures;
  SiteMapFigureOptions map;
  HtmlReportOptions html;     // generated_utc doubles as report.json's
  bool force_output = false;  // write into a folder holding other files too
};

// Stamps the report as generated now (or at SOURCE_DATE_EPOCH when set: throws UsageError when
// it is not whole seconds since 1970) by this littermap's version.
void StampReportFilesOptions(ReportFilesOptions& options);

// Creates `dir` if needed. Returns the figures written. Throws BadInputError when no run falls
// in the period, UsageError when the files cannot be written.
SiteReport WriteReportFiles(db::SiteDatabase& site, const std::filesystem::path& dir,
                            const ReportFilesOptions& options);
// The same for the site `site_file` (a GeoPackage or a PostGIS site); throws BadInputError when it
// is not one.
SiteReport WriteReportFiles(const db::SiteLocator& site_file, const std::filesystem::path& dir,
                            const ReportFilesOptions& options);

// What was written: the site, its runs, items and hotspots, and DIR/index.html on a line of its
// own.
std::string ReportSummary(const SiteReport& report, const std::filesystem::path& dir);

}  // namespace littermap::reports
