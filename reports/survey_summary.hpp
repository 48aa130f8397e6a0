#pragma once
// What `littermap survey` tells the user at the end, from the site's report: the run's distance,
// ground covered, litter found by class, new / still there / gone, its notes, the site's totals,
// the three densest hotspots and where the report is.

#include <filesystem>
#include <string>

#include "reports/site_report.hpp"

namespace littermap::reports {

std::string SurveySummary(const SiteReport& report, const std::string& run_name,
                          const std::filesystem::path& report_html);

}  // namespace littermap::reports
