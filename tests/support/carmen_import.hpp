#pragma once
// A CARMEN log of ../shared/datasets/carmen imported as the tests use it: the run bag in
// DIR/bag and the log's corrected poses in DIR/ref.tum, with the odometry noise of a seed.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace littermap::testing {

// NAME: the log's name, e.g. "intel" for intel-corrected.log.gz. A missing data set or a
// failing import is a fatal failure (call it inside ASSERT_NO_FATAL_FAILURE).
inline void ImportCarmen(const std::string& name, int odometry_noise_seed,
                         const std::filesystem::path& dir) {
  const auto log =
      std::filesystem::path(LITTERMAP_DATASETS_DIR) / "carmen" / (name + "-corrected.log.gz");
  ASSERT_TRUE(std::filesystem::exists(log)) << "missing data set " << log;
  const CommandResult result = RunLittermap(
      "-q import carmen " + Quote(log) + " -o " + Quote(dir / "bag") + " --reference " +
      Quote(dir / "ref.tum") + " --odometry-noise " + std::to_string(odometry_noise_seed));
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

}  // namespace littermap::testing
