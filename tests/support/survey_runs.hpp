#pragma once
// A simulated survey reconstructed twice: with the defaults, and with one feature turned off, so
// a test can compare what the feature does.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.hpp"

namespace littermap::test {

// Simulates the world file text into DIR/bag and DIR/truth, then reconstructs DIR/run with the
// defaults and DIR/plain with the reconstruct options given as YAML text. Call it inside
// ASSERT_NO_FATAL_FAILURE.
inline void SimulateAndReconstructTwice(const std::filesystem::path& dir,
                                        const std::string& world_yaml,
                                        const std::string& plain_options_yaml) {
  std::ofstream(dir / "world.yaml") << world_yaml;
  auto result = RunLittermap("-q simulate " + Quote(dir / "world.yaml") + " -o " +
                             Quote(dir / "bag") + " --truth " + Quote(dir / "truth"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  result = RunLittermap("-q reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "run"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ofstream(dir / "plain.yaml") << plain_options_yaml;
  result = RunLittermap("-q reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "plain") +
                        " --options " + Quote(dir / "plain.yaml"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
}

}  // namespace littermap::test
