#pragma once
// Dates on the command line: "2026-11-22" (UTC midnight) or "2026-11-22T14:30[:05]" (UTC), as
// Unix seconds (core/time.hpp FormatUtc goes the other way).

#include <optional>
#include <string>

namespace littermap::cli {

// None for an empty text; throws UsageError naming `option` for anything else unreadable.
std::optional<double> ParseDateArgument(const std::string& text, const char* option);

}  // namespace littermap::cli
