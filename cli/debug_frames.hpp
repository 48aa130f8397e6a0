#pragma once
// Segmentation pictures of processed frames (`--debug-frames DIR`) and the per-stage time line
// shared by `detect` and `samples`.

#include <cstdio>
#include <filesystem>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "core/error.hpp"
#include "detect/run_objects.hpp"

namespace littermap::cli {

inline void WriteDebugFrame(const std::filesystem::path& directory, const detect::RgbdFrame& frame,
                            const detect::FrameSegmentation& segmentation) {
  char name[64];
  std::snprintf(name, sizeof name, "frame_%06zu.png", frame.index);
  if (!cv::imwrite((directory / name).string(),
                   detect::DrawSegmentation(frame.colour_bgr, segmentation))) {
    throw UsageError((directory / name).string() + ": cannot write");
  }
}

inline std::string SegmentationTimeLine(const detect::RunObjectsResult& result) {
  const double n = static_cast<double>(std::max<std::size_t>(1, result.frames));
  const auto& t = result.time;
  char line[256];
  std::snprintf(line, sizeof line,
                "segmentation %.1f ms/frame (cloud+normals %.1f, components %.1f, ground %.1f, "
                "texture+graph cut %.1f, objects %.1f)",
                t.total_ms() / n, t.cloud_ms / n, t.components_ms / n, t.ground_ms / n,
                t.texture_ms / n, t.objects_ms / n);
  return line;
}

}  // namespace littermap::cli
