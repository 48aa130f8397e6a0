#pragma once
// Checks for option values that CLI11 does not have: a finite number in a range (CLI::Range lets
// NaN through), a file name with one of the extensions littermap can write.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace littermap::cli {

// Limits of the options that size a computation: beyond them a run takes hours or all memory.
inline constexpr double kMinCellSizeM = 0.05;  // heatmap/report --cell-size
inline constexpr double kMaxCellSizeM = 100.0;
inline constexpr double kMinBandwidthM = 0.1;  // heatmap/report --bandwidth
inline constexpr double kMaxBandwidthM = 100.0;
inline constexpr int kMaxHotspots = 1000;       // heatmap/report --hotspots
inline constexpr double kMaxDurationS = 86400;  // simulate/capture --duration: a day

inline CLI::Validator FiniteRange(double min, double max) {
  char range[96];
  std::snprintf(range, sizeof range, "%g to %g", min, max);
  return CLI::Validator(
      [min, max, text_range = std::string(range)](std::string& text) -> std::string {
        double value = 0;
        std::size_t used = 0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(value) || value < min ||
            value > max) {
          return "must be a finite number from " + text_range + ", not '" + text + "'";
        }
        return "";
      },
      "NUMBER in " + std::string(range));
}

inline CLI::Validator FileExtension(const std::vector<std::string>& extensions) {
  std::string list;
  for (const std::string& extension : extensions) list += (list.empty() ? "" : ", ") + extension;
  return CLI::Validator(
      [extensions, list](std::string& text) -> std::string {
        for (const std::string& extension : extensions) {
          if (text.size() > extension.size() && text.ends_with(extension)) return "";
        }
        return "'" + text + "' must end in " + list;
      },
      "FILE (" + list + ")");
}

}  // namespace littermap::cli
