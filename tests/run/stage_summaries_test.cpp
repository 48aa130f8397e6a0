// What the reconstruct and detect stages tell the user when done.

#include <gtest/gtest.h>

#include "run/detect_run.hpp"
#include "run/reconstruct_run.hpp"

namespace littermap::run {
namespace {

TEST(ReconstructSummary, CountsPosesKeyFramesAndLoops) {
  ReconstructRunResult result;
  result.run_dir = "out/run";
  result.poses = 201;
  result.key_frames = 22;
  result.loops_accepted = 3;
  result.loops_rejected = 1;
  result.run_time_s = 1.304;
  result.scans_per_s = 154.6;
  EXPECT_EQ(ReconstructSummary(result),
            "wrote out/run: 201 poses, 22 key frames, loops 3 accepted / 1 rejected, 1.30 s "
            "(155 scans/s)");
}

TEST(ReconstructSummary, CountsFramesForVisualOdometry) {
  ReconstructRunResult result;
  result.run_dir = "tum/run";
  result.visual_odometry = true;
  result.visual.frames = 120;
  result.visual.tracked = 118;
  result.visual.key_frames = 14;
  result.visual.segments = 2;
  result.run_time_s = 3.5;
  result.scans_per_s = 34.25;
  EXPECT_EQ(ReconstructSummary(result),
            "wrote tum/run: 118 of 120 frames tracked, 14 key frames, 2 segments, 3.50 s "
            "(34 frames/s)");
}

TEST(DetectSummary, CountsItemsAndTimesTheSegmentationPerFrame) {
  DetectRunResult result;
  result.output_dir = "out/run";
  result.objects.frames = 4;
  result.objects.objects = 9;
  result.objects.time = {40, 8, 4, 20, 12};  // ms over the 4 frames
  result.litter_items = 2;
  result.natural_objects = 1;
  result.seldom_seen = 5;
  result.merged = 1;
  EXPECT_EQ(SegmentationTimeLine(result.objects),
            "segmentation 21.0 ms/frame (cloud+normals 10.0, components 2.0, ground 1.0, "
            "texture+graph cut 5.0, objects 3.0)");
  EXPECT_EQ(DetectSummary(result, detect::FusionOptions{0.25, 3, 0.75}),
            "wrote out/run: 4 frames, 9 objects, 2 litter items and 1 natural objects seen in "
            ">= 3 views and >= 75% of the frames that could see them; 5 seen in fewer were "
            "dropped, 1 merged with a neighbour within 0.25 m\n" +
                SegmentationTimeLine(result.objects));
}

TEST(DetectSummary, TimesNoFramesAsOne) {
  detect::RunObjectsResult none;
  EXPECT_EQ(SegmentationTimeLine(none),
            "segmentation 0.0 ms/frame (cloud+normals 0.0, components 0.0, ground 0.0, "
            "texture+graph cut 0.0, objects 0.0)");
}

}  // namespace
}  // namespace littermap::run
