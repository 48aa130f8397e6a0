#include "run/quality_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "support/temp_dir.hpp"

namespace littermap::run {
namespace {

using littermap::test::TempDir;

// A laser run's quality.json as reconstruct wrote it (the Intel lab log): loop closures, the
// final scan alignment and a warning.
constexpr const char* kSlamText = R"json({
  "scans": 910,
  "scans_tracked": 910,
  "scans_without_echoes": 0,
  "ground_echoes_dropped": 0,
  "scans_moving_echo_filtered": 0,
  "moving_echoes_dropped": 0,
  "scans_given_up_to_moving_echoes": 0,
  "stamps_backwards": 0,
  "stamps_duplicate": 0,
  "odometry_missing": 0,
  "odometry_rejected": 0,
  "odometry_arbitrated_by_laser": 0,
  "routines": {
    "global": 907,
    "buffer": 1,
    "rgbd": 0,
    "odometry-only": 2
  },
  "key_frames": 895,
  "loop_closures_found": 441,
  "loop_closures_accepted": 181,
  "loop_closures_rejected": 260,
  "loop_closures_rejected_match": 252,
  "loop_closures_rejected_disagreement": 3,
  "loop_closures_rejected_degenerate": 2,
  "loop_closures_rejected_after_optimisation": 3,
  "loop_closures_rejected_inconsistent": 0,
  "loop_closures_confirmed": 1,
  "landmarks": {
    "in_graph": 38,
    "sightings": 199,
    "associated_by_tracking": 71,
    "loops_found": 0,
    "loops_accepted": 0,
    "loops_rejected": 0
  },
  "optimisations": 187,
  "final_cost": 52.88249472644489,
  "scan_alignment": {
    "pairs": 5989,
    "pairs_matched": 3667,
    "correspondences": 156162,
    "rounds": 4,
    "initial_cost": 45296.482669532525,
    "final_cost": 21272.63493199213
  },
  "scan_refinement": {
    "pairs": 40,
    "pairs_matched": 38,
    "correspondences": 1520,
    "rounds": 4,
    "initial_cost": 812.5,
    "final_cost": 640.25
  },
  "run_time_s": 2.356362464,
  "scans_per_s": 386.1884637456184,
  "warnings": [
    "intel-1: no topic /camera/color/image_raw/compressed; tracking with the laser alone (no RGB-D routine)"
  ]
}
)json";

// A simulated run with a camera: the RGB-D routine's counts, no scan alignment, no warnings.
constexpr const char* kRgbdText = R"json({
  "scans": 201,
  "scans_tracked": 201,
  "scans_without_echoes": 0,
  "ground_echoes_dropped": 0,
  "scans_moving_echo_filtered": 0,
  "moving_echoes_dropped": 0,
  "scans_given_up_to_moving_echoes": 0,
  "stamps_backwards": 0,
  "stamps_duplicate": 0,
  "odometry_missing": 0,
  "odometry_rejected": 0,
  "odometry_arbitrated_by_laser": 0,
  "routines": {
    "global": 201,
    "buffer": 0,
    "rgbd": 0,
    "odometry-only": 0
  },
  "key_frames": 22,
  "loop_closures_found": 0,
  "loop_closures_accepted": 0,
  "loop_closures_rejected": 0,
  "loop_closures_rejected_match": 0,
  "loop_closures_rejected_disagreement": 0,
  "loop_closures_rejected_degenerate": 0,
  "loop_closures_rejected_after_optimisation": 0,
  "loop_closures_rejected_inconsistent": 0,
  "loop_closures_confirmed": 0,
  "landmarks": {
    "in_graph": 4,
    "sightings": 22,
    "associated_by_tracking": 18,
    "loops_found": 0,
    "loops_accepted": 0,
    "loops_rejected": 0
  },
  "optimisations": 0,
  "final_cost": 0.0,
  "rgbd": {
    "frames": 200,
    "key_frames": 65,
    "alignments": 3,
    "aligned": 2,
    "loop_alignments": 1,
    "loops_found": 1,
    "loops_accepted": 1,
    "loops_rejected": 0
  },
  "run_time_s": 1.112439542,
  "scans_per_s": 180.68397644211032,
  "warnings": []
}
)json";

constexpr const char* kVisualText = R"json({
  "mode": "visual-odometry",
  "frames": 120,
  "frames_tracked": 118,
  "key_frames": 14,
  "segments": 2,
  "run_time_s": 3.5,
  "frames_per_s": 34.25,
  "warnings": [
    "tracking was lost 1 times; each new segment starts at the last pose known"
  ]
}
)json";

TEST(QualityFile, ReadsEveryFieldOfASlamRun) {
  const std::optional<ReconstructionQuality> q = QualityFromJson(kSlamText);
  ASSERT_TRUE(q.has_value());
  EXPECT_FALSE(q->visual_odometry);
  EXPECT_EQ(q->scans, 910u);
  ASSERT_EQ(q->routines.size(), 4u);
  EXPECT_EQ(q->routines[0], (std::pair<std::string, std::size_t>("global", 907)));
  EXPECT_EQ(q->routines[3], (std::pair<std::string, std::size_t>("odometry-only", 2)));
  EXPECT_EQ(q->loop_closures_rejected, 260u);
  EXPECT_EQ(q->loop_closures_rejected_degenerate, 2u);
  EXPECT_EQ(q->loop_closures_rejected_after_optimisation, 3u);
  EXPECT_EQ(q->loop_closures_confirmed, 1u);
  EXPECT_EQ(q->landmarks.associated_by_tracking, 71u);
  EXPECT_DOUBLE_EQ(q->final_cost, 52.88249472644489);
  ASSERT_TRUE(q->scan_alignment.has_value());
  EXPECT_EQ(q->scan_alignment->rounds, 4);
  EXPECT_DOUBLE_EQ(q->scan_alignment->initial_cost, 45296.482669532525);
  ASSERT_TRUE(q->scan_refinement.has_value());
  EXPECT_EQ(q->scan_refinement->pairs_matched, 38u);
  EXPECT_DOUBLE_EQ(q->scan_refinement->final_cost, 640.25);
  EXPECT_FALSE(q->rgbd.has_value());
  EXPECT_DOUBLE_EQ(q->scans_per_s, 386.1884637456184);
  ASSERT_EQ(q->warnings.size(), 1u);
  EXPECT_EQ(q->warnings[0].rfind("intel-1: no topic", 0), 0u);
}

TEST(QualityFile, WritesBackTheBytesItRead) {
  for (const char* text : {kSlamText, kRgbdText, kVisualText}) {
    const std::optional<ReconstructionQuality> quality = QualityFromJson(text);
    ASSERT_TRUE(quality.has_value()) << text;
    EXPECT_EQ(ToJson(*quality), text);
  }
}

TEST(QualityFile, WritesAVisualOdometryRunInItsOwnKeys) {
  ReconstructionQuality q;
  q.visual_odometry = true;
  q.frames = 120;
  q.frames_tracked = 118;
  q.key_frames = 14;
  q.segments = 2;
  q.run_time_s = 3.5;
  q.scans_per_s = 34.25;
  q.warnings = {"tracking was lost 1 times; each new segment starts at the last pose known"};
  EXPECT_EQ(ToJson(q), kVisualText);
  const std::optional<ReconstructionQuality> read = QualityFromJson(kVisualText);
  ASSERT_TRUE(read.has_value());
  EXPECT_TRUE(read->visual_odometry);
  EXPECT_EQ(read->frames_tracked, 118u);
  EXPECT_DOUBLE_EQ(read->scans_per_s, 34.25);
  EXPECT_TRUE(read->routines.empty());
}

TEST(QualityFile, ReadsMissingOrMistypedKeysAsZero) {
  const std::optional<ReconstructionQuality> q =
      QualityFromJson(R"({"scans": "many", "key_frames": 7, "routines": [1, 2],
                          "warnings": ["kept", 3], "landmarks": {"in_graph": 2}})");
  ASSERT_TRUE(q.has_value());
  EXPECT_EQ(q->scans, 0u);
  EXPECT_EQ(q->key_frames, 7u);
  EXPECT_TRUE(q->routines.empty());
  EXPECT_EQ(q->warnings, std::vector<std::string>{"kept"});
  EXPECT_EQ(q->landmarks.in_graph, 2u);
  EXPECT_FALSE(q->scan_alignment.has_value());
  EXPECT_FALSE(q->scan_refinement.has_value());
  EXPECT_FALSE(QualityFromJson("[1, 2]").has_value());
  EXPECT_FALSE(QualityFromJson("{\"scans\": ").has_value());
  EXPECT_FALSE(QualityFromJson("").has_value());
}

TEST(QualityFile, WritesAndReadsAFile) {
  TempDir dir;
  const std::filesystem::path file = dir / "quality.json";
  WriteQualityFile(file, *QualityFromJson(kRgbdText));
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, kRgbdText);
  const ReconstructionQuality read = ReadQualityFile(file);
  ASSERT_TRUE(read.rgbd.has_value());
  EXPECT_EQ(read.rgbd->frames, 200u);
  EXPECT_EQ(read.rgbd->loops_accepted, 1u);
  EXPECT_THROW(ReadQualityFile(dir / "missing.json"), BadInputError);
  std::ofstream(dir / "array.json") << "[]";
  EXPECT_THROW(ReadQualityFile(dir / "array.json"), BadInputError);
  try {  // a folder that is not there: the path is at fault
    WriteQualityFile(dir / "no" / "such" / "quality.json", read);
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.kind(), ErrorKind::kBadInput) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
}

}  // namespace
}  // namespace littermap::run
