// littermap site init: creates a GeoPackage site database; refuses what it cannot do with exit 1.

#include <gtest/gtest.h>

#include <fstream>

#include "core/sqlite_database.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::RunLittermap;
using test::TempDir;

std::int64_t Integer(const std::filesystem::path& file, const std::string& sql) {
  SqliteDatabase database(file, SqliteDatabase::Mode::kReadOnly);
  SqliteStatement query = database.Prepare(sql);
  return query.Step() ? query.ColumnInt64(0) : -1;
}

TEST(SiteCli, InitCreatesALocalSiteGeoPackage) {
  TempDir dir;
  const auto site = dir / "park.gpkg";
  const auto result = RunLittermap("site init " + site.string() + " --name 'North park'");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("local frame"), std::string::npos) << result.output;
  EXPECT_EQ(Integer(site, "PRAGMA application_id"), 0x47504B47);
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM gpkg_contents WHERE data_type = 'features'"), 3);

  const auto again = RunLittermap("site init " + site.string() + " --name other");
  EXPECT_EQ(again.exit_code, 1) << again.output;
  EXPECT_NE(again.output.find("already exists"), std::string::npos) << again.output;
}

TEST(SiteCli, InitPlacesTheSiteInAnEpsgCrs) {
  TempDir dir;
  const auto site = dir / "utm.gpkg";
  const auto result = RunLittermap("site init " + site.string() +
                                   " --name Madison --crs EPSG:32616 --origin 305000 4770000 "
                                   "--rotation 12.5");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("EPSG:32616"), std::string::npos) << result.output;
  EXPECT_EQ(Integer(site,
                    "SELECT srs_id FROM gpkg_geometry_columns WHERE "
                    "table_name = 'litter_items'"),
            32616);
}

TEST(SiteCli, InitRefusesBadCrsArguments) {
  TempDir dir;
  const std::string site = (dir / "bad.gpkg").string();
  EXPECT_EQ(RunLittermap("site init " + site + " --name a --crs EPSG:4326").exit_code, 1);
  EXPECT_EQ(RunLittermap("site init " + site + " --name a --crs nonsense").exit_code, 1);
  EXPECT_EQ(RunLittermap("site init " + site + " --name a --origin 1 2").exit_code, 1);
  EXPECT_EQ(RunLittermap("site init " + site).exit_code, 1);  // --name is required
  EXPECT_FALSE(std::filesystem::exists(site));
}

TEST(SiteCli, InitDoesNotOverwriteAnExistingFile) {
  TempDir dir;
  const auto text = dir / "notes.gpkg";
  std::ofstream(text) << "not a database";
  const auto result = RunLittermap("site init " + text.string() + " --name x");
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("notes.gpkg"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace littermap
