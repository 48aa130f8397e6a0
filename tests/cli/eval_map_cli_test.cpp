// `littermap eval map` on a real log (the Intel lab, CARMEN): the table and JSON of several
// trajectories of its scans, a shaken copy of the corrected poses drawing a blurrier map than
// the poses themselves, and the command's refusals. (That littermap's own trajectory draws the
// lab sharper than the reference is asserted in reconstruct's data tier, which reconstructs the
// log anyway.)

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <vector>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "support/carmen_import.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunLittermap;

TEST(EvalMapCli, AShakenTrajectoryDrawsTheIntelLabBlurrier) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(test::ImportCarmen("intel", 1, dir.path()));
  // The reference with every other pose turned by 2 degrees and moved by 5 cm.
  std::vector<StampedPose> shaken = bag::ReadTumTrajectory(dir / "ref.tum");
  for (std::size_t i = 0; i < shaken.size(); i += 2) {
    shaken[i].position_m.x() += 0.05;
    shaken[i].orientation =
        Eigen::AngleAxisd(2 * std::numbers::pi / 180, Eigen::Vector3d::UnitZ()) *
        shaken[i].orientation;
  }
  bag::WriteTumTrajectory(dir / "shaken.tum", shaken);

  const auto eval =
      RunLittermap("-q eval map " + Quote(dir / "bag") + " " + Quote(dir / "ref.tum") + " " +
                   Quote(dir / "shaken.tum") + " --json");
  ASSERT_EQ(eval.exit_code, 0) << eval.output;
  const auto json = nlohmann::json::parse(eval.output);
  ASSERT_EQ(json["trajectories"].size(), 2u);
  for (const auto& row : json["trajectories"]) {
    EXPECT_EQ(row["scans"], 910);
    EXPECT_EQ(row["scans_drawn"], 910);
  }
  const double reference = json["trajectories"][0]["occupied_cells"].get<double>();
  const double shaken_cells = json["trajectories"][1]["occupied_cells"].get<double>();
  EXPECT_GT(shaken_cells, 1.2 * reference);  // measured 38,809 against 26,436 cells (1.47)

  // The table names every trajectory and compares it with the first.
  const auto table = RunLittermap("-q eval map " + Quote(dir / "bag") + " " +
                                  Quote(dir / "shaken.tum") + " " + Quote(dir / "ref.tum"));
  ASSERT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("100.0%"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("shaken.tum"), std::string::npos) << table.output;
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
