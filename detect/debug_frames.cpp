#include "detect/debug_frames.hpp"

#include <cstdio>

#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"

namespace littermap::detect {

FrameCallback DebugFrameWriter(const std::filesystem::path& directory) {
  if (directory.empty()) return {};
  std::filesystem::create_directories(directory);
  return [directory](const RgbdFrame& frame, const FrameSegmentation& segmentation) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%06zu.png", frame.index);
    if (!cv::imwrite((directory / name).string(),
                     DrawSegmentation(frame.colour_bgr, segmentation))) {
      throw UsageError((directory / name).string() + ": cannot write");
    }
  };
}

}  // namespace littermap::detect
