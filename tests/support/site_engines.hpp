#pragma once
// Site tests run against both engines: a GeoPackage file, and a schema on the PostgreSQL +
// PostGIS server that the postgis.start test fixture runs (scripts/postgis.sh, in the build
// folder). Files that include this header form each module's postgis tier, which requires it.

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/error.hpp"
#include "db/site_database.hpp"
#include "db/site_locator.hpp"

namespace littermap::test {

enum class SiteEngine { kGeoPackage, kPostgis };

inline std::string SiteEngineName(const ::testing::TestParamInfo<SiteEngine>& info) {
  return info.param == SiteEngine::kGeoPackage ? "GeoPackage" : "Postgis";
}

// The test server's URL (the fixture writes it next to the cluster).
inline std::string PostgisTestUrl() {
  const std::filesystem::path file = std::filesystem::path(LITTERMAP_TEST_POSTGIS_DIR) / "url";
  std::ifstream in(file);
  std::string url;
  if (!(in >> url)) {
    throw EnvironmentError(file.string() +
                           ": no test server URL; ctest starts the server in the postgis.start "
                           "fixture (scripts/postgis.sh start " LITTERMAP_TEST_POSTGIS_DIR ")");
  }
  return url;
}

// Where one test's site lives: SITE.gpkg in `dir`, or a schema of its own on the test server,
// dropped when the test ends.
class TestSite {
 public:
  TestSite(SiteEngine engine, const std::filesystem::path& dir, const std::string& stem) {
    if (engine == SiteEngine::kGeoPackage) {
      locator_ = db::SiteLocator(dir / (stem + ".gpkg"));
      return;
    }
    static std::atomic<int> counter{0};
    std::random_device random;
    const std::string schema = "t" + std::to_string(getpid()) + "_" +
                               std::to_string(random() % 100000) + "_" + std::to_string(counter++) +
                               "_" + stem;
    locator_ = db::ParseSiteLocator(PostgisTestUrl() + "?site=" + schema);
  }
  ~TestSite() {
    if (!locator_.postgres()) return;
    try {
      db::SiteDatabase::Remove(locator_);
    } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): the test reported already
    }
  }
  TestSite(const TestSite&) = delete;
  TestSite& operator=(const TestSite&) = delete;

  const db::SiteLocator& locator() const { return locator_; }
  // What a command line takes: the path, or the URL with ?site=.
  std::string argument() const {
    return locator_.postgres() ? locator_.conninfo + "?site=" + locator_.schema
                               : locator_.file.string();
  }

 private:
  db::SiteLocator locator_;
};

}  // namespace littermap::test
