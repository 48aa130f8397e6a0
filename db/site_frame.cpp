#include "db/site_frame.hpp"

#include <cstdio>

namespace littermap::db {

std::string Describe(const SiteFrame& frame) {
  if (!frame.georeferenced()) return "local frame (not georeferenced)";
  const char* format = "EPSG:%d, origin E %.3f N %.3f, rotation %.3f deg";
  const auto print = [&](char* text, std::size_t size) {
    return std::snprintf(text, size, format, frame.epsg_code, frame.origin_easting_m,
                         frame.origin_northing_m, frame.rotation_deg);
  };
  std::string text(static_cast<std::size_t>(print(nullptr, 0)), '\0');
  print(text.data(), text.size() + 1);  // the values are as big as the user gave them
  return text;
}

}  // namespace littermap::db
