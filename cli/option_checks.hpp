#pragma once
// Checks for option values that CLI11 does not have: a finite number in a range (CLI::Range lets
// NaN through), a whole number in a range (CLI11 clamps 2^64 and wraps -1 into an unsigned), a
// file name with one of the extensions littermap can write, and inputs that must exist (as bad
// input, exit 2, like a file that turns out unreadable later; CLI11's checks make it a usage
// error).

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/failure.hpp"

namespace littermap::cli {

// Limits of the options that size a computation: beyond them a run takes hours or all memory.
inline constexpr double kMinCellSizeM = 0.05;  // heatmap/report --cell-size
inline constexpr double kMaxCellSizeM = 100.0;
inline constexpr double kMinBandwidthM = 0.1;  // heatmap/report --bandwidth
inline constexpr double kMaxBandwidthM = 100.0;
inline constexpr int kMaxHotspots = 1000;              // heatmap/report --hotspots
inline constexpr int kMaxHotspotMinItems = 1000;       // heatmap/report/survey --hotspot-min-items
inline constexpr double kMaxDurationS = 86400;         // simulate/capture --duration: a day
inline constexpr std::size_t kMaxFrameStep = 100000;   // detect/train/survey --every
inline constexpr double kMaxSiteCoordinateM = 100000;  // ingest --initial/--transform: 100 km

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

// A whole number from min to max, written in decimal and nothing else ("-1" is not an unsigned
// number, "1e3" and "2.5" are not whole numbers, 2^64 does not fit).
template <typename Integer>
CLI::Validator WholeNumber(Integer min, Integer max) {
  const std::string range = std::to_string(min) + " to " + std::to_string(max);
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        Integer value{};
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc() || stop != end || value < min || value > max) {
          return "must be a whole number from " + range + ", not '" + text + "'";
        }
        return "";
      },
      "INTEGER in " + range);
}

// A random seed: any 64-bit unsigned number.
inline CLI::Validator Seed() {
  return WholeNumber<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max());
}

enum class InputKind { kFile, kFolder, kFileOrFolder };

// An input path that must exist and be of its kind. Throws littermap's FileFailure (which
// CLI11 passes through its parser): "PATH: cannot read: No such file or directory".
inline CLI::Validator ExistingInput(InputKind kind) {
  return CLI::Validator(
      [kind](std::string& text) -> std::string {
        const std::filesystem::path path(text);
        std::error_code error;
        const std::filesystem::file_status status = std::filesystem::status(path, error);
        if (error) throw FileFailure(path, "cannot read", error.value());
        if (!std::filesystem::exists(status)) throw FileFailure(path, "cannot read", ENOENT);
        const bool folder = std::filesystem::is_directory(status);
        if (kind == InputKind::kFile && folder) throw FileFailure(path, "cannot read", EISDIR);
        if (kind == InputKind::kFolder && !folder) throw FileFailure(path, "cannot read", ENOTDIR);
        return "";
      },
      kind == InputKind::kFile ? "FILE" : (kind == InputKind::kFolder ? "DIR" : "PATH"));
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
