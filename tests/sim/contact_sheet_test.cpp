// Contact sheets of run bags: a bag without camera frames is bad input naming the bag and topic;
// a simulated bag gives one row of colour | depth | laser panels per sampled frame.

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "bag/bag_writer.hpp"
#include "bag/contact_sheet.hpp"
#include "core/error.hpp"
#include "sim/recorder.hpp"
#include "sim/world_spec.hpp"
#include "support/temp_dir.hpp"

namespace littermap::sim {
namespace {

TEST(ContactSheet, BagWithoutColourFramesIsBadInput) {
  test::TempDir dir;
  {
    bag::BagWriter writer(dir / "bag");
    writer.AddTopic<msg::LaserScan>("/scan");
    writer.WriteMessage("/scan", 1, msg::LaserScan{});
    writer.Close();
  }
  try {
    bag::WriteContactSheet(dir / "bag", dir / "sheet.png");
    FAIL() << "no error";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("no colour frames on /camera/color/image_raw/compressed"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "sheet.png"));
}

TEST(ContactSheet, RowsOfColourDepthAndLaser) {
  test::TempDir dir;
  SimRecordOptions options;
  options.max_duration_s = 0.5;  // 5 frames
  RecordSimulation(LoadWorldSpec(std::filesystem::path(LITTERMAP_SOURCE_DIR) / "samples" /
                                 "worlds" / "park_small.yaml"),
                   dir / "bag", {}, options);
  bag::ContactSheetOptions sheet_options;
  sheet_options.rows = 3;
  const bag::ContactSheetResult result =
      bag::WriteContactSheet(dir / "bag", dir / "sheet.png", sheet_options);
  EXPECT_EQ(result.rows, 3);
  const cv::Mat sheet = cv::imread((dir / "sheet.png").string());
  ASSERT_EQ(sheet.cols, 3 * 320);
  ASSERT_EQ(sheet.rows, 3 * 240);
  // The laser panel's background is dark grey; the colour panel is a lit park, not black.
  EXPECT_GT(cv::mean(sheet(cv::Rect(0, 0, 320, 240)))[1], 40);
  EXPECT_LT(cv::mean(sheet(cv::Rect(640, 0, 320, 240)))[1], 60);
}

}  // namespace
}  // namespace littermap::sim
