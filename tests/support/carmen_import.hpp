#pragma once
// A CARMEN log of ../shared/datasets/carmen imported as the tests use it: the run bag in
// DIR/bag and the log's corrected poses in DIR/ref.tum, with the odometry noise of a seed.
// The importer is called as a library function, as `littermap import carmen` calls it.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "importers/carmen_importer.hpp"

namespace littermap::test {

// NAME: the log's name, e.g. "intel" for intel-corrected.log.gz. A missing data set or a
// failing import is a fatal failure (call it inside ASSERT_NO_FATAL_FAILURE).
inline void ImportCarmen(const std::string& name, int odometry_noise_seed,
                         const std::filesystem::path& dir) {
  const auto log =
      std::filesystem::path(LITTERMAP_DATASETS_DIR) / "carmen" / (name + "-corrected.log.gz");
  ASSERT_TRUE(std::filesystem::exists(log)) << "missing data set " << log;
  importers::CarmenImportOptions options;
  options.reference_path = dir / "ref.tum";
  options.odometry_noise_seed = static_cast<std::uint64_t>(odometry_noise_seed);
  try {
    importers::ImportCarmenLog(log, dir / "bag", options);
  } catch (const Error& error) {
    FAIL() << "importing " << log << ": " << error.what();
  }
}

}  // namespace littermap::test
