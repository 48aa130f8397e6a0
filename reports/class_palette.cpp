#include "reports/class_palette.hpp"

#include <array>

namespace littermap::reports {
namespace {

struct Entry {
  std::string_view name;
  std::string_view label;
  int r, g, b;
};

constexpr std::array<Entry, 7> kLitter = {{
    {"bottle", "Bottles", 0, 114, 178},
    {"can", "Cans", 230, 159, 0},
    {"cup", "Cups", 86, 180, 233},
    {"carton", "Cartons", 213, 94, 0},
    {"food_container", "Food containers", 0, 158, 115},
    {"plastic_bag", "Plastic bags", 204, 121, 167},
    {"other", "Other litter", 240, 228, 66},
}};

std::string Hex(int r, int g, int b) {
  constexpr char kDigits[] = "0123456789ABCDEF";
  std::string hex = "#";
  for (const int v : {r, g, b}) {
    hex += kDigits[v / 16];
    hex += kDigits[v % 16];
  }
  return hex;
}

}  // namespace

ClassStyle StyleOf(std::string_view class_name) {
  for (const Entry& e : kLitter) {
    if (e.name == class_name)
      return {std::string(e.label), cv::Scalar(e.b, e.g, e.r), Hex(e.r, e.g, e.b)};
  }
  return {std::string(class_name), cv::Scalar(128, 128, 128), Hex(128, 128, 128)};
}

}  // namespace littermap::reports
