#include "core/utc_date.hpp"

#include <cstdio>
#include <ctime>

#include "core/error.hpp"

namespace littermap {

std::optional<double> ParseUtcDate(const std::string& text, const char* option) {
  if (text.empty()) return std::nullopt;
  std::tm date{};
  char separator = 0;
  char rest = 0;
  const int fields =
      std::sscanf(text.c_str(), "%4d-%2d-%2d%c%2d:%2d:%2d%c", &date.tm_year, &date.tm_mon,
                  &date.tm_mday, &separator, &date.tm_hour, &date.tm_min, &date.tm_sec, &rest);
  const bool date_only = fields == 3;
  const bool with_time = (fields == 6 || fields == 7) && (separator == 'T' || separator == ' ');
  if ((!date_only && !with_time) || date.tm_mon < 1 || date.tm_mon > 12 || date.tm_mday < 1 ||
      date.tm_mday > 31 || date.tm_hour > 23 || date.tm_min > 59 || date.tm_sec > 60) {
    throw UsageError(std::string(option) + " " + text +
                     ": expected a UTC date YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS]");
  }
  date.tm_year -= 1900;
  date.tm_mon -= 1;
  return static_cast<double>(timegm(&date));
}

}  // namespace littermap
