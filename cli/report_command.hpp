#pragma once
// What `littermap report` and `littermap survey` share: the report's defaults.

#include "reports/report_files.hpp"

namespace littermap::cli {

// Default figures, generated now, stamped with this littermap's version.
reports::ReportFilesOptions DefaultReportOptions();

}  // namespace littermap::cli
