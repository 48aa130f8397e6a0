#include "reports/class_palette.hpp"

#include <array>

namespace littermap::reports {
namespace {

struct Entry {
  std::string_view name;
  std::string_view label;
  std::string_view one;
  std::string_view many;
  int r, g, b;
};

constexpr std::array<Entry, 7> kLitter = {{
    {"bottle", "Bottles", "bottle", "bottles", 0, 114, 178},
    {"can", "Cans", "can", "cans", 230, 159, 0},
    {"cup", "Cups", "cup", "cups", 86, 180, 233},
    {"carton", "Cartons", "carton", "cartons", 213, 94, 0},
    {"food_container", "Food containers", "food container", "food containers", 0, 158, 115},
    {"plastic_bag", "Plastic bags", "plastic bag", "plastic bags", 204, 121, 167},
    {"other", "Other litter", "other item", "other items", 240, 228, 66},
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
    if (e.name == class_name) {
      return {std::string(e.label), std::string(e.one), std::string(e.many),
              cv::Scalar(e.b, e.g, e.r), Hex(e.r, e.g, e.b)};
    }
  }
  std::string words(class_name);  // a class of another model: its own name, in words
  for (char& c : words) c = c == '_' ? ' ' : c;
  return {std::string(class_name), words, words, cv::Scalar(128, 128, 128), Hex(128, 128, 128)};
}

}  // namespace littermap::reports
