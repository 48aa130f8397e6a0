#pragma once
// Pictures of the processed frames' segmentation for people (`--debug-frames DIR` of `detect`
// and `samples`): DrawSegmentation of every frame, as DIR/frame_NNNNNN.png.

#include <filesystem>
#include <functional>

#include "detect/run_objects.hpp"

namespace littermap::detect {

// An `on_frame` callback for ForEachRunObject and the detect stage that writes each frame's
// picture into `directory`, which is created now; an empty callback for an empty directory. The
// callback throws UsageError naming a file it cannot write.
FrameCallback DebugFrameWriter(const std::filesystem::path& directory);

}  // namespace littermap::detect
