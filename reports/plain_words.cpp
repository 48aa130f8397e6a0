#include "reports/plain_words.hpp"

#include <cmath>

#include "reports/class_palette.hpp"
#include "reports/html_text.hpp"

namespace littermap::reports {

std::string CountOf(std::size_t n, std::string_view one, std::string_view many) {
  return FormatNumber(static_cast<double>(n), 0) + " " + std::string(n == 1 ? one : many);
}

std::string ClassCount(std::string_view class_name, std::size_t n) {
  const ClassStyle style = StyleOf(class_name);
  return CountOf(n, style.one, style.many);
}

std::string FromTheDock(double x_m, double y_m, int decimals) {
  const double unit = std::pow(10.0, -decimals);
  const auto part = [&](double value, const char* positive, const char* negative) {
    if (std::abs(value) < unit / 2) return std::string();
    return FormatNumber(std::abs(value), decimals) + " m " + (value > 0 ? positive : negative);
  };
  const std::string east_west = part(x_m, "east", "west");
  const std::string north_south = part(y_m, "north", "south");
  if (east_west.empty() && north_south.empty()) return "at the dock";
  if (east_west.empty()) return north_south + " of the dock";
  if (north_south.empty()) return east_west + " of the dock";
  return east_west + " and " + north_south + " of the dock";
}

}  // namespace littermap::reports
