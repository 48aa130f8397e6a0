// A bag's scans and laser extrinsic read for the scan-based trajectory checks: the extrinsic's
// warning comes before the reading is announced, and a missing topic is named.

#include "reconstruct/bag_scans.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "reconstruct/room_bag.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reconstruct {
namespace {

TEST(BagScans, ReadsTheScansAndTheExtrinsic) {
  test::TempDir dir;
  test::WriteRoomBag(dir / "bag", test::RoomRun());
  std::vector<std::string> events;
  const BagScans read = ReadBagScans(
      dir / "bag", "/scan", [&](const Progress& p) { events.push_back(std::string(p.task)); },
      [&](const std::string& warning) { events.push_back("warning: " + warning); });
  ASSERT_EQ(read.scans.size(), 100u);
  EXPECT_EQ(read.scans[1].stamp_ns, 1'100'000'000);
  EXPECT_EQ(read.scans[0].ranges_m.size(), 360u);
  EXPECT_NEAR(read.T_base_laser.x_m, test::kBaseLaser.x_m, 1e-9);
  EXPECT_NEAR(read.T_base_laser.y_m, test::kBaseLaser.y_m, 1e-9);
  EXPECT_NEAR(read.T_base_laser.theta_rad, test::kBaseLaser.theta_rad, 1e-9);
  EXPECT_EQ(events, std::vector<std::string>{"reading the scans of " + (dir / "bag").string()});
}

TEST(BagScans, WarnsOfAMissingExtrinsicFirst) {
  test::TempDir dir;
  test::WriteRoomBag(dir / "bag", test::RoomRun(), false);
  std::vector<std::string> events;
  const BagScans read = ReadBagScans(
      dir / "bag", "/scan", [&](const Progress& p) { events.push_back(std::string(p.task)); },
      [&](const std::string& warning) { events.push_back("warning: " + warning); });
  EXPECT_EQ(read.T_base_laser.x_m, 0);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_NE(events[0].find("warning: "), std::string::npos);
  EXPECT_NE(events[0].find("assuming the laser sits at base_link"), std::string::npos);
  EXPECT_EQ(events[1], "reading the scans of " + (dir / "bag").string());
  // Without callbacks, nothing is told.
  EXPECT_EQ(ReadBagScans(dir / "bag", "/scan").scans.size(), 100u);
}

TEST(BagScans, NamesAMissingTopic) {
  test::TempDir dir;
  test::WriteRoomBag(dir / "bag", test::RoomRun());
  test::ExpectBadInput([&] { ReadBagScans(dir / "bag", "/front_scan"); }, "/front_scan");
}

}  // namespace
}  // namespace littermap::reconstruct
