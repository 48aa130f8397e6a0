// `littermap eval map` on a real log (the Intel lab, CARMEN): the map littermap's trajectory
// draws from the scans is sharper than the one the log's own corrected poses draw, and far
// sharper than the noisy odometry's; and the command's refusals.

#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "support/carmen_import.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using testing::Quote;
using testing::RunLittermap;

TEST(EvalMapCli, LittermapDrawsTheIntelLabSharperThanItsReference) {
  testing::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(testing::ImportCarmen("intel", 1, dir.path()));
  const auto run =
      RunLittermap("-q reconstruct " + Quote(dir / "bag") + " -o " + Quote(dir / "run"));
  ASSERT_EQ(run.exit_code, 0) << run.output;

  const auto eval = RunLittermap(
      "-q eval map " + Quote(dir / "bag") + " " + Quote(dir / "run" / "trajectory.tum") + " " +
      Quote(dir / "ref.tum") + " " + Quote(dir / "run" / "odometry.tum") + " --json");
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const auto json = nlohmann::json::parse(eval.output);
  ASSERT_EQ(json["trajectories"].size(), 3u);
  for (const auto& row : json["trajectories"]) {
    EXPECT_EQ(row["scans"], 910);
    EXPECT_EQ(row["scans_drawn"], 910);
  }
  const double littermap = json["trajectories"][0]["occupied_cells"].get<double>();
  const double reference = json["trajectories"][1]["occupied_cells"].get<double>();
  const double odometry = json["trajectories"][2]["occupied_cells"].get<double>();
  // Measured: 21,917 / 26,436 / 72,806 cells of 5 cm (ratios 0.83 and 2.75 to the reference).
  EXPECT_LT(littermap, 0.95 * reference);
  EXPECT_GT(odometry, 2 * reference);

  // The table names every trajectory and compares it with the first.
  const auto table =
      RunLittermap("-q eval map " + Quote(dir / "bag") + " " +
                   Quote(dir / "run" / "trajectory.tum") + " " + Quote(dir / "ref.tum"));
  ASSERT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("100.0%"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("ref.tum"), std::string::npos) << table.output;

  // A trajectory of another time places no scan: bad input, named.
  std::ofstream(dir / "other.tum") << "5.0 0 0 0 0 0 0 1\n6.0 1 0 0 0 0 0 1\n";
  const auto other =
      RunLittermap("-q eval map " + Quote(dir / "bag") + " " + Quote(dir / "other.tum"));
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find("other.tum"), std::string::npos) << other.output;
  // A bag without the scan topic: bad input naming the topic.
  const auto topic = RunLittermap("-q eval map " + Quote(dir / "bag") + " " +
                                  Quote(dir / "ref.tum") + " --scan-topic /front_scan");
  EXPECT_EQ(topic.exit_code, 2) << topic.output;
  EXPECT_NE(topic.output.find("/front_scan"), std::string::npos) << topic.output;
  // Options out of range are usage errors.
  EXPECT_EQ(RunLittermap("-q eval map " + Quote(dir / "bag") + " " + Quote(dir / "ref.tum") +
                         " --cell-size 0")
                .exit_code,
            1);
}

}  // namespace
}  // namespace littermap
