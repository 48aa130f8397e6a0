// The detection options file: its keys set the segmentation and fusion options, the command
// line's README lists each of them, anything else fails naming the file and the key.

#include "detect/options_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::detect {
namespace {

std::filesystem::path Write(const test::TempDir& dir, const std::string& text) {
  const auto path = dir / "detect.yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(DetectOptionsFile, SetsTheNamedOptions) {
  test::TempDir dir;
  RunObjectsOptions objects;
  FusionOptions fusion;
  ApplyOptionsFile(Write(dir,
                         "normal_step_px: 1\n"
                         "max_depth_m: 4.0\n"
                         "depth_noise_per_m2: 0.002\n"
                         "max_training_pixels: 400\n"
                         "refine_objects: false\n"
                         "max_size_m: 0.5\n"
                         "every: 2\n"
                         "min_views: 4\n"
                         "class_views: 5\n"
                         "min_litter_probability: 0.6\n"
                         "association_radius_m: 0.3\n"),
                   &objects, &fusion);
  const SegmentationOptions& s = objects.segmentation;
  EXPECT_EQ(s.cloud.normal_step_px, 1);
  EXPECT_EQ(s.cloud.max_depth_m, 4.0f);
  EXPECT_EQ(s.ground.depth_noise_per_m2, 0.002);  // one noise model for both steps
  EXPECT_EQ(s.texture.depth_noise_per_m2, 0.002);
  EXPECT_EQ(s.texture.max_training_pixels, 400);
  EXPECT_FALSE(s.objects.refine);
  EXPECT_EQ(s.objects.max_size_m, 0.5);
  EXPECT_EQ(objects.every, 2u);
  EXPECT_EQ(fusion.min_views, 4);
  EXPECT_EQ(fusion.class_views, 5);
  EXPECT_EQ(fusion.min_litter_probability, 0.6);
  EXPECT_EQ(fusion.association_radius_m, 0.3);
  // Untouched keys keep their defaults.
  EXPECT_EQ(s.components.max_gap_m, ComponentOptions{}.max_gap_m);
}

TEST(DetectOptionsFile, BadKeysAndValuesNameTheFileAndKey) {
  test::TempDir dir;
  RunObjectsOptions objects;
  FusionOptions fusion;
  auto apply = [&](const std::filesystem::path& file) {
    return [&objects, &fusion, file] { ApplyOptionsFile(file, &objects, &fusion); };
  };
  const auto unknown = Write(dir, "normal_stepx: 1\n");
  test::ExpectBadInput(apply(unknown), unknown.string() + ": unknown option 'normal_stepx'");
  const auto negative = Write(dir, "every: -1\n");
  test::ExpectBadInput(apply(negative), "option 'every' has a value of the wrong type");
  const auto nan = Write(dir, "max_size_m: .nan\n");
  test::ExpectBadInput(apply(nan), "option 'max_size_m' must be a finite number");
  const auto range = Write(dir, "max_size_m: 0.01\n");
  test::ExpectBadInput(apply(range),
                       range.string() + ": segmentation: max_size_m must be > min_size_m");
  const auto step = Write(dir, "normal_step_px: 20\n");
  test::ExpectBadInput(apply(step), "normal_step_px must be from 1 to 8");
  const auto geometry = Write(dir, "geometry_step_px: 5\n");
  test::ExpectBadInput(apply(geometry), "geometry_step_px must be from 1 to 4");
  const auto litter = Write(dir, "min_litter_probability: 0\n");
  test::ExpectBadInput(apply(litter),
                       litter.string() + ": detect: min_litter_probability must be in (0, 1]");
  const auto window = Write(dir, "fals_window_px: 4\n");
  test::ExpectBadInput(apply(window), "fals_window_px must be 1, 3, 5 or 7");
}

// The shipped full-resolution profile reads, and differs from the defaults where it says.
TEST(DetectOptionsFile, TheFullResolutionProfileSetsTheGeometryStepAndTheGrabCutBoxes) {
  RunObjectsOptions objects;
  FusionOptions fusion;
  ApplyOptionsFile(LITTERMAP_SOURCE_DIR "/samples/detect_full.yaml", &objects, &fusion);
  const SegmentationOptions& s = objects.segmentation;
  EXPECT_EQ(SegmentationOptions{}.geometry_step_px, 2);
  EXPECT_EQ(SegmentationOptions{}.objects.box_margin, 0.3);
  EXPECT_EQ(SegmentationOptions{}.objects.max_refine_pixels, 3000);
  EXPECT_EQ(s.geometry_step_px, 1);
  EXPECT_EQ(s.objects.box_margin, 0.6);
  EXPECT_EQ(s.objects.max_refine_pixels, 6000);
  EXPECT_EQ(s.cloud.fals_window_px, OrganizedCloudOptions{}.fals_window_px);
}

TEST(DetectOptionsFile, TheReadmeDocumentsEveryKey) {
  std::ifstream file(LITTERMAP_SOURCE_DIR "/README.md");
  std::stringstream text;
  text << file.rdbuf();
  const std::string readme = text.str();
  const std::size_t section = readme.find("### `littermap detect");
  ASSERT_NE(section, std::string::npos);
  const std::string detect = readme.substr(section, readme.find("\n### ", section + 1) - section);
  for (const std::string& key : OptionsFileKeys()) {
    EXPECT_NE(detect.find("`" + key + "`"), std::string::npos) << key << " is not in README";
  }
}

}  // namespace
}  // namespace littermap::detect
