// Segmentation IoU over a run: its reports, and the truth it refuses before reading the bag.
// (Scoring the frames themselves: segmentation_score.hpp; the whole command on a simulated run:
// tests/cli/detect_cli_test.cpp.)

#include "detect/segmentation_evaluation.hpp"

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::detect {
namespace {

using test::ExpectBadInput;

TEST(SegmentationEvaluation, ReportsPerClass) {
  SegmentationEvaluation evaluation;
  evaluation.classes["all"] = {11, 0.4861, 0.5454};
  evaluation.classes["can"] = {2, 0.93, 1.0};
  EXPECT_EQ(ToText(evaluation),
            "class             objects  mean IoU    IoU >= 0.5\n"
            "all                    11     0.486         0.545\n"
            "can                     2     0.930         1.000");
  EXPECT_EQ(ToJson(evaluation),
            "{\n  \"all\": {\n    \"objects\": 11,\n    \"mean_iou\": 0.4861,\n"
            "    \"found_share\": 0.5454\n  },\n  \"can\": {\n    \"objects\": 2,\n"
            "    \"mean_iou\": 0.93,\n    \"found_share\": 1.0\n  }\n}");
  // No object scored: the header alone, JSON null.
  EXPECT_EQ(ToText({}), "class             objects  mean IoU    IoU >= 0.5");
  EXPECT_EQ(ToJson({}), "null");
}

void WriteTruth(const std::filesystem::path& dir, const std::string& litter_id,
                const std::string& index) {
  std::filesystem::create_directories(dir / "masks");
  std::ofstream(dir / "litter.csv") << "id,class,x,y\n" << litter_id << ",can,1,0\n";
  std::ofstream(dir / "natural.csv") << "id,class,x,y\n";
  std::ofstream(dir / "masks" / "index.csv") << "frame,stamp_ns,file\n" << index;
}

TEST(SegmentationEvaluation, RefusesTruthItCannotUse) {
  test::TempDir dir;
  WriteTruth(dir / "a", "x7", "0,1,masks/frame_000000.png\n10,2,masks/frame_000010.png\n");
  ExpectBadInput([&] { EvaluateSegmentation(dir / "no_bag", dir / "a", {}); },
                 (dir / "a").string() + ": object id 'x7' is not an integer");
  WriteTruth(dir / "b", "7", "0,1,masks/frame_000000.png\n");
  ExpectBadInput([&] { EvaluateSegmentation(dir / "no_bag", dir / "b", {}); },
                 "index.csv: fewer than two masks");
  WriteTruth(dir / "c", "7", "0,1,masks/frame_000000.png\n10,2,masks/frame_000010.png\n");
  ExpectBadInput([&] { EvaluateSegmentation(dir / "no_bag", dir / "c", {}); }, "no_bag");
}

}  // namespace
}  // namespace littermap::detect
