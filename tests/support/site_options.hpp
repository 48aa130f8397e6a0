#pragma once
// The options of a test site in one call: a name and, when georeferenced, where it lies.

#include <optional>
#include <string>

#include "db/site_database.hpp"

namespace littermap::test {

inline db::SiteOptions SiteOptionsOf(const std::string& name,
                                     std::optional<int> epsg = std::nullopt, double easting = 0,
                                     double northing = 0, double rotation_deg = 0) {
  db::SiteOptions options;
  options.name = name;
  options.epsg_code = epsg;
  options.origin_easting_m = easting;
  options.origin_northing_m = northing;
  options.rotation_deg = rotation_deg;
  return options;
}

}  // namespace littermap::test
