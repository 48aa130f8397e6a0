#include "detect/options_file.hpp"

#include "core/options_file.hpp"

namespace littermap::detect {
namespace {

struct DetectionTuning {
  RunObjectsOptions objects;
  FusionOptions fusion;
  void Validate() const {
    objects.Validate();
    fusion.Validate();
  }
};

using O = DetectionTuning;

template <typename T, typename Field>
OptionSetter<O> Set(Field field) {
  return SetOption<T, O>(field);
}

// The depth noise model is one for the ground fit and the texture refinement.
OptionSetter<O> SetDepthNoise() {
  return [](const YAML::Node& node, O* o) {
    o->objects.segmentation.ground.depth_noise_per_m2 =
        o->objects.segmentation.texture.depth_noise_per_m2 = OptionValue<double>(node);
  };
}

const OptionSetters<O>& Setters() {
  static const OptionSetters<O> setters = {
      // The resolution of the frame's geometry.
      {"geometry_step_px",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.geometry_step_px; })},
      // The organized cloud and its normals.
      {"min_depth_m",
       Set<float>([](O& o) -> float& { return o.objects.segmentation.cloud.min_depth_m; })},
      {"max_depth_m",
       Set<float>([](O& o) -> float& { return o.objects.segmentation.cloud.max_depth_m; })},
      {"fals_window_px",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.cloud.fals_window_px; })},
      {"normal_smoothing_px",
       Set<float>([](O& o) -> float& { return o.objects.segmentation.cloud.normal_smoothing_px; })},
      {"max_depth_change_factor", Set<float>([](O& o) -> float& {
         return o.objects.segmentation.cloud.max_depth_change_factor;
       })},
      {"normal_method",
       SetOptionChoice<O>(
           std::map<std::string, NormalMethod>{
               {"covariance", NormalMethod::kCovariance},
               {"average_3d_gradient", NormalMethod::kAverage3dGradient},
               {"simple_3d_gradient", NormalMethod::kSimple3dGradient},
               {"average_depth_change", NormalMethod::kAverageDepthChange},
               {"fals", NormalMethod::kFals}},
           [](O& o) -> NormalMethod& { return o.objects.segmentation.cloud.normal_method; })},
      {"normal_step_px",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.cloud.normal_step_px; })},
      // Connected components.
      {"max_normal_angle_deg", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.components.max_normal_angle_deg;
       })},
      {"colour_normal_angle_deg", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.components.colour_normal_angle_deg;
       })},
      {"max_colour_distance", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.components.max_colour_distance;
       })},
      {"max_gap_m",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.components.max_gap_m; })},
      {"max_gap_per_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.components.max_gap_per_m;
       })},
      // The ground.
      {"ground_max_tilt_deg",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.ground.max_tilt_deg; })},
      {"ground_max_level_offset_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.ground.max_level_offset_m;
       })},
      {"ground_min_component_points",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.ground.min_component_points; })},
      {"ground_min_joined_points",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.ground.min_joined_points; })},
      {"ground_max_join_residual_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.ground.max_join_residual_m;
       })},
      {"ground_inlier_band_m",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.ground.inlier_band_m; })},
      {"depth_noise_per_m2", SetDepthNoise()},
      // Texture learning and the graph cut.
      {"gmm_components",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.texture.gmm_components; })},
      {"max_training_pixels",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.texture.max_training_pixels; })},
      {"min_ground_band_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.texture.min_ground_band_m;
       })},
      {"min_object_height_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.texture.min_object_height_m;
       })},
      {"max_depth_below_ground_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.texture.max_depth_below_ground_m;
       })},
      {"colour_anomaly_log_ratio", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.texture.colour_anomaly_log_ratio;
       })},
      {"region_margin_px",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.texture.region_margin_px; })},
      {"smoothness_weight", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.texture.smoothness_weight;
       })},
      {"height_weight",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.texture.height_weight; })},
      {"min_nonground_training_pixels", Set<int>([](O& o) -> int& {
         return o.objects.segmentation.texture.min_nonground_training_pixels;
       })},
      // Objects.
      {"min_pixels",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.objects.min_pixels; })},
      {"min_depth_points",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.objects.min_depth_points; })},
      {"min_size_m",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.objects.min_size_m; })},
      {"max_size_m",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.objects.max_size_m; })},
      {"max_height_m",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.objects.max_height_m; })},
      {"box_margin",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.objects.box_margin; })},
      {"min_box_margin_px",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.objects.min_box_margin_px; })},
      {"refine_objects",
       Set<bool>([](O& o) -> bool& { return o.objects.segmentation.objects.refine; })},
      {"uncertain_fringe_px",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.objects.uncertain_fringe_px; })},
      {"max_refine_pixels",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.objects.max_refine_pixels; })},
      {"split_objects",
       Set<bool>([](O& o) -> bool& { return o.objects.segmentation.objects.split; })},
      {"split_max_gap_m",
       Set<double>([](O& o) -> double& { return o.objects.segmentation.objects.split_max_gap_m; })},
      {"split_max_gap_per_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.objects.split_max_gap_per_m;
       })},
      {"split_min_height_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.objects.split_min_height_m;
       })},
      {"split_max_base_m", Set<double>([](O& o) -> double& {
         return o.objects.segmentation.objects.split_max_base_m;
       })},
      {"split_max_parts",
       Set<int>([](O& o) -> int& { return o.objects.segmentation.objects.split_max_parts; })},
      // Frames and items.
      {"every", Set<std::size_t>([](O& o) -> std::size_t& { return o.objects.every; })},
      {"max_pose_gap_s", Set<double>([](O& o) -> double& { return o.objects.max_pose_gap_s; })},
      {"association_radius_m",
       Set<double>([](O& o) -> double& { return o.fusion.association_radius_m; })},
      {"min_views", Set<int>([](O& o) -> int& { return o.fusion.min_views; })},
      {"min_seen_share", Set<double>([](O& o) -> double& { return o.fusion.min_seen_share; })},
      {"class_views", Set<int>([](O& o) -> int& { return o.fusion.class_views; })},
      {"min_litter_probability",
       Set<double>([](O& o) -> double& { return o.fusion.min_litter_probability; })},
  };
  return setters;
}

}  // namespace

std::vector<std::string> OptionsFileKeys() { return OptionKeys(Setters()); }

void ApplyOptionsFile(const std::filesystem::path& path, RunObjectsOptions* objects,
                      FusionOptions* fusion) {
  DetectionTuning tuning{*objects, *fusion};
  littermap::ApplyOptionsFile(path, Setters(), &tuning);
  *objects = tuning.objects;
  *fusion = tuning.fusion;
}

}  // namespace littermap::detect
