#include "core/object_classes.hpp"

#include <algorithm>

namespace littermap {

const std::vector<std::string>& LitterClasses() {
  static const std::vector<std::string> classes = {
      "can", "bottle", "cup", "carton", "food_container", "plastic_bag", "other"};
  return classes;
}

const std::vector<std::string>& NaturalClasses() {
  static const std::vector<std::string> classes = {"flower_red",    "flower_yellow", "flower_white",
                                                   "flower_purple", "leaf",          "stone",
                                                   "pine_cone",     "branch",        "mushroom"};
  return classes;
}

bool IsLitterClass(std::string_view class_name) {
  const auto& litter = LitterClasses();
  return std::find(litter.begin(), litter.end(), class_name) != litter.end();
}

bool IsNaturalClass(std::string_view class_name) {
  const auto& natural = NaturalClasses();
  return class_name == "natural" ||
         std::find(natural.begin(), natural.end(), class_name) != natural.end();
}

}  // namespace littermap
