#pragma once
// index.html: the report park staff read. One self-contained file (inline CSS, images as data:
// URLs, no script, nothing fetched), readable on a phone and printable on A4: key figures, the
// site map with litter density and items, where to clean first, what litter, change over time
// with the survey effort beside it, and how reliable each run is.

#include <filesystem>
#include <string>

#include "reports/site_map_figure.hpp"
#include "reports/site_report.hpp"

namespace littermap::reports {

struct HtmlReportOptions {
  std::string generated_utc;  // shown in the header
  std::string version;        // littermap's
};

std::string HtmlReport(const SiteReport& report, const SiteMapFigure& figure,
                       const HtmlReportOptions& options);

// Writes HtmlReport atomically. Throws UsageError when the file cannot be written.
void WriteHtmlReport(const std::filesystem::path& file, const SiteReport& report,
                     const SiteMapFigure& figure, const HtmlReportOptions& options);

}  // namespace littermap::reports
