#include "detect/debug_frames.hpp"

#include <cstdio>

#include "bag/image_codec.hpp"

namespace littermap::detect {

FrameCallback DebugFrameWriter(const std::filesystem::path& directory) {
  if (directory.empty()) return {};
  std::filesystem::create_directories(directory);
  return [directory](const ProcessedFrame& processed) {
    char name[64];
    std::snprintf(name, sizeof name, "frame_%06zu.png", processed.frame.index);
    bag::WriteImageFile(directory / name,
                        DrawSegmentation(processed.frame.colour_bgr, processed.segmentation));
  };
}

}  // namespace littermap::detect
