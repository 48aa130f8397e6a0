#pragma once
// The relations metric of Kuemmerle et al., "On measuring the accuracy of SLAM algorithms"
// (Autonomous Robots 27(4), 2009): a trajectory is graded by relative motions between pairs of
// scans that people verified by hand, not by another SLAM system's poses. Each relation
// (t1, t2, x, y, yaw) is the motion from the pose at t1 to the pose at t2 in the frame of the
// pose at t1; the estimate's is inv(P1) * P2. Two error definitions are in use and both are
// reported:
// - the benchmark's metricEvaluator: the component difference of the two motions,
//   translation |t_est - t_rel|, rotation |wrap(yaw_est - yaw_rel)|;
// - Cartographer's compute_relations_metrics: the motion est * inv(rel), its translation norm
//   |t_est - R(yaw_est - yaw_rel) t_rel| and its angle.
// The relation stamps are those of the benchmark's raw logs. A trajectory has one pose per scan,
// in the log's scan order; `scan_stamps_s` gives each scan's stamp in the relations' time base
// (the raw log's own stamps, or a .scanmap's for a log that was re-stamped and thinned).

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/planar_pose.hpp"

namespace littermap::eval {

struct PoseRelation {
  double t1_s = 0;
  double t2_s = 0;
  PlanarPose T_1_2;  // the verified motion from the pose at t1 to the pose at t2
};

// A .relations file: "t1 t2 x y z roll pitch yaw" per line. Throws BadInputError
// "FILE:LINE: ..." for a malformed line and for a file without relations.
std::vector<PoseRelation> ReadPoseRelations(const std::filesystem::path& path);

// A .scanmap file: "scan_index log_stamp raw_scan_index raw_stamp" per scan of a re-stamped log,
// '#' lines skipped; returns raw_stamp for scan 0, 1, ... Throws BadInputError "FILE:LINE: ..."
// for a malformed line or a scan index out of order.
std::vector<double> ReadScanMapStamps(const std::filesystem::path& path);

struct PoseRelationOptions {
  // A relation stamp names the scan whose stamp is nearest to it, if within this: the relation
  // files print 5 or 6 decimals.
  double max_stamp_difference_s = 2e-5;
  double large_error_m = 0.5;  // relations with a larger translational error are counted
  void Validate() const;
};

struct ErrorStatistics {
  double mean = 0;
  double stddev = 0;  // the sample standard deviation (n - 1), 0 for one value
  double max = 0;
};

// The errors of one definition over the relations used.
struct RelationErrors {
  ErrorStatistics translation_m;
  ErrorStatistics translation_sq_m2;
  ErrorStatistics rotation_deg;
  ErrorStatistics rotation_sq_deg2;
  double translation_median_m = 0;
  std::size_t over_large_error = 0;  // translational error above options.large_error_m
};

struct PoseRelationMetrics {
  std::size_t relations = 0;
  std::size_t used = 0;         // both ends are scans of the trajectory
  std::size_t unmatched = 0;    // an end is no scan's stamp
  RelationErrors component;     // the benchmark's metricEvaluator
  RelationErrors cartographer;  // Cartographer's compute_relations_metrics
};

// Throws BadInputError if the trajectory does not have one pose per scan stamp, or if no
// relation can be used.
PoseRelationMetrics EvaluatePoseRelations(const std::vector<PlanarPose>& trajectory,
                                          const std::vector<double>& scan_stamps_s,
                                          const std::vector<PoseRelation>& relations,
                                          const PoseRelationOptions& options);
// The same for a TUM trajectory file (the yaw of each pose); BadInputErrors of the evaluation
// name the file.
PoseRelationMetrics EvaluatePoseRelations(const std::filesystem::path& trajectory,
                                          const std::vector<double>& scan_stamps_s,
                                          const std::vector<PoseRelation>& relations,
                                          const PoseRelationOptions& options);

// The metrics as a JSON object (2-space indent): relations, used, unmatched, and per definition
// (metric_evaluator, cartographer) trans_m, trans_sq_m2, rot_deg, rot_sq_deg2 (mean, stddev,
// max), trans_median_m and over_large_error.
std::string ToJson(const PoseRelationMetrics& metrics);
// The same as text, a block per definition.
std::string ToText(const PoseRelationMetrics& metrics, const PoseRelationOptions& options);

}  // namespace littermap::eval
