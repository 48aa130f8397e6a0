#pragma once
// A site report as files: DIR/index.html (for people) and DIR/report.json (for tools), from one
// set of figures.

#include <filesystem>

#include "reports/html_report.hpp"
#include "reports/site_map_figure.hpp"
#include "reports/site_report.hpp"

namespace littermap::reports {

struct ReportFilesOptions {
  SiteReportOptions figures;
  SiteMapFigureOptions map;
  HtmlReportOptions html;  // generated_utc doubles as report.json's
};

// Creates `dir` if needed. Returns the figures written. Throws BadInputError when no run falls
// in the period, UsageError when the files cannot be written.
SiteReport WriteReportFiles(db::SiteDatabase& site, const std::filesystem::path& dir,
                            const ReportFilesOptions& options);

}  // namespace littermap::reports
