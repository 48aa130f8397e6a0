// Map sharpness of trajectory files over a bag of the known room: the true poses draw the
// thinnest walls, a trajectory that leaves scans undrawn is warned of as it is measured, and a
// trajectory of another time is bad input naming its file.

#include "reconstruct/trajectory_map_sharpness.hpp"

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "reconstruct/room_bag.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reconstruct {
namespace {

TEST(TrajectoryMaps, ComparesTrajectoriesOfTheBag) {
  test::TempDir dir;
  const test::RoomScans run = test::RoomRun();
  test::WriteRoomBag(dir / "bag", run);
  bag::WriteTumTrajectory(dir / "truth.tum", run.truth);
  bag::WriteTumTrajectory(dir / "noisy.tum", test::Perturbed(run.truth, 0.02, 0.5 * test::kDeg));
  const std::vector<StampedPose> half(run.truth.begin(), run.truth.begin() + 50);
  bag::WriteTumTrajectory(dir / "half.tum", half);

  const std::vector<std::string> files = {(dir / "truth.tum").string(), (dir / "half.tum").string(),
                                          (dir / "noisy.tum").string()};
  std::vector<std::string> events;
  const auto maps = MeasureTrajectoryMaps(
      dir / "bag", files, {}, [&](const Progress& p) { events.push_back(std::string(p.task)); },
      [&](const std::string& warning) { events.push_back("warning: " + warning); });
  ASSERT_EQ(maps.size(), 3u);
  // As eval's map sharpness test measures the room: 800 cells for the true poses.
  EXPECT_EQ(maps[0].occupied_cells, 800u);
  EXPECT_EQ(maps[1].scans_drawn, 50u);
  EXPECT_GT(maps[2].occupied_cells, maps[0].occupied_cells);
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0], "reading the scans of " + (dir / "bag").string());
  EXPECT_EQ(events[1], "drawing the scans with " + files[0]);
  EXPECT_EQ(events[2], "drawing the scans with " + files[1]);
  EXPECT_EQ(events[3], "warning: " + files[1] +
                           ": 50 of 100 scans have no pose within 0.02 s and are not drawn; "
                           "counts of trajectories that draw different scans do not compare");
  EXPECT_EQ(events[4], "drawing the scans with " + files[2]);
}

TEST(TrajectoryMaps, RefusesWhatCannotBeMeasured) {
  test::TempDir dir;
  test::WriteRoomBag(dir / "bag", test::RoomRun());
  std::ofstream(dir / "other.tum") << "50.0 0 0 0 0 0 0 1\n51.0 1 0 0 0 0 0 1\n";
  const std::string other = (dir / "other.tum").string();
  test::ExpectBadInput([&] { MeasureTrajectoryMaps(dir / "bag", {other}, {}); },
                       other + ": map sharpness: no scan has a trajectory pose");
  TrajectoryMapsOptions options;
  options.map.cell_size_m = 0;
  EXPECT_THROW(MeasureTrajectoryMaps(dir / "bag", {other}, options), UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct
