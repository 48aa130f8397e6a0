#include "core/utc_date.hpp"

#include <ctime>
#include <regex>

#include "core/error.hpp"

namespace littermap {

std::optional<double> ParseUtcDate(const std::string& text, const char* option) {
  if (text.empty()) return std::nullopt;
  static const std::regex kLayout(
      R"((\d{4})-(\d{2})-(\d{2})(?:[T ](\d{2}):(\d{2})(?::(\d{2}))?)?)");
  std::smatch field;
  std::tm date{};
  const auto number = [&](std::size_t i) { return field[i].matched ? std::stoi(field[i]) : 0; };
  if (std::regex_match(text, field, kLayout)) {
    date.tm_year = number(1);
    date.tm_mon = number(2);
    date.tm_mday = number(3);
    date.tm_hour = number(4);
    date.tm_min = number(5);
    date.tm_sec = number(6);
  }
  if (field.empty() || date.tm_mon < 1 || date.tm_mon > 12 || date.tm_mday < 1 ||
      date.tm_mday > 31 || date.tm_hour > 23 || date.tm_min > 59 || date.tm_sec > 59) {
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
