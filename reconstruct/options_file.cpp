#include "reconstruct/options_file.hpp"

#include <map>
#include <utility>

#include "core/options_file.hpp"

namespace littermap::reconstruct {
namespace {

using O = ReconstructionOptions;
using Setter = OptionSetter<O>;

// A value of the RGB-D aligners of routine 3 and of visual odometry alike.
template <typename T>
Setter SetAligners(T RgbdAlignerOptions::*field) {
  return [field](const YAML::Node& node, O* options) {
    options->rgbd_tracker.aligner.*field = options->visual_odometry.aligner.*field =
                                               OptionValue<T>(node);
  };
}

// A named choice, for both RGB-D aligners.
template <typename Enum>
Setter SetAligners(std::map<std::string, Enum> names, Enum RgbdAlignerOptions::*field) {
  return [names, field](const YAML::Node& node, O* options) {
    options->rgbd_tracker.aligner.*field = options->visual_odometry.aligner.*field =
                                               OptionChoice(names, node);
  };
}

template <typename T, typename Field>
Setter Set(Field field) {
  return SetOption<T, O>(field);
}

template <typename Enum, typename Field>
Setter SetChoice(std::map<std::string, Enum> names, Field field) {
  return SetOptionChoice<O>(std::move(names), field);
}

const OptionSetters<O>& Setters() {
  static const OptionSetters<O> setters = {
      {"scan_min_range_m", Set<double>([](O& o) -> double& { return o.slam.points.min_range_m; })},
      {"scan_max_range_m", Set<double>([](O& o) -> double& { return o.slam.points.max_range_m; })},
      {"scan_voxel_size_m", Set<double>([](O& o) -> double& { return o.slam.scan_voxel_size_m; })},
      {"moving_echoes", SetChoice<MovingEchoMode>(
                            {{"auto", MovingEchoMode::kAuto},
                             {"on", MovingEchoMode::kOn},
                             {"true", MovingEchoMode::kOn},
                             {"off", MovingEchoMode::kOff},
                             {"false", MovingEchoMode::kOff}},
                            [](O& o) -> MovingEchoMode& { return o.slam.moving_echoes.mode; })},
      {"moving_echo_min_relief_m",
       Set<double>([](O& o) -> double& { return o.slam.moving_echoes.min_relief_m; })},
      {"moving_echo_long_interval_s",
       Set<double>([](O& o) -> double& { return o.slam.moving_echoes.long_interval_s; })},
      {"moving_echo_max_fraction",
       Set<double>([](O& o) -> double& { return o.slam.moving_echoes.max_moving_fraction; })},
      {"icp_point_to_line",
       Set<bool>([](O& o) -> bool& { return o.slam.tracker.icp.point_to_line; })},
      {"icp_max_correspondence_distances_m",
       Set<std::vector<double>>([](O& o) -> std::vector<double>& {
         return o.slam.tracker.icp.max_correspondence_distances_m;
       })},
      {"icp_inlier_distance_m",
       Set<double>([](O& o) -> double& { return o.slam.tracker.icp.inlier_distance_m; })},
      {"min_matching_ratio",
       Set<double>([](O& o) -> double& { return o.slam.tracker.min_matching_ratio; })},
      {"min_buffer_matching_ratio",
       Set<double>([](O& o) -> double& { return o.slam.tracker.min_buffer_matching_ratio; })},
      {"max_level_tilt_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.max_level_tilt_rad; })},
      {"tilted_min_matching_ratio",
       Set<double>([](O& o) -> double& { return o.slam.tracker.tilted_min_matching_ratio; })},
      {"odometry_sigma_m",
       Set<double>([](O& o) -> double& { return o.slam.tracker.odometry_sigma_m; })},
      {"odometry_sigma_per_m",
       Set<double>([](O& o) -> double& { return o.slam.tracker.odometry_sigma_per_m; })},
      {"odometry_sigma_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.odometry_sigma_rad; })},
      {"odometry_sigma_rad_per_m",
       Set<double>([](O& o) -> double& { return o.slam.tracker.odometry_sigma_rad_per_m; })},
      {"odometry_sigma_rad_per_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.odometry_sigma_rad_per_rad; })},
      {"gyro_heading", Set<bool>([](O& o) -> bool& { return o.gyro_heading; })},
      {"gyro_sigma_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.gyro_sigma_rad; })},
      {"gyro_sigma_rad_per_s",
       Set<double>([](O& o) -> double& { return o.slam.tracker.gyro_sigma_rad_per_s; })},
      {"gyro_sigma_rad_per_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.gyro_sigma_rad_per_rad; })},
      {"max_correction_m",
       Set<double>([](O& o) -> double& { return o.slam.tracker.max_correction_m; })},
      {"max_correction_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.max_correction_rad; })},
      {"min_ratio_large_turn_correction",
       Set<double>([](O& o) -> double& { return o.slam.tracker.min_ratio_large_turn_correction; })},
      {"min_arbitration_ratio_gain",
       Set<double>([](O& o) -> double& { return o.slam.tracker.min_arbitration_ratio_gain; })},
      {"max_arbitration_gap_s",
       Set<double>([](O& o) -> double& { return o.slam.tracker.max_arbitration_gap_s; })},
      {"max_gyro_chi2", Set<double>([](O& o) -> double& { return o.slam.tracker.max_gyro_chi2; })},
      {"max_odometry_chi2",
       Set<double>([](O& o) -> double& { return o.slam.tracker.max_odometry_chi2; })},
      {"landmarks", Set<bool>([](O& o) -> bool& { return o.slam.landmarks; })},
      {"max_landmark_loop_chi2",
       Set<double>([](O& o) -> double& { return o.slam.max_landmark_loop_chi2; })},
      {"landmark_max_radius_spread_m",
       Set<double>([](O& o) -> double& { return o.slam.landmark_map.max_graph_radius_spread_m; })},
      {"landmark_max_rocking_rad",
       Set<double>([](O& o) -> double& { return o.slam.landmark_max_rocking_rad; })},
      {"landmark_rocking_window_s",
       Set<double>([](O& o) -> double& { return o.slam.landmark_rocking_window_s; })},
      {"landmark_min_inliers",
       Set<std::size_t>([](O& o) -> std::size_t& { return o.slam.landmark_map.min_inliers; })},
      {"match_sigma_floor_m",
       Set<double>([](O& o) -> double& { return o.slam.tracker.match_sigma_floor_m; })},
      {"match_sigma_floor_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.match_sigma_floor_rad; })},
      {"max_large_turn_correction_rad",
       Set<double>([](O& o) -> double& { return o.slam.tracker.max_large_turn_correction_rad; })},
      {"rgbd", Set<bool>([](O& o) -> bool& { return o.rgbd; })},
      {"rgbd_features", SetAligners<RgbdFeatures>({{"orb", RgbdFeatures::kOrb},
                                                   {"sift", RgbdFeatures::kSift},
                                                   {"akaze", RgbdFeatures::kAkaze}},
                                                  &RgbdAlignerOptions::features)},
      {"rgbd_rejection",
       SetAligners<PairRejection>({{"histogram", PairRejection::kCircularHistogram},
                                   {"ransac", PairRejection::kRansac},
                                   {"none", PairRejection::kNone}},
                                  &RgbdAlignerOptions::rejection)},
      {"rgbd_ratio_slack",
       Set<double>([](O& o) -> double& { return o.slam.tracker.rgbd_ratio_slack; })},
      {"rgbd_key_frame_distance_m",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.key_frame_distance_m; })},
      {"rgbd_key_frame_angle_rad",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.key_frame_angle_rad; })},
      {"rgbd_loops", Set<bool>([](O& o) -> bool& { return o.rgbd_tracker.loops; })},
      {"rgbd_loop_min_path_separation_m",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.loop_min_path_separation_m; })},
      {"rgbd_loop_search_radius_m",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.loop_search_radius_m; })},
      {"rgbd_loop_min_confidence",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.loop_min_confidence; })},
      {"rgbd_search_radius_m",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.search_radius_m; })},
      {"rgbd_min_confidence",
       Set<double>([](O& o) -> double& { return o.rgbd_tracker.min_confidence; })},
      {"rgbd_max_features", SetAligners(&RgbdAlignerOptions::max_features)},
      {"rgbd_orb_fast_threshold", SetAligners(&RgbdAlignerOptions::orb_fast_threshold)},
      {"key_frame_translation_m", Set<double>([](O& o) -> double& {
         return o.slam.tracker.key_frames.translation_threshold_m;
       })},
      {"key_frame_rotation_rad", Set<double>([](O& o) -> double& {
         return o.slam.tracker.key_frames.rotation_threshold_rad;
       })},
      {"local_window_key_frames", Set<std::size_t>([](O& o) -> std::size_t& {
         return o.slam.tracker.key_frames.local_window;
       })},
      {"loop_closure", Set<bool>([](O& o) -> bool& { return o.slam.loop_closure; })},
      {"loop_search_radius_m",
       Set<double>([](O& o) -> double& { return o.slam.loops.search_radius_m; })},
      {"loop_min_path_separation_m",
       Set<double>([](O& o) -> double& { return o.slam.loops.min_path_separation_m; })},
      {"loop_submap_half_window",
       Set<std::size_t>([](O& o) -> std::size_t& { return o.slam.loops.submap_half_window; })},
      {"loop_min_matching_ratio",
       Set<double>([](O& o) -> double& { return o.slam.loops.min_matching_ratio; })},
      {"loop_max_rms_residual_m",
       Set<double>([](O& o) -> double& { return o.slam.loops.max_rms_residual_m; })},
      {"loop_max_weakest_sigma_m",
       Set<double>([](O& o) -> double& { return o.slam.loops.max_weakest_sigma_m; })},
      {"loop_max_gyro_disagreement_rad",
       Set<double>([](O& o) -> double& { return o.slam.loops.max_gyro_disagreement_rad; })},
      {"loop_max_gyro_disagreement_rad_per_s",
       Set<double>([](O& o) -> double& { return o.slam.loops.max_gyro_disagreement_rad_per_s; })},
      {"loop_cooldown_key_frames",
       Set<std::size_t>([](O& o) -> std::size_t& { return o.slam.loop_cooldown_key_frames; })},
      {"loop_loss_scale",
       Set<double>([](O& o) -> double& { return o.slam.graph.loop_loss_scale; })},
      {"edge_sigma_floor_m",
       Set<double>([](O& o) -> double& { return o.slam.edge_sigma_floor_m; })},
      {"edge_sigma_floor_rad",
       Set<double>([](O& o) -> double& { return o.slam.edge_sigma_floor_rad; })},
      {"gyro_edge_sigma_floor_rad",
       Set<double>([](O& o) -> double& { return o.slam.gyro_edge_sigma_floor_rad; })},
      {"soft_edge_sigma_floor_rad",
       Set<double>([](O& o) -> double& { return o.slam.soft_edge_sigma_floor_rad; })},
      {"gyro_turn_sigma_rad_per_sqrt_s",
       Set<double>([](O& o) -> double& { return o.slam.gyro_turn_sigma_rad_per_sqrt_s; })},
      {"max_final_loop_chi2",
       Set<double>([](O& o) -> double& { return o.slam.max_final_loop_chi2; })},
      {"max_loop_residual_m",
       Set<double>([](O& o) -> double& { return o.slam.max_loop_residual_m; })},
      {"loop_consistency_max_stretch_m",
       Set<double>([](O& o) -> double& { return o.slam.loop_consistency.max_stretch_m; })},
      {"loop_consistency_max_disagreement_m",
       Set<double>([](O& o) -> double& { return o.slam.loop_consistency.max_disagreement_m; })},
      {"loop_consistency_max_disagreement_rad",
       Set<double>([](O& o) -> double& { return o.slam.loop_consistency.max_disagreement_rad; })},
      {"scan_alignment",
       SetChoice<AlignmentMode>({{"auto", AlignmentMode::kAuto},
                                 {"on", AlignmentMode::kOn},
                                 {"off", AlignmentMode::kOff}},
                                [](O& o) -> AlignmentMode& { return o.slam.alignment_mode; })},
      {"scan_refinement", Set<bool>([](O& o) -> bool& { return o.slam.refine_scans; })},
      {"alignment_pair_radius_m",
       Set<double>([](O& o) -> double& { return o.slam.alignment.pair_radius_m; })},
      {"alignment_normal_gap_per_m",
       Set<double>([](O& o) -> double& { return o.slam.alignment.normals.gap_per_m; })},
      {"alignment_point_sigma_m",
       Set<double>([](O& o) -> double& { return o.slam.alignment.point_sigma_m; })},
      {"alignment_revisit_pairs",
       Set<std::size_t>([](O& o) -> std::size_t& { return o.slam.alignment.max_revisit_pairs; })},
      {"alignment_max_correspondence_distances_m",
       Set<std::vector<double>>([](O& o) -> std::vector<double>& {
         return o.slam.alignment.max_correspondence_distances_m;
       })},
      {"map_cell_size_m", Set<double>([](O& o) -> double& { return o.slam.grid.cell_size_m; })},
      {"map_max_range_m", Set<double>([](O& o) -> double& { return o.slam.map_max_range_m; })},
  };
  return setters;
}

}  // namespace

std::vector<std::string> OptionsFileKeys() { return OptionKeys(Setters()); }

void ApplyOptionsFile(const std::filesystem::path& path, ReconstructionOptions* options) {
  littermap::ApplyOptionsFile(path, Setters(), options);
}

}  // namespace littermap::reconstruct
