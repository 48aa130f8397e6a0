// The reconstruction options file: known keys set their options (the RGB-D choices both
// aligners), anything else fails naming the file and the key.

#include "reconstruct/options_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::reconstruct {
namespace {

std::filesystem::path Write(const test::TempDir& dir, const std::string& text) {
  const auto path = dir / "options.yaml";
  std::ofstream(path) << text;
  return path;
}

std::string ErrorOf(const std::filesystem::path& path) {
  ReconstructionOptions options;
  try {
    ApplyOptionsFile(path, &options);
  } catch (const BadInputError& e) {
    return e.what();
  }
  return "";
}

TEST(OptionsFile, SetsTheNamedOptions) {
  test::TempDir dir;
  ReconstructionOptions options;
  ApplyOptionsFile(Write(dir,
                         "min_matching_ratio: 0.5\n"
                         "rgbd: false\n"
                         "rgbd_features: akaze\n"
                         "rgbd_rejection: ransac\n"
                         "rgbd_key_frame_distance_m: 0.4\n"
                         "rgbd_orb_fast_threshold: 9\n"
                         "loop_closure: false\n"
                         "scan_alignment: off\n"
                         "alignment_point_sigma_m: 0.02\n"
                         "rgbd_loops: false\n"
                         "tilted_min_matching_ratio: 0.9\n"
                         "max_level_tilt_rad: 0.2\n"
                         "gyro_edge_sigma_floor_rad: 0.003\n"
                         "soft_edge_sigma_floor_rad: 0.04\n"
                         "gyro_turn_sigma_rad_per_sqrt_s: 0\n"
                         "loop_consistency_max_stretch_m: 5\n"
                         "loop_consistency_max_disagreement_m: 0.1\n"
                         "loop_consistency_max_disagreement_rad: 0.02\n"),
                   &options);
  EXPECT_EQ(options.slam.tracker.min_matching_ratio, 0.5);
  EXPECT_FALSE(options.rgbd);
  EXPECT_EQ(options.rgbd_tracker.aligner.features, RgbdFeatures::kAkaze);
  EXPECT_EQ(options.visual_odometry.aligner.features, RgbdFeatures::kAkaze);
  EXPECT_EQ(options.rgbd_tracker.aligner.rejection, PairRejection::kRansac);
  EXPECT_EQ(options.visual_odometry.aligner.rejection, PairRejection::kRansac);
  EXPECT_EQ(options.rgbd_tracker.key_frame_distance_m, 0.4);
  EXPECT_EQ(options.rgbd_tracker.aligner.orb_fast_threshold, 9);
  EXPECT_EQ(options.visual_odometry.aligner.orb_fast_threshold, 9);
  EXPECT_FALSE(options.slam.loop_closure);
  EXPECT_EQ(options.slam.alignment_mode, AlignmentMode::kOff);
  EXPECT_EQ(options.slam.alignment.point_sigma_m, 0.02);
  EXPECT_FALSE(options.rgbd_tracker.loops);
  EXPECT_EQ(options.slam.tracker.tilted_min_matching_ratio, 0.9);
  EXPECT_EQ(options.slam.tracker.max_level_tilt_rad, 0.2);
  EXPECT_EQ(options.slam.gyro_edge_sigma_floor_rad, 0.003);
  EXPECT_EQ(options.slam.soft_edge_sigma_floor_rad, 0.04);
  EXPECT_EQ(options.slam.gyro_turn_sigma_rad_per_sqrt_s, 0);
  EXPECT_EQ(options.slam.loop_consistency.max_stretch_m, 5);
  EXPECT_EQ(options.slam.loop_consistency.max_disagreement_m, 0.1);
  EXPECT_EQ(options.slam.loop_consistency.max_disagreement_rad, 0.02);
}

TEST(OptionsFile, AnEmptyFileKeepsTheDefaults) {
  test::TempDir dir;
  ReconstructionOptions options;
  ApplyOptionsFile(Write(dir, ""), &options);
  EXPECT_EQ(options.slam.tracker.min_matching_ratio,
            ReconstructionOptions{}.slam.tracker.min_matching_ratio);
  EXPECT_TRUE(options.rgbd);
}

TEST(OptionsFile, BadKeysAndValuesNameTheFileAndKey) {
  test::TempDir dir;
  const std::string unknown = ErrorOf(Write(dir, "min_matchng_ratio: 0.5\n"));
  EXPECT_NE(unknown.find("options.yaml: unknown option 'min_matchng_ratio'"), std::string::npos)
      << unknown;
  const std::string type = ErrorOf(Write(dir, "min_matching_ratio: [1, 2]\n"));
  EXPECT_NE(type.find("option 'min_matching_ratio' has a value of the wrong type"),
            std::string::npos)
      << type;
  const std::string choice = ErrorOf(Write(dir, "rgbd_features: surf\n"));
  EXPECT_NE(choice.find("options.yaml: option 'rgbd_features' must be one of akaze, orb, sift"),
            std::string::npos)
      << choice;
  const std::string mode = ErrorOf(Write(dir, "scan_alignment: yes\n"));
  EXPECT_NE(mode.find("option 'scan_alignment' must be one of auto, off, on"), std::string::npos)
      << mode;
  EXPECT_NE(ErrorOf(Write(dir, "- a list\n")).find("expected a map"), std::string::npos);
}

TEST(OptionsFile, OutOfRangeValuesFailValidation) {
  test::TempDir dir;
  ReconstructionOptions options;
  const std::filesystem::path file = Write(dir, "rgbd_min_confidence: 2\n");
  test::ExpectBadInput([&] { ApplyOptionsFile(file, &options); }, file.string() + ": ");
  const std::filesystem::path floor = Write(dir, "soft_edge_sigma_floor_rad: 0\n");
  test::ExpectBadInput([&] { ApplyOptionsFile(floor, &options); },
                       "edge sigma floors, odometry and refinement hold sigmas must be > 0");
  const std::filesystem::path gyro = Write(dir, "gyro_turn_sigma_rad_per_sqrt_s: -0.001\n");
  ReconstructionOptions fresh;
  test::ExpectBadInput([&] { ApplyOptionsFile(gyro, &fresh); },
                       "gyro_turn_sigma_rad_per_sqrt_s must be >= 0");
  const std::filesystem::path stretch = Write(dir, "loop_consistency_max_stretch_m: -1\n");
  ReconstructionOptions other;
  test::ExpectBadInput([&] { ApplyOptionsFile(stretch, &other); },
                       "loop consistency: the stretch and the disagreement bounds must be >= 0");
  const std::filesystem::path nan = Write(dir, "max_correction_m: .nan\n");
  test::ExpectBadInput([&] { ApplyOptionsFile(nan, &options); },
                       nan.string() + ": option 'max_correction_m' must be a finite number");
  const std::filesystem::path inf =
      Write(dir, "alignment_max_correspondence_distances_m: [1, .inf]\n");
  test::ExpectBadInput([&] { ApplyOptionsFile(inf, &options); },
                       "option 'alignment_max_correspondence_distances_m' must be finite numbers");
}

}  // namespace
}  // namespace littermap::reconstruct
