// `littermap ingest` places later runs on the site map: two reconstructions of the real orebro
// log (different odometry noise) are registered onto each other from a wrong start guess, where
// their trajectories fit; a start too far off is refused with exit code 2; --transform places a
// run by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "bag/tum_trajectory.hpp"
#include "core/sqlite_database.hpp"
#include "eval/trajectory_metrics.hpp"
#include "support/carmen_import.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::RunLittermap;

using test::kDatasets;

using test::Quote;

// orebro imported with odometry noise `seed` and reconstructed into dir/run<seed>, with one
// item at (1, 2) in the run's frame.
std::filesystem::path ReconstructedRun(const std::filesystem::path& dir, int seed) {
  const auto imported = dir / ("import" + std::to_string(seed));
  const auto run = dir / ("run" + std::to_string(seed));
  std::filesystem::create_directories(imported);
  EXPECT_NO_FATAL_FAILURE(test::ImportCarmen("orebro", seed, imported));
  EXPECT_EQ(
      RunLittermap("-q reconstruct " + Quote(imported / "bag") + " -o " + Quote(run)).exit_code, 0);
  std::ofstream(run / "items.csv") << "id,class,x,y,z,size_m\n1,can,1,2,0,0.1\n";
  return run;
}

// The rigid transform that fits run `from`'s trajectory onto run `onto`'s (the ATE alignment).
Eigen::Isometry3d TrajectoryFit(const std::filesystem::path& from,
                                const std::filesystem::path& onto) {
  const auto read = [](const std::filesystem::path& run) {
    return bag::ReadTumTrajectory(run / "trajectory.tum");
  };
  return eval::EvaluateTrajectory(read(from), read(onto), {}).T_reference_estimate;
}

// x, y, yaw and registration quality (-1: none) of a run in the site database.
std::vector<double> Placement(const std::filesystem::path& site, int run_id) {
  SqliteDatabase database(site, SqliteDatabase::Mode::kReadOnly);
  SqliteStatement query = database.Prepare(
      "SELECT site_from_run_x_m, site_from_run_y_m, site_from_run_yaw_rad, "
      "coalesce(registration_quality, -1) FROM runs WHERE run_id = ?");
  query.Bind(1, std::int64_t{run_id});
  if (!query.Step()) return {};
  return {query.ColumnDouble(0), query.ColumnDouble(1), query.ColumnDouble(2),
          query.ColumnDouble(3)};
}

TEST(IngestRegistrationCli, LaterRunsAreMatchedOntoTheSiteMap) {
  ASSERT_TRUE(std::filesystem::exists(kDatasets / "carmen" / "orebro-corrected.log.gz"));
  test::TempDir dir;
  const auto first = ReconstructedRun(dir.path(), 1);
  const auto second = ReconstructedRun(dir.path(), 2);
  const auto site = dir / "site.gpkg";
  ASSERT_EQ(RunLittermap("site init " + Quote(site) + " --name orebro").exit_code, 0);

  const auto defining = RunLittermap("ingest " + Quote(site) + " " + Quote(first));
  ASSERT_EQ(defining.exit_code, 0) << defining.output;
  EXPECT_NE(defining.output.find("becomes the site map"), std::string::npos) << defining.output;

  // Too far from where the run starts for the search window: refused, nothing stored.
  const auto far =
      RunLittermap("ingest " + Quote(site) + " " + Quote(second) + " --initial 12 -9 70");
  EXPECT_EQ(far.exit_code, 2) << far.output;
  EXPECT_NE(far.output.find("does not match the site map"), std::string::npos) << far.output;
  EXPECT_NE(far.output.find("map.yaml"), std::string::npos) << far.output;
  EXPECT_TRUE(Placement(site, 2).empty());

  // Both reconstructions start at the log's first pose, but the two SLAM runs bend the building
  // a little differently: the placement that fits the second map onto the first best is the one
  // that fits its trajectory onto the first's (about 0.1 m and 1 degree from the identity). The
  // search starts 1.5 m and 8 deg off.
  const auto matched =
      RunLittermap("ingest " + Quote(site) + " " + Quote(second) + " --initial 1.2 -0.9 8");
  ASSERT_EQ(matched.exit_code, 0) << matched.output;
  const std::vector<double> placed = Placement(site, 2);
  ASSERT_EQ(placed.size(), 4u);
  const Eigen::Isometry3d T_first_second = TrajectoryFit(second, first);
  const Eigen::Vector3d x_axis = T_first_second.rotation() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(placed[0], T_first_second.translation().x(), 0.05);
  EXPECT_NEAR(placed[1], T_first_second.translation().y(), 0.05);
  EXPECT_NEAR(placed[2], std::atan2(x_axis.y(), x_axis.x()), 0.3 * M_PI / 180);
  EXPECT_GE(placed[3], 0.5);  // the matching ratio is stored

  // By hand: stored as given, with no matching ratio. Other results of the same folder take
  // another name (the site refuses two different runs both called run2).
  std::ofstream(second / "items.csv", std::ios::app) << "2,cup,3,3,0,0.1\n";
  const auto by_hand = RunLittermap("ingest " + Quote(site) + " " + Quote(second) +
                                    " --transform 100 50 90 --name 'run2 by hand'");
  ASSERT_EQ(by_hand.exit_code, 0) << by_hand.output;
  const std::vector<double> manual = Placement(site, 3);
  ASSERT_EQ(manual.size(), 4u);
  EXPECT_DOUBLE_EQ(manual[0], 100);
  EXPECT_DOUBLE_EQ(manual[1], 50);
  EXPECT_NEAR(manual[2], M_PI / 2, 1e-12);
  EXPECT_EQ(manual[3], -1);
}

}  // namespace
}  // namespace littermap
