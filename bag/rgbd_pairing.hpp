#pragma once
// Pairs the colour and depth images of a run bag's RGB-D frames as they come in time order:
// one colour and one depth image within a stamp gap make a frame. Images stay as stored
// (compressed or raw, bag/camera_image.hpp), so a reader decodes only the frames it uses.

#include <optional>

#include "bag/camera_image.hpp"
#include "core/time.hpp"

namespace littermap::bag {

struct CompressedRgbd {
  TimestampNs stamp_ns = 0;  // the colour image's
  CameraImage colour, depth;
};

class RgbdPairing {
 public:
  explicit RgbdPairing(double max_gap_s = 0.02);

  // The frame an image completes, if any; an image with no partner within the gap waits for
  // one (a newer image of its kind replaces it).
  std::optional<CompressedRgbd> AddColour(CameraImage image);
  std::optional<CompressedRgbd> AddDepth(CameraImage image);
  // Forgets the waiting images (a skipped colour image must not pair with its depth).
  void Reset();

 private:
  std::optional<CompressedRgbd> Pair();

  TimestampNs max_gap_ns_;
  std::optional<CameraImage> colour_, depth_;
};

}  // namespace littermap::bag
