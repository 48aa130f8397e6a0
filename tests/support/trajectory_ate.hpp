#pragma once
// The ATE RMSE of a trajectory against a reference, as `littermap eval trajectory --json` gives it.

#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/run_command.hpp"

namespace littermap::test {

inline double Ate(const std::filesystem::path& estimate, const std::filesystem::path& reference) {
  const CommandResult eval =
      RunLittermap("eval trajectory " + Quote(estimate) + " " + Quote(reference) + " --json");
  EXPECT_EQ(eval.exit_code, 0) << eval.output;
  return nlohmann::json::parse(eval.output).at("ate_rmse_m").get<double>();
}

}  // namespace littermap::test
