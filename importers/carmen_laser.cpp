#include "importers/carmen_laser.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <vector>

#include "core/error.hpp"

namespace littermap::importers {

CarmenBeamGeometry CarmenBeams(const CarmenLaserRecord& record) {
  if (record.has_geometry) return {record.start_angle_rad, record.angular_resolution_rad};
  const std::size_t n = record.ranges_m.size();
  const double field_of_view = std::numbers::pi;
  // Odd counts include both ends of the 180° field of view; even counts stop one step short.
  double spacing = 0;
  if (n % 2 == 1 && n > 1) {
    spacing = field_of_view / static_cast<double>(n - 1);
  } else if (n > 0) {
    spacing = field_of_view / static_cast<double>(n);
  }
  return {-field_of_view / 2, spacing};
}

namespace {

double NoReturnRange(std::span<const CarmenLaserRecord> scans, const CarmenRangeOptions& options) {
  if (options.no_return_range_m > 0) return options.no_return_range_m;
  const bool explicit_maximum = std::all_of(scans.begin(), scans.end(), [](const auto& scan) {
    return scan.has_geometry && scan.max_range_m > 0;
  });
  if (explicit_maximum && !scans.empty()) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& scan : scans) smallest = std::min(smallest, scan.max_range_m);
    return smallest;
  }
  float largest = 0;
  for (const auto& scan : scans) {
    for (const float range : scan.ranges_m) largest = std::max(largest, range);
  }
  const double band =
      std::max(options.no_return_band_min_m, options.no_return_band_fraction * largest);
  return std::max(static_cast<double>(largest) - band, options.range_min_m);
}

}  // namespace

CarmenRangeLimits CarmenRanges(std::span<const CarmenLaserRecord> scans,
                               const CarmenRangeOptions& options) {
  if (!(options.range_min_m >= 0) || !(options.no_return_range_m >= 0) ||
      !(options.no_return_band_fraction >= 0) || !(options.no_return_band_min_m >= 0)) {
    throw UsageError("CARMEN range options must be non-negative");
  }
  CarmenRangeLimits limits;
  limits.range_min_m = static_cast<float>(options.range_min_m);
  limits.no_return_range_m = NoReturnRange(scans, options);
  // Rounding to float is monotonic, so every reading >= the no-return range (as float) is
  // strictly greater than the next float below it.
  const float no_return = static_cast<float>(limits.no_return_range_m);
  limits.range_max_m = std::nextafter(no_return, 0.0f);
  for (const auto& scan : scans) {
    limits.no_return_readings += static_cast<std::uint64_t>(std::count_if(
        scan.ranges_m.begin(), scan.ranges_m.end(), [&](float r) { return r >= no_return; }));
  }
  return limits;
}

msg::LaserScan ToLaserScan(const CarmenLaserRecord& record, const msg::Header& header,
                           const CarmenRangeLimits& limits) {
  const CarmenBeamGeometry beams = CarmenBeams(record);
  msg::LaserScan scan;
  scan.header = header;
  scan.angle_min = static_cast<float>(beams.angle_min_rad);
  scan.angle_increment = static_cast<float>(beams.angle_increment_rad);
  const std::size_t steps = record.ranges_m.empty() ? 0 : record.ranges_m.size() - 1;
  scan.angle_max = static_cast<float>(beams.angle_min_rad +
                                      beams.angle_increment_rad * static_cast<double>(steps));
  scan.range_min = limits.range_min_m;
  scan.range_max = limits.range_max_m;
  scan.ranges = record.ranges_m;
  return scan;
}

namespace {

struct OffsetSpread {
  double distance_m = 0;
  double angle_rad = 0;
};

OffsetSpread SpreadAround(const std::vector<PlanarPose>& offsets, const PlanarPose& center) {
  OffsetSpread spread;
  for (const auto& offset : offsets) {
    spread.distance_m =
        std::max(spread.distance_m, std::hypot(offset.x_m - center.x_m, offset.y_m - center.y_m));
    spread.angle_rad =
        std::max(spread.angle_rad, std::abs(WrapAngle(offset.theta_rad - center.theta_rad)));
  }
  return spread;
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

PlanarPose MedianOffset(const std::vector<PlanarPose>& offsets) {
  std::vector<double> x, y, theta;
  for (const auto& offset : offsets) {
    x.push_back(offset.x_m);
    y.push_back(offset.y_m);
    theta.push_back(offset.theta_rad);
  }
  return {Median(x), Median(y), Median(theta)};
}

// Reads robot_frontlaser_{offset,side_offset,angular_offset}; false when none is there.
bool ParamOffset(const CarmenLog& log, PlanarPose* offset) {
  bool present = false;
  const auto read = [&](const char* name, double* value) {
    const auto it = log.params.find(name);
    if (it == log.params.end()) return;
    char* end = nullptr;
    const double parsed = std::strtod(it->second.c_str(), &end);
    if (end == it->second.c_str() || *end != '\0' || !std::isfinite(parsed)) {
      throw BadInputError(std::string("PARAM ") + name + ": '" + it->second + "' is not a number");
    }
    *value = parsed;
    present = true;
  };
  read("robot_frontlaser_offset", &offset->x_m);
  read("robot_frontlaser_side_offset", &offset->y_m);
  read("robot_frontlaser_angular_offset", &offset->theta_rad);
  return present;
}

std::string Describe(const PlanarPose& pose) {
  char text[96];
  std::snprintf(text, sizeof text, "(x %.4f m, y %.4f m, theta %.4f rad)", pose.x_m, pose.y_m,
                pose.theta_rad);
  return text;
}

}  // namespace

LaserMounting EstimateLaserMounting(const CarmenLog& log, const LaserMountingOptions& options) {
  std::vector<PlanarPose> offsets;
  offsets.reserve(log.scans.size());
  for (const auto& scan : log.scans) offsets.push_back(Between(scan.robot_pose, scan.laser_pose));

  LaserMounting mounting;
  mounting.param_present = ParamOffset(log, &mounting.param_offset);
  const PlanarPose median = MedianOffset(offsets);
  const OffsetSpread spread = SpreadAround(offsets, median);
  mounting.constant =
      spread.distance_m <= options.tolerance_m && spread.angle_rad <= options.tolerance_rad;
  // The poses are what the map is drawn from, so a constant offset in them wins over the PARAM
  // (freiburg-101 and freiburg-campus say -0.04 m, but their corrected laser and robot poses
  // coincide, and the map drawn with the PARAM's offset is 10 % less sharp).
  const bool use_param = !mounting.constant && mounting.param_present;
  mounting.source = use_param ? LaserMounting::Source::kParam : LaserMounting::Source::kPoses;
  mounting.T_base_laser = use_param ? mounting.param_offset : median;
  const OffsetSpread chosen = SpreadAround(offsets, mounting.T_base_laser);
  mounting.spread_m = chosen.distance_m;
  mounting.spread_rad = chosen.angle_rad;
  const OffsetSpread param_gap = SpreadAround({mounting.param_offset}, median);
  if (!mounting.constant) {
    char text[96];
    std::snprintf(text, sizeof text, "%.4f m and %.4f rad", spread.distance_m, spread.angle_rad);
    mounting.note = std::string("the laser offset in the robot frame varies between scans by ") +
                    "up to " + text + "; using " +
                    (use_param ? "the PARAM offset " : "the median offset ") +
                    Describe(mounting.T_base_laser);
  } else if (mounting.param_present && (param_gap.distance_m > options.tolerance_m ||
                                        param_gap.angle_rad > options.tolerance_rad)) {
    mounting.note = "PARAM robot_frontlaser_offset gives the laser at " +
                    Describe(mounting.param_offset) + ", but every scan's poses put it at " +
                    Describe(median) + "; using the poses";
  }
  return mounting;
}

}  // namespace littermap::importers
