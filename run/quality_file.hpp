#pragma once
// RUN_DIR/quality.json: how the reconstruction of a run went (stable key names, run/run_files.hpp).
// A SLAM run lists its scans, the routines that placed them, loop closures, landmarks, the final
// scan alignment and, with a camera, the RGB-D routine; a visual-odometry run ("mode":
// "visual-odometry", a bag without laser) its camera frames. Both end with the run time and the
// warnings. The site database keeps the file's text (db::RunRecord::reconstruction_quality).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace littermap::run {

struct LandmarkQuality {
  std::size_t in_graph = 0;
  std::size_t sightings = 0;
  std::size_t associated_by_tracking = 0;
  std::size_t loops_found = 0;
  std::size_t loops_accepted = 0;
  std::size_t loops_rejected = 0;
};

// The final alignment of the key frames' scans, when it ran.
struct ScanAlignmentQuality {
  std::size_t pairs = 0;
  std::size_t pairs_matched = 0;
  std::size_t correspondences = 0;
  int rounds = 0;
  double initial_cost = 0;
  double final_cost = 0;
};

// The RGB-D routine, when the bag had a camera.
struct RgbdQuality {
  std::size_t frames = 0;
  std::size_t key_frames = 0;
  std::size_t alignments = 0;
  std::size_t aligned = 0;
  std::size_t loop_alignments = 0;
  std::size_t loops_found = 0;
  std::size_t loops_accepted = 0;
  std::size_t loops_rejected = 0;
};

struct ReconstructionQuality {
  bool visual_odometry = false;
  // SLAM runs:
  std::size_t scans = 0;
  std::size_t scans_tracked = 0;
  std::size_t scans_without_echoes = 0;
  std::size_t ground_echoes_dropped = 0;
  std::size_t scans_moving_echo_filtered = 0;
  std::size_t moving_echoes_dropped = 0;
  std::size_t scans_given_up_to_moving_echoes = 0;
  std::size_t stamps_backwards = 0;
  std::size_t stamps_duplicate = 0;
  std::size_t odometry_missing = 0;
  std::size_t odometry_rejected = 0;
  std::size_t odometry_arbitrated_by_laser = 0;
  std::vector<std::pair<std::string, std::size_t>> routines;  // scans per routine, file order
  std::size_t loop_closures_found = 0;
  std::size_t loop_closures_accepted = 0;
  std::size_t loop_closures_rejected = 0;  // the five below together
  std::size_t loop_closures_rejected_match = 0;
  std::size_t loop_closures_rejected_disagreement = 0;
  std::size_t loop_closures_rejected_degenerate = 0;
  std::size_t loop_closures_rejected_after_optimisation = 0;
  std::size_t loop_closures_rejected_inconsistent = 0;  // disagreed with other loops
  // Accepted loops that confirmed a tentative match (each brings that match in too).
  std::size_t loop_closures_confirmed = 0;
  LandmarkQuality landmarks;
  std::size_t optimisations = 0;
  double final_cost = 0;
  std::optional<ScanAlignmentQuality> scan_alignment;
  std::optional<ScanAlignmentQuality> scan_refinement;  // every scan against the key frames
  std::optional<RgbdQuality> rgbd;
  // Visual-odometry runs:
  std::size_t frames = 0;
  std::size_t frames_tracked = 0;
  std::size_t segments = 0;
  // Both:
  std::size_t key_frames = 0;
  double run_time_s = 0;
  double scans_per_s = 0;  // frames per second ("frames_per_s") for visual odometry
  std::vector<std::string> warnings;
};

// The file's text: two-space indented JSON and a final newline.
std::string ToJson(const ReconstructionQuality& quality);

// None when the text is not a JSON object. Keys missing or not of their type read as zero or
// empty: older versions of littermap wrote fewer of them.
std::optional<ReconstructionQuality> QualityFromJson(std::string_view text);

// Throws UsageError if the file cannot be created, InternalError if writing fails.
void WriteQualityFile(const std::filesystem::path& file, const ReconstructionQuality& quality);

// Throws BadInputError naming the file when it cannot be read or is not a JSON object.
ReconstructionQuality ReadQualityFile(const std::filesystem::path& file);

}  // namespace littermap::run
