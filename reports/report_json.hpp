#pragma once
// report.json: the figures of the HTML report for other tools. Lengths in metres, areas in m2,
// densities in items per 100 m2 per survey, times in Unix seconds and UTC text.

#include <filesystem>
#include <string>

#include "reports/site_report.hpp"

namespace littermap::reports {

std::string ReportJson(const SiteReport& report, const std::string& generated_utc);

// Writes ReportJson atomically. Throws UsageError when the file cannot be written.
void WriteReportJson(const std::filesystem::path& file, const SiteReport& report,
                     const std::string& generated_utc);

}  // namespace littermap::reports
