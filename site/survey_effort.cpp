#include "site/survey_effort.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace littermap::site {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// Marks the cells whose centres lie in the sector seen from camera pose T_site_camera.
void MarkSector(const heatmap::GridGeometry& grid, const PlanarPose& camera,
                const FootprintSector& sector, std::vector<std::uint8_t>& observed) {
  const double far = sector.far_m;
  const int c0 = std::max(
      0, static_cast<int>(std::floor((camera.x_m - far - grid.min_x_m) / grid.cell_size_m)));
  const int c1 =
      std::min(grid.width - 1,
               static_cast<int>(std::floor((camera.x_m + far - grid.min_x_m) / grid.cell_size_m)));
  const int r0 = std::max(
      0, static_cast<int>(std::floor((grid.max_y_m - camera.y_m - far) / grid.cell_size_m)));
  const int r1 =
      std::min(grid.height - 1,
               static_cast<int>(std::floor((grid.max_y_m - camera.y_m + far) / grid.cell_size_m)));
  const double cos_half = std::cos(sector.half_fov_rad);
  const double heading_x = std::cos(camera.theta_rad);
  const double heading_y = std::sin(camera.theta_rad);
  const double near2 = sector.near_m * sector.near_m;
  const double far2 = far * far;
  for (int r = r0; r <= r1; ++r) {
    const double dy = grid.CellCenterY(r) - camera.y_m;
    for (int c = c0; c <= c1; ++c) {
      const double dx = grid.CellCenterX(c) - camera.x_m;
      const double d2 = dx * dx + dy * dy;
      if (d2 < near2 || d2 > far2) continue;
      // Inside the field of view: the bearing's cosine to the heading exceeds cos(fov/2).
      if (dx * heading_x + dy * heading_y < cos_half * std::sqrt(d2)) continue;
      observed[static_cast<std::size_t>(r) * grid.width + c] = 1;
    }
  }
}

}  // namespace

FootprintSector GroundSector(const CameraFootprintOptions& options) {
  if (options.horizontal_fov_deg <= 0 || options.horizontal_fov_deg >= 180 ||
      options.vertical_fov_deg <= 0 || options.vertical_fov_deg >= 180 ||
      options.mount_height_m <= 0 || options.max_detection_range_m <= 0 ||
      options.pose_step_m <= 0 || options.pose_step_deg <= 0) {
    throw UsageError(
        "camera footprint: fields of view must be in (0, 180) deg and mount "
        "height, detection range and pose steps positive");
  }
  const double half_v = options.vertical_fov_deg * kDegToRad / 2.0;
  const double pitch = options.mount_pitch_down_deg * kDegToRad;
  const double lower_ray = pitch + half_v;  // steepest ray below the horizon
  const double upper_ray = pitch - half_v;  // shallowest ray
  if (lower_ray <= 0.0) {
    throw UsageError("camera footprint: the camera looks above the horizon and sees no ground");
  }
  FootprintSector sector;
  sector.half_fov_rad = options.horizontal_fov_deg * kDegToRad / 2.0;
  sector.near_m =
      lower_ray >= std::numbers::pi / 2 ? 0.0 : options.mount_height_m / std::tan(lower_ray);
  sector.far_m = options.max_detection_range_m;
  if (upper_ray > 0)
    sector.far_m = std::min(sector.far_m, options.mount_height_m / std::tan(upper_ray));
  if (sector.far_m <= sector.near_m) {
    throw UsageError("camera footprint: the camera sees no ground within detection range");
  }
  return sector;
}

RunCoverage CoverRun(const heatmap::GridGeometry& grid, std::span<const PlanarPose> trajectory,
                     const CameraFootprintOptions& options) {
  const FootprintSector sector = GroundSector(options);
  const PlanarPose T_base_camera{options.mount_x_m, options.mount_y_m,
                                 options.mount_yaw_deg * kDegToRad};
  RunCoverage coverage;
  coverage.observed.assign(grid.size(), 0);
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const PlanarPose& a = trajectory[i];
    const PlanarPose& b = i + 1 < trajectory.size() ? trajectory[i + 1] : a;
    const double turn = std::abs(WrapAngle(b.theta_rad - a.theta_rad));
    const double travel = std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
    const int steps = std::max(
        1, static_cast<int>(std::ceil(std::max(travel / options.pose_step_m,
                                               turn / (options.pose_step_deg * kDegToRad)))));
    const int last = i + 1 < trajectory.size() ? steps - 1 : 0;  // b is the next pose's first
    for (int s = 0; s <= last; ++s) {
      const double t = static_cast<double>(s) / steps;
      const PlanarPose pose{a.x_m + t * (b.x_m - a.x_m), a.y_m + t * (b.y_m - a.y_m),
                            a.theta_rad + t * WrapAngle(b.theta_rad - a.theta_rad)};
      MarkSector(grid, Compose(pose, T_base_camera), sector, coverage.observed);
      ++coverage.footprints;
    }
  }
  coverage.observed_cells = static_cast<std::size_t>(
      std::count(coverage.observed.begin(), coverage.observed.end(), std::uint8_t{1}));
  coverage.observed_area_m2 = static_cast<double>(coverage.observed_cells) * grid.cell_area_m2();
  return coverage;
}

void AddCoverage(heatmap::Raster& effort, const RunCoverage& coverage) {
  if (coverage.observed.size() != effort.values.size()) {
    throw UsageError("survey effort: coverage and effort rasters differ in size");
  }
  for (std::size_t i = 0; i < coverage.observed.size(); ++i)
    effort.values[i] += coverage.observed[i];
}

}  // namespace littermap::site
