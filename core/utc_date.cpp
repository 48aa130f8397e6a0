#include "core/utc_date.hpp"

#include <cstdio>
#include <ctime>
#include <regex>

#include "core/error.hpp"

namespace littermap {

std::optional<double> ParseUtcDate(const std::string& text, const char* option) {
  if (text.empty()) return std::nullopt;
  // sscanf's %d skips blanks and takes signs: the layout is checked first.
  static const std::regex kLayout(R"(\d{4}-\d{2}-\d{2}([T ]\d{2}:\d{2}(:\d{2})?)?)");
  if (!std::regex_match(text, kLayout)) {
    throw UsageError(std::string(option) + " " + text +
                     ": expected a UTC date YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS]");
  }
  std::tm date{};
  char separator = 0;
  int used = -1;
  const auto whole = [&](int fields, int expected) {
    return fields == expected && used == static_cast<int>(text.size());
  };
  const char* c = text.c_str();
  const bool date_only =
      whole(std::sscanf(c, "%4d-%2d-%2d%n", &date.tm_year, &date.tm_mon, &date.tm_mday, &used), 3);
  bool with_time = false;
  if (!date_only) {
    used = -1;
    with_time = whole(std::sscanf(c, "%4d-%2d-%2d%c%2d:%2d%n", &date.tm_year, &date.tm_mon,
                                  &date.tm_mday, &separator, &date.tm_hour, &date.tm_min, &used),
                      6);
  }
  if (!date_only && !with_time) {
    used = -1;
    with_time = whole(
        std::sscanf(c, "%4d-%2d-%2d%c%2d:%2d:%2d%n", &date.tm_year, &date.tm_mon, &date.tm_mday,
                    &separator, &date.tm_hour, &date.tm_min, &date.tm_sec, &used),
        7);
  }
  with_time = with_time && (separator == 'T' || separator == ' ');
  if ((!date_only && !with_time) || date.tm_mon < 1 || date.tm_mon > 12 || date.tm_mday < 1 ||
      date.tm_mday > 31 || date.tm_hour < 0 || date.tm_hour > 23 || date.tm_min < 0 ||
      date.tm_min > 59 || date.tm_sec < 0 || date.tm_sec > 59) {
    throw UsageError(std::string(option) + " " + text +
                     ": expected a UTC date YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS]");
  }
  date.tm_year -= 1900;
  date.tm_mon -= 1;
  const std::tm asked = date;
  const double seconds = static_cast<double>(timegm(&date));
  // timegm carries 2026-02-30 into March: a day the month does not have is a typo, not a date.
  if (date.tm_mday != asked.tm_mday || date.tm_mon != asked.tm_mon) {
    throw UsageError(std::string(option) + " " + text + ": the month has no such day");
  }
  return seconds;
}

}  // namespace littermap
