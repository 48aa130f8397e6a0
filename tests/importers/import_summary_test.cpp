// The lines `littermap import` prints: counts, beams, noisy odometry, what was not imported and
// the reference trajectory.

#include "importers/import_summary.hpp"

#include <gtest/gtest.h>

namespace littermap::importers {
namespace {

CarmenImportResult IntelResult() {
  CarmenImportResult result;
  result.scan_count = 910;
  result.odometry_count = 910;
  result.beam_count_min = result.beam_count_max = 180;
  result.duration_s = 2650.94;
  result.skipped_types = {{"NEFF", 910}};
  result.odom_records_ignored = 14541;
  result.reference_poses = 910;
  return result;
}

TEST(ImportSummary, CarmenSaysWhatWasWrittenAndWhatWasNot) {
  EXPECT_EQ(ImportSummary("out/intel", CarmenImportOptions{}, IntelResult()),
            "wrote out/intel: 910 scans (180 beams), 910 odometry, 2650.9 s (not imported: 910 "
            "NEFF, 14541 ODOM)\n");
}

TEST(ImportSummary, CarmenNamesTheNoiseSeedTheBeamRangeAndTheReference) {
  CarmenImportOptions options;
  options.odometry_noise_seed = 3;
  options.reference_path = "intel.tum";
  CarmenImportResult result = IntelResult();
  result.noisy_odometry = true;
  result.beam_count_max = 361;
  result.skipped_types.clear();
  result.odom_records_ignored = 0;
  EXPECT_EQ(ImportSummary("intel", options, result),
            "wrote intel: 910 scans (180-361 beams), 910 odometry (noisy, seed 3), 2650.9 s\n"
            "wrote intel.tum: 910 reference poses\n");
}

TEST(ImportSummary, TumSaysTheCameraAndWhereItCameFrom) {
  TumImportResult result;
  result.camera = TumCamera::kFreiburg2;
  result.camera_from_directory = true;
  result.pairs_written = 2;
  result.duration_s = 0.036;
  result.reference_poses = 2;
  TumImportOptions options;
  options.reference_path = "tum.tum";
  EXPECT_EQ(ImportSummary("tum", options, result),
            "wrote tum: 2 colour, 2 depth, 2 camera_info (freiburg2, from the directory name), "
            "0.0 s\nwrote tum.tum: 2 reference poses\n");
  result.camera = TumCamera::kFreiburg3;
  result.camera_from_directory = false;
  EXPECT_EQ(ImportSummary("tum", TumImportOptions{}, result),
            "wrote tum: 2 colour, 2 depth, 2 camera_info (freiburg3), 0.0 s\n");
}

}  // namespace
}  // namespace littermap::importers
