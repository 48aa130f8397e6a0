#pragma once
// Moves a site between engines (site export: PostGIS to a GeoPackage; site import: the other
// way), or between two places of one engine: every table of the schema description, row by row
// with the same ids, geometry re-encoded for the target, in one transaction. The target must not
// exist; when the copy fails it is removed again. Progress: "copying TABLE", rows so far.

#include <cstddef>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "db/site_locator.hpp"

namespace littermap::db {

struct SiteCopyResult {
  std::string site_name;
  struct Table {
    std::string name;
    std::size_t rows = 0;
  };
  std::vector<Table> tables;  // in copy order

  std::size_t Rows(const std::string& table) const;
};

// Throws UsageError when the target exists; BadInputError when the source is not a site.
SiteCopyResult CopySite(const SiteLocator& from, const SiteLocator& to,
                        const ProgressCallback& progress = {});

}  // namespace littermap::db
