// A site's CRS as people give and read it: EPSG codes parsed from text, frames described.

#include "db/site_frame.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "db/spatial_ref_sys.hpp"

namespace littermap::db {
namespace {

TEST(ParseEpsgCode, ReadsTheCodeWithOrWithoutItsAuthority) {
  EXPECT_EQ(ParseEpsgCode("EPSG:32633", "--crs"), 32633);
  EXPECT_EQ(ParseEpsgCode("epsg:32633", "--crs"), 32633);
  EXPECT_EQ(ParseEpsgCode("32633", "--crs"), 32633);
  EXPECT_EQ(ParseEpsgCode("", "--crs"), std::nullopt);
}

TEST(ParseEpsgCode, NamesTheOptionForOtherText) {
  for (const char* text : {"nonsense", "EPSG:", "EPSG:32a", "EPSG:1234567890", "-5"}) {
    try {
      ParseEpsgCode(text, "--crs");
      ADD_FAILURE() << text;
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()),
                "--crs " + std::string(text) + ": expected EPSG:N, e.g. EPSG:32633");
    }
  }
}

TEST(SiteFrame, DescribesItsPlacement) {
  SiteFrame local;
  EXPECT_EQ(Describe(local), "local frame (not georeferenced)");
  SiteFrame utm;
  utm.epsg_code = 32616;
  utm.origin_easting_m = 305000;
  utm.origin_northing_m = 4770000;
  utm.rotation_deg = 12.5;
  EXPECT_EQ(Describe(utm), "EPSG:32616, origin E 305000.000 N 4770000.000, rotation 12.500 deg");
  utm.origin_easting_m = 1e300;  // as big as the user gave it, never cut short
  const std::string huge = Describe(utm);
  EXPECT_GT(huge.size(), 300u);
  EXPECT_EQ(huge.substr(huge.size() - 39), ".000 N 4770000.000, rotation 12.500 deg");
}

}  // namespace
}  // namespace littermap::db
