#include "eval/map_sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "eval/text_format.hpp"

namespace littermap::eval {

void MapSharpnessOptions::Validate() const {
  if (!(cell_size_m > 0) || !(max_range_m > 0) || !(max_time_difference_s >= 0)) {
    throw UsageError(
        "map sharpness: cell_size_m and max_range_m must be > 0, max_time_difference_s >= 0");
  }
}

MapSharpness MeasureMapSharpness(const std::vector<LaserScan>& scans,
                                 const PlanarPose& T_base_laser,
                                 const std::vector<StampedPose>& trajectory,
                                 const MapSharpnessOptions& options) {
  options.Validate();
  if (trajectory.empty()) throw BadInputError("map sharpness: the trajectory has no poses");
  std::vector<TimestampNs> stamps_ns;
  for (const LaserScan& scan : scans) stamps_ns.push_back(scan.stamp_ns);
  const std::vector<std::optional<PlanarPose>> poses =
      PlanarPosesAt(trajectory, stamps_ns, options.max_time_difference_s);

  MapSharpness sharpness;
  sharpness.scans = scans.size();
  std::unordered_set<std::uint64_t> cells;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const LaserScan& scan = scans[i];
    const std::optional<PlanarPose>& T_world_base = poses[i];
    if (!T_world_base) continue;
    ++sharpness.scans_drawn;
    const PlanarPose T_world_laser = Compose(*T_world_base, T_base_laser);
    for (std::size_t beam = 0; beam < scan.ranges_m.size(); ++beam) {
      const double range_m = scan.ranges_m[beam];
      if (!scan.IsValid(beam) || !(range_m <= options.max_range_m)) continue;
      const double angle_rad = T_world_laser.theta_rad + scan.AngleOf(beam);
      const double x =
          std::floor((T_world_laser.x_m + range_m * std::cos(angle_rad)) / options.cell_size_m);
      const double y =
          std::floor((T_world_laser.y_m + range_m * std::sin(angle_rad)) / options.cell_size_m);
      // Two 32-bit cell indices in one key (±2^31 cells of 5 cm reach 100,000 km); a pose
      // beyond that, or NaN, draws nothing.
      constexpr double kLimit = 2147483647.0;
      if (!(std::abs(x) < kLimit && std::abs(y) < kLimit)) continue;
      const auto ix = static_cast<std::uint32_t>(static_cast<std::int32_t>(x));
      const auto iy = static_cast<std::uint32_t>(static_cast<std::int32_t>(y));
      cells.insert((static_cast<std::uint64_t>(ix) << 32) | iy);
      ++sharpness.echoes_drawn;
    }
  }
  if (sharpness.scans_drawn == 0) {
    char within[64];
    std::snprintf(within, sizeof within, "%g s", options.max_time_difference_s);
    throw BadInputError(std::string("map sharpness: no scan has a trajectory pose within ") +
                        within + "; the trajectory is not of these scans");
  }
  sharpness.occupied_cells = cells.size();
  return sharpness;
}

std::string ToJson(const std::vector<std::string>& names, const std::vector<MapSharpness>& maps,
                   const MapSharpnessOptions& options) {
  nlohmann::ordered_json json;
  json["cell_size_m"] = options.cell_size_m;
  json["max_range_m"] = options.max_range_m;
  json["trajectories"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < maps.size(); ++i) {
    json["trajectories"].push_back({{"trajectory", names.at(i)},
                                    {"scans", maps[i].scans},
                                    {"scans_drawn", maps[i].scans_drawn},
                                    {"echoes_drawn", maps[i].echoes_drawn},
                                    {"occupied_cells", maps[i].occupied_cells}});
  }
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ToText(const std::vector<std::string>& names, const std::vector<MapSharpness>& maps,
                   const MapSharpnessOptions& options) {
  std::string text;
  AppendFormat(text, "occupied %.0f cm cells of the echoes within %.1f m (fewer: sharper map)\n",
               100 * options.cell_size_m, options.max_range_m);
  AppendFormat(text, "%12s %9s %12s %12s  %s\n", "cells", "vs first", "echoes", "scans",
               "trajectory");
  for (std::size_t i = 0; i < maps.size(); ++i) {
    AppendFormat(text, "%12zu %8.1f%% %12zu %5zu/%-6zu  %s\n", maps[i].occupied_cells,
                 100.0 * static_cast<double>(maps[i].occupied_cells) /
                     static_cast<double>(maps.front().occupied_cells),
                 maps[i].echoes_drawn, maps[i].scans_drawn, maps[i].scans, names.at(i).c_str());
  }
  text.pop_back();  // the caller ends the last line, as after ToJson
  return text;
}

}  // namespace littermap::eval
