#include "importers/import_summary.hpp"

#include <cstdio>

namespace littermap::importers {
namespace {

std::string Seconds(double seconds) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.1f s", seconds);
  return text;
}

std::string ReferenceLine(const std::filesystem::path& reference, std::uint64_t poses) {
  if (reference.empty()) return "";
  return "wrote " + reference.string() + ": " + std::to_string(poses) + " reference poses\n";
}

// " (not imported: 440 NEFF, 7814 ODOM)", or nothing when every record was imported.
std::string NotImported(const CarmenImportResult& result) {
  std::string text;
  for (const auto& [type, count] : result.skipped_types) {
    text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + type;
  }
  if (result.odom_records_ignored > 0) {
    text += (text.empty() ? "" : ", ") + std::to_string(result.odom_records_ignored) + " ODOM";
  }
  return text.empty() ? "" : " (not imported: " + text + ")";
}

}  // namespace

std::string ImportSummary(const std::filesystem::path& bag, const CarmenImportOptions& options,
                          const CarmenImportResult& result) {
  std::string beams = std::to_string(result.beam_count_min);
  if (result.beam_count_max != result.beam_count_min) {
    beams += "-" + std::to_string(result.beam_count_max);
  }
  std::string odometry = std::to_string(result.odometry_count) + " odometry";
  if (result.noisy_odometry) {
    odometry += " (noisy, seed " + std::to_string(options.odometry_noise_seed.value_or(0)) + ")";
  }
  return "wrote " + bag.string() + ": " + std::to_string(result.scan_count) + " scans (" + beams +
         " beams), " + odometry + ", " + Seconds(result.duration_s) + NotImported(result) + "\n" +
         ReferenceLine(options.reference_path, result.reference_poses);
}

std::string ImportSummary(const std::filesystem::path& bag, const TumImportOptions& options,
                          const TumImportResult& result) {
  const std::string pairs = std::to_string(result.pairs_written);
  return "wrote " + bag.string() + ": " + pairs + " colour, " + pairs + " depth, " + pairs +
         " camera_info (" + TumCameraName(result.camera) +
         (result.camera_from_directory ? ", from the directory name" : "") + "), " +
         Seconds(result.duration_s) + "\n" +
         ReferenceLine(options.reference_path, result.reference_poses);
}

}  // namespace littermap::importers
