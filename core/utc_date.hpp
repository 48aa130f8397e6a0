#pragma once
// Dates as users write them: "2026-11-22" (UTC midnight) or "2026-11-22T14:30[:05]" (UTC), as
// Unix seconds (core/time.hpp FormatUtc goes the other way).

#include <optional>
#include <string>

namespace littermap {

// None for an empty text; throws UsageError naming `option` (the option or field the text came
// from) for anything else unreadable.
std::optional<double> ParseUtcDate(const std::string& text, const char* option);

}  // namespace littermap
