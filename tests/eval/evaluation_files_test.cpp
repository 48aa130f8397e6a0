// The metrics from files, as the `eval` commands run them: trajectories and relations graded from
// TUM files (errors naming the file), the truth files of a simulated run read together, a run's
// items carried into the truth's frame, and the detections' text report.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "eval/detection_evaluation.hpp"
#include "eval/pose_relations.hpp"
#include "eval/trajectory_metrics.hpp"
#include "support/expect_bad_input.hpp"
#include "support/temp_dir.hpp"

namespace littermap::eval {
namespace {

using test::ExpectBadInput;

// A 4 m straight line and a turn, one pose per 0.1 s, shifted by (dx, dy) and turned by yaw.
std::vector<StampedPose> Path(double dx, double dy, double yaw_rad) {
  std::vector<StampedPose> poses;
  const Eigen::Rotation2Dd R(yaw_rad);
  for (int i = 0; i < 60; ++i) {
    const Eigen::Vector2d p =
        i < 40 ? Eigen::Vector2d(0.1 * i, 0) : Eigen::Vector2d(4, 0.1 * (i - 40));
    const Eigen::Vector2d q = R * p + Eigen::Vector2d(dx, dy);
    poses.push_back(StampedPoseFromPlanar(1'000'000'000LL + i * 100'000'000LL,
                                          {q.x(), q.y(), yaw_rad + (i < 40 ? 0 : M_PI / 2)}));
  }
  return poses;
}

void Write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(EvaluationFiles, TrajectoryFilesGradeAsTheirPoses) {
  test::TempDir dir;
  bag::WriteTumTrajectory(dir / "est.tum", Path(1, 2, 0.3));
  bag::WriteTumTrajectory(dir / "ref.tum", Path(0, 0, 0));
  const TrajectoryMetrics metrics = EvaluateTrajectory(dir / "est.tum", dir / "ref.tum", {});
  EXPECT_EQ(metrics.associated_poses, 60u);
  EXPECT_LT(metrics.ate_rmse_m, 1e-6);  // a rigid motion of the reference
  Write(dir / "bad.tum", "1.0 0 0\n");
  ExpectBadInput([&] { EvaluateTrajectory(dir / "bad.tum", dir / "ref.tum", {}); }, "bad.tum:1");
}

TEST(EvaluationFiles, RelationErrorsNameTheTrajectoryFile) {
  test::TempDir dir;
  bag::WriteTumTrajectory(dir / "traj.tum", Path(0, 0, 0));
  std::vector<double> stamps;
  for (int i = 0; i < 60; ++i) stamps.push_back(1.0 + 0.1 * i);
  const std::vector<PoseRelation> relations = {{1.0, 2.0, {1.0, 0, 0}},
                                               {1.0, 5.0, {4, 0, M_PI / 2}}};
  const PoseRelationMetrics metrics =
      EvaluatePoseRelations(dir / "traj.tum", stamps, relations, {});
  EXPECT_EQ(metrics.used, 2u);
  EXPECT_NEAR(metrics.component.translation_m.max, 0, 1e-6);
  stamps.pop_back();  // one pose too many
  ExpectBadInput([&] { EvaluatePoseRelations(dir / "traj.tum", stamps, relations, {}); },
                 (dir / "traj.tum").string() + ": the trajectory has 60 poses for 59 scans");
}

TEST(EvaluationFiles, TruthFilesReadInOrder) {
  test::TempDir dir;
  Write(dir / "litter.csv", "id,class,x,y\n1,can,1,0\n2,cup,5,5\n");
  Write(dir / "natural.csv", "id,class,x,y\n3,stone,2,0\n");
  Write(dir / "visible.csv", "frame,object_id,pixels\n0,1,500\n0,3,20\n");
  const DetectionTruth all =
      ReadDetectionTruth(dir / "litter.csv", dir / "natural.csv", dir / "visible.csv");
  ASSERT_EQ(all.objects.size(), 3u);
  EXPECT_TRUE(all.objects[0].litter);
  EXPECT_EQ(all.objects[2].id, "3");
  EXPECT_FALSE(all.objects[2].litter);
  ASSERT_TRUE(all.visible_pixels.has_value());
  EXPECT_EQ(all.visible_pixels->at("1"), std::vector<std::size_t>{500});
  const DetectionTruth litter_only = ReadDetectionTruth(dir / "litter.csv", {}, {});
  EXPECT_EQ(litter_only.objects.size(), 2u);
  EXPECT_FALSE(litter_only.visible_pixels.has_value());
  ExpectBadInput([&] { ReadDetectionTruth(dir / "litter.csv", dir / "none.csv", {}); }, "none.csv");
}

TEST(EvaluationFiles, ItemsFollowTheAlignmentOfTheirRun) {
  test::TempDir dir;
  // The run's map frame is the truth's turned by 0.3 rad and moved by (1, 2).
  bag::WriteTumTrajectory(dir / "est.tum", Path(1, 2, 0.3));
  bag::WriteTumTrajectory(dir / "ref.tum", Path(0, 0, 0));
  const Eigen::Vector2d in_truth(3, 1);
  const Eigen::Vector2d in_run = Eigen::Rotation2Dd(0.3) * in_truth + Eigen::Vector2d(1, 2);
  const auto items =
      AlignItems({{"a", "can", in_run, 1.0, true}}, dir / "est.tum", dir / "ref.tum");
  ASSERT_EQ(items.size(), 1u);
  EXPECT_NEAR((items[0].position_m - in_truth).norm(), 0, 1e-6);
  Write(dir / "other.tum", "5.0 0 0 0 0 0 0 1\n6.0 1 0 0 0 0 0 1\n");
  EXPECT_THROW(AlignItems({}, dir / "other.tum", dir / "ref.tum"), BadInputError);
}

TEST(EvaluationFiles, TextReportOfDetections) {
  DetectionTruth truth;
  truth.objects = {
      {"1", "can", {0, 0}, true}, {"2", "cup", {5, 0}, true}, {"3", "stone", {9, 0}, false}};
  const std::vector<DetectedItem> items = {{"a", "can", {0.1, 0}, 0.9, true},
                                           {"b", "bottle", {20, 0}, 0.8, true}};
  const DetectionMetrics metrics = EvaluateDetections(items, truth, {});
  EXPECT_FALSE(metrics.visibility_filtered);
  const std::string text = ToText(metrics, {});
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "matching           one-to-one within 0.30 m, nearest pairs first");
  EXPECT_EQ(text.find("hidden objects"), std::string::npos);
  EXPECT_NE(text.find("\ntrue positives     1\nfalse positives    1\nfalse negatives    1\n"
                      "precision          0.500\nrecall             0.500\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\nconfusion (rows: truth, columns: predicted)\n"), std::string::npos);
  EXPECT_NE(text.find("\ncan                   1         1     1      1.000   1.000\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.back(), '\n');

  truth.visible_pixels = VisiblePixels{{"1", {500}}, {"3", {500}}};  // the cup is hidden
  const DetectionMetrics visible = EvaluateDetections(items, truth, {});
  EXPECT_TRUE(visible.visibility_filtered);
  EXPECT_NE(ToText(visible, {})
                .find("hidden objects     1 (under 100 pixels in every mask: not truth)\n"),
            std::string::npos);
  EXPECT_NE(ToText(visible, {})
                .find("\nrecall             1.000\n"
                      "  by masks seen in   1: 1/1 1.000  2: 0/0 1.000  3+: 0/0 1.000\n"),
            std::string::npos)
      << ToText(visible, {});
}

}  // namespace
}  // namespace littermap::eval
