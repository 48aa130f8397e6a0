#include "capture/live_capture.hpp"

#include <cstdio>

#include "capture/robot_description.hpp"
#include "core/error.hpp"

namespace littermap::capture {

RecordingResult CaptureLive(const std::filesystem::path& bag, const LiveCaptureOptions& options,
                            const std::atomic<bool>& stop_requested,
                            const RecorderStatusCallback& status, const WarningCallback& warn) {
  std::vector<std::unique_ptr<SensorSource>> sources =
      MakeSources(options.sources, ParseCameraMode(options.camera_mode));
  msg::TFMessage tf_static;
  if (!options.robot_yaml.empty()) {
    tf_static = StaticTransforms(HostNowNs(), ReadRobotDescription(options.robot_yaml));
  } else if (warn) {
    warn(
        "no --robot description: the bag has no /tf_static, and later stages place the sensors "
        "at base_link");
  }
  RecorderOptions recorder;
  recorder.bag.storage = options.storage;
  if (options.duration_s) {
    if (!(*options.duration_s > 0)) throw UsageError("--duration: must be positive");
    recorder.max_duration_s = *options.duration_s;
  }
  if (!(options.min_free_disk_mb >= 0)) throw UsageError("--min-free-disk-mb: must be >= 0");
  recorder.min_free_disk_bytes = static_cast<std::uint64_t>(options.min_free_disk_mb * 1048576.0);
  return Record(bag, std::move(sources), tf_static, recorder, stop_requested, status);
}

std::string RecordingSummary(const std::filesystem::path& bag, const RecordingResult& result) {
  char counts[128];
  std::snprintf(counts, sizeof counts, " after %.1f s, %llu messages\n", result.duration_s,
                static_cast<unsigned long long>(result.messages));
  std::string text = bag.string() + ": " + result.stop_reason + counts;
  for (const SourceStatus& source : result.sources) text += "  " + FormatSummary(source) + "\n";
  return text;
}

}  // namespace littermap::capture
