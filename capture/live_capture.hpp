#pragma once
// A run recorded from the robot's real sensors, set up as `littermap capture` asks for it: the
// sources from their URIs (capture/capture_sources.hpp), the camera mode, the sensor mounts for
// /tf_static (capture/robot_description.hpp) and the recorder's stop conditions
// (capture/recorder.hpp).

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "capture/capture_sources.hpp"
#include "capture/recorder.hpp"
#include "core/progress.hpp"

namespace littermap::capture {

struct LiveCaptureOptions {
  CaptureSources sources;
  std::filesystem::path robot_yaml;        // empty: the bag gets no /tf_static
  std::string camera_mode = "640x480@30";  // WIDTHxHEIGHT@FPS (ParseCameraMode)
  std::optional<double> duration_s;        // none: until stop_requested
  double min_free_disk_mb = 256;           // stop cleanly when the disk has less left
  std::string storage = "sqlite3";         // of the bag: "sqlite3" | "mcap"
};

// Sets up the sources and records until a stop condition. Warns when there is no robot
// description. Throws UsageError naming the option (--camera-mode, --duration,
// --min-free-disk-mb) or the URI at fault, BadInputError for an unreadable robot description, and
// what Record throws; a write failure during the recording is in the result, not thrown.
RecordingResult CaptureLive(const std::filesystem::path& bag, const LiveCaptureOptions& options,
                            const std::atomic<bool>& stop_requested,
                            const RecorderStatusCallback& status = {},
                            const WarningCallback& warn = {});

// "BAG: STOP_REASON after D s, N messages", then each source's FormatSummary indented by two
// spaces; every line ends in "\n".
std::string RecordingSummary(const std::filesystem::path& bag, const RecordingResult& result);

}  // namespace littermap::capture
