// Ground segmentation (thesis 3.1) on ray-cast scenes with known objects, and on the real TUM
// desk pair where the desk plays the ground.

#include "detect/frame_segmenter.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "synthetic_scene.hpp"

namespace littermap::detect {
namespace {

using test::RenderScene;
using test::SceneBox;
using test::SyntheticScene;

FrameSegmentation Segment(const SyntheticScene& scene,
                          const SegmentationOptions& options = SegmentationOptions{}) {
  const CameraIntrinsics K;
  cv::Mat colour, depth;
  RenderScene(scene, K, &colour, &depth);
  FrameSegmenter segmenter(options);
  return segmenter.Segment(colour, depth, K, test::CameraPose().cast<float>());
}

// The objects, nearest first.
std::vector<SegmentedObject> NearestFirst(const FrameSegmentation& result) {
  std::vector<SegmentedObject> objects = result.objects;
  std::sort(objects.begin(), objects.end(),
            [](const auto& a, const auto& b) { return a.range_m < b.range_m; });
  return objects;
}

// The can-sized box 2 m ahead that several scenes hold (12 x 7 x 7 cm, level frame); found, it is
// seen by its visible surfaces only: the centroid sits on the camera's side and top, within 5 cm.
const SceneBox kCan{{2.0, -0.05, 0.0}, {2.12, 0.02, 0.07}, {40, 40, 200}};
void ExpectTheCan(const SegmentedObject& object) {
  EXPECT_NEAR(object.centroid_level_m.x(), 2.06, 0.05);
  EXPECT_NEAR(object.centroid_level_m.y(), -0.015, 0.03);
  EXPECT_NEAR(object.height_m, 0.07, 0.02);
}

TEST(FrameSegmenter, FindsTheGroundAndNothingElseOnAnEmptyLawn) {
  const FrameSegmentation result = Segment(SyntheticScene{});
  ASSERT_TRUE(result.ground_found);
  // Depth noise grows to ~2 cm at 4.5 m; the fitted plane must stay within a few mm of it.
  EXPECT_LT(result.ground_rms_m, 0.01);
  EXPECT_NEAR(result.ground.HeightAt(2.0, 0.0), 0.0, 0.01);
  EXPECT_GT(result.ground_points, 100000u);
  EXPECT_TRUE(result.objects.empty());
}

TEST(FrameSegmenter, SlopedGroundIsGroundNotAnObject) {
  SyntheticScene scene;
  scene.slope_deg = 8;
  const FrameSegmentation result = Segment(scene);
  ASSERT_TRUE(result.ground_found);
  EXPECT_NEAR(result.ground.HeightAt(3.0, 0.0), 3.0 * std::tan(8.0 * M_PI / 180.0), 0.02);
  EXPECT_TRUE(result.objects.empty());
}

TEST(FrameSegmenter, CutsOutLitterSizedBoxesAndMeasuresThem) {
  SyntheticScene scene;
  // A can-sized box 2 m ahead and a flat carton 3 m ahead to the left.
  scene.boxes.push_back(kCan);
  scene.boxes.push_back({{3.0, 0.5, 0.0}, {3.2, 0.6, 0.03}, {230, 230, 230}});
  const FrameSegmentation result = Segment(scene);
  ASSERT_TRUE(result.ground_found);
  ASSERT_EQ(result.objects.size(), 2u);
  const std::vector<SegmentedObject> objects = NearestFirst(result);
  ExpectTheCan(objects[0]);
  EXPECT_NEAR(objects[0].size_m, 0.12, 0.04);
  EXPECT_NEAR(objects[1].centroid_level_m.x(), 3.1, 0.06);
  EXPECT_NEAR(objects[1].centroid_level_m.y(), 0.55, 0.04);
  EXPECT_NEAR(objects[1].size_m, 0.2, 0.06);
}

// The geometry computed on every second pixel finds the same objects, and their outlines, refined
// at full resolution, are the full-resolution geometry's: mask IoU >= 0.85, centroids within 1 cm.
TEST(FrameSegmenter, GeometryAtHalfResolutionOutlinesObjectsAtFullResolution) {
  SyntheticScene scene;
  scene.boxes.push_back(kCan);
  scene.boxes.push_back({{3.0, 0.5, 0.0}, {3.2, 0.6, 0.03}, {230, 230, 230}});
  scene.boxes.push_back({{4.0, -0.6, 0.0}, {4.08, -0.52, 0.08}, {40, 160, 220}});  // far: 10 px
  SegmentationOptions full, half;
  full.geometry_step_px = 1;
  half.geometry_step_px = 2;
  const FrameSegmentation a = Segment(scene, full), b = Segment(scene, half);
  ASSERT_EQ(a.objects.size(), 3u);
  ASSERT_EQ(b.objects.size(), 3u);
  EXPECT_EQ(b.refinement.labels.size(), cv::Size(640, 480));
  EXPECT_EQ(b.refinement.non_ground.size(), cv::Size(640, 480));
  EXPECT_NEAR(double(b.ground_points), double(a.ground_points), 0.05 * double(a.ground_points));
  for (const SegmentedObject& x : a.objects) {
    const auto y = std::min_element(b.objects.begin(), b.objects.end(), [&](auto& p, auto& q) {
      return (p.centroid_level_m - x.centroid_level_m).norm() <
             (q.centroid_level_m - x.centroid_level_m).norm();
    });
    EXPECT_LT((y->centroid_level_m - x.centroid_level_m).norm(), 0.01);
    cv::Mat mask_a = cv::Mat::zeros(480, 640, CV_8U), mask_b = mask_a.clone();
    x.mask.copyTo(mask_a(x.box));
    y->mask.copyTo(mask_b(y->box));
    const double iou =
        double(cv::countNonZero(mask_a & mask_b)) / cv::countNonZero(mask_a | mask_b);
    EXPECT_GE(iou, 0.85) << "object at " << x.centroid_level_m.transpose();
  }
}

TEST(FrameSegmenter, ObjectsTallerThanLitterAreNotObjects) {
  SyntheticScene scene;
  scene.boxes.push_back({{2.5, -0.3, 0.0}, {2.9, 0.3, 1.5}, {30, 60, 90}});  // a wall-ish block
  const FrameSegmentation result = Segment(scene);
  ASSERT_TRUE(result.ground_found);
  EXPECT_TRUE(result.objects.empty());
}

// A board lying flat, too wide for litter but as low as a carton: its core alone is measured too
// wide, so it is rejected before GrabCut is spent on it; a carton beside it is still refined.
TEST(FrameSegmenter, CoresWiderThanLitterAreRejectedBeforeRefinement) {
  SyntheticScene scene;
  scene.boxes.push_back({{2.2, -0.8, 0.0}, {2.6, 0.2, 0.04}, {30, 60, 160}});  // 1 m board
  scene.boxes.push_back({{3.0, 0.5, 0.0}, {3.2, 0.6, 0.03}, {230, 230, 230}});
  const FrameSegmentation result = Segment(scene);
  ASSERT_TRUE(result.ground_found);
  ASSERT_EQ(result.blobs, 2u);
  EXPECT_EQ(result.refined, 1u);
  ASSERT_EQ(result.objects.size(), 1u);
  EXPECT_NEAR(result.objects[0].centroid_level_m.x(), 3.1, 0.06);
}

// A can lying before a larger carton: the camera sees the can's top against the carton's face, one
// blob 0.6 m deep, too large for litter. Cut apart in space, both are found where they lie.
TEST(FrameSegmenter, LitterTouchingLitterInTheImageIsCutApartInSpace) {
  SyntheticScene scene;
  scene.boxes.push_back(kCan);
  scene.boxes.push_back({{2.35, -0.15, 0.0}, {2.6, 0.2, 0.15}, {220, 220, 220}});  // carton
  SegmentationOptions whole;
  whole.objects.split = false;
  EXPECT_TRUE(Segment(scene, whole).objects.empty());
  const FrameSegmentation result = Segment(scene);
  ASSERT_EQ(result.objects.size(), 2u);
  const std::vector<SegmentedObject> objects = NearestFirst(result);
  ExpectTheCan(objects[0]);
  EXPECT_NEAR(objects[1].centroid_level_m.x(), 2.45, 0.1);
  EXPECT_NEAR(objects[1].centroid_level_m.y(), 0.025, 0.05);
  EXPECT_NEAR(objects[1].height_m, 0.15, 0.02);
}

// A can before a trunk: one blob in the image, taller than litter. The trunk's part stays too
// tall; the can's part is litter.
TEST(FrameSegmenter, LitterBeforeATrunkIsFound) {
  SyntheticScene scene;
  scene.boxes.push_back(kCan);
  scene.boxes.push_back({{2.3, -0.2, 0.0}, {2.6, 0.2, 1.5}, {30, 60, 90}});  // trunk
  SegmentationOptions whole;
  whole.objects.split = false;
  EXPECT_TRUE(Segment(scene, whole).objects.empty());
  const FrameSegmentation result = Segment(scene);
  ASSERT_EQ(result.objects.size(), 1u);
  ExpectTheCan(result.objects[0]);
}

// A blob of more litter-sized parts than split_max_parts is taken for clutter (a bush's leaves,
// the things on a desk) and none of its parts is kept: here four cans before a wall, found only
// when four parts are allowed.
TEST(FrameSegmenter, ABlobOfManyLitterSizedPartsIsClutter) {
  SyntheticScene scene;
  for (const double y : {-0.4, -0.15, 0.1, 0.35}) {
    scene.boxes.push_back({{2.0, y, 0.0}, {2.12, y + 0.07, 0.07}, {40, 40, 200}});
  }
  scene.boxes.push_back({{2.3, -0.6, 0.0}, {2.6, 0.6, 1.5}, {30, 60, 90}});
  const FrameSegmentation clutter = Segment(scene);
  EXPECT_EQ(clutter.split, 1u);
  EXPECT_TRUE(clutter.objects.empty());
  SegmentationOptions four;
  four.objects.split_max_parts = 4;
  const FrameSegmentation cans = Segment(scene, four);
  ASSERT_EQ(cans.objects.size(), 4u);
  for (const SegmentedObject& can : cans.objects) {
    EXPECT_NEAR(can.centroid_level_m.x(), 2.06, 0.05);
    EXPECT_NEAR(can.height_m, 0.07, 0.02);
  }
}

// The TUM freiburg2 desk, camera about 0.8 m above the desk and pitched ~40 degrees down, and its
// segmentation with the desk as the ground.
struct TumDesk {
  cv::Mat colour;
  cv::Mat depth_mm;
  CameraIntrinsics K{520.909, 521.007, 325.141, 249.702, 640, 480};
  Eigen::Isometry3f T_level_camera =
      (MakeIsometry({0, 0, 0.8}, {0, 40.0 * M_PI / 180.0, 0}) * T_body_optical()).cast<float>();
  SegmentationOptions options;
};

TumDesk ReadTumDesk(const std::string& frame) {
  const std::string dir = std::string(LITTERMAP_DATASETS_DIR) + "/tum_pair/";
  TumDesk desk;
  desk.colour = cv::imread(dir + frame + ".png", cv::IMREAD_COLOR);
  const cv::Mat raw = cv::imread(dir + frame + "_depth.png", cv::IMREAD_UNCHANGED);
  if (!raw.empty()) raw.convertTo(desk.depth_mm, CV_16U, 1000.0 / 5000.0);  // 5000 per metre
  desk.options.ground.max_level_offset_m = 1.0;  // the desk is not at wheel level
  return desk;
}

// The desk is the ground; the mug, the tape roll and the can standing on it are objects.
TEST(FrameSegmenter, RealDeskFromTumIsGroundWithObjectsOnIt) {
  const TumDesk desk = ReadTumDesk("1");
  ASSERT_FALSE(desk.colour.empty());
  ASSERT_FALSE(desk.depth_mm.empty());
  FrameSegmenter segmenter(desk.options);
  const FrameSegmentation result =
      segmenter.Segment(desk.colour, desk.depth_mm, desk.K, desk.T_level_camera);
  ASSERT_TRUE(result.ground_found);
  EXPECT_LT(result.ground_rms_m, 0.03);
  EXPECT_GT(result.ground_points, 50000u);
  // Pixels on the mug, the tape roll and the red can (looked up in 1.png).
  const std::vector<cv::Point> expected = {{465, 325}, {572, 318}, {62, 292}};
  int found = 0;
  for (const cv::Point& p : expected) {
    for (const auto& object : result.objects) found += object.box.contains(p) ? 1 : 0;
  }
  EXPECT_GE(found, 2) << result.objects.size() << " objects";
  for (const auto& object : result.objects) {
    EXPECT_LE(object.size_m, 0.4);
    EXPECT_GE(object.size_m, 0.03);
  }
}

// GrabCut's colour models start from k-means++ seeds drawn from OpenCV's per-thread random
// stream: an object's mask must not depend on how many objects were refined before it (other
// frames, or blobs of this frame rejected before GrabCut).
TEST(FrameSegmenter, AnObjectIsCutTheSameWhateverWasRefinedBefore) {
  const TumDesk desk = ReadTumDesk("1");
  const TumDesk other = ReadTumDesk("2");
  ASSERT_FALSE(desk.colour.empty());
  ASSERT_FALSE(other.colour.empty());
  const auto segment = [](const TumDesk& frame) {
    return FrameSegmenter(frame.options)
        .Segment(frame.colour, frame.depth_mm, frame.K, frame.T_level_camera);
  };
  const FrameSegmentation first = segment(desk);
  ASSERT_GT(first.refined, 0u);
  (void)segment(other);
  for (int i = 0; i < 1000; ++i) (void)cv::theRNG().next();  // any other use of the stream
  const FrameSegmentation again = segment(desk);
  ASSERT_EQ(again.objects.size(), first.objects.size());
  for (std::size_t i = 0; i < first.objects.size(); ++i) {
    EXPECT_EQ(again.objects[i].box, first.objects[i].box) << i;
    EXPECT_EQ(cv::countNonZero(again.objects[i].mask != first.objects[i].mask), 0) << i;
  }
}

}  // namespace
}  // namespace littermap::detect
