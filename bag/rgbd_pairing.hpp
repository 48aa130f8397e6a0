#pragma once
// Pairs the colour and depth images of a run bag's RGB-D frames as they come in time order:
// one colour and one depth image within a stamp gap make a frame. Images stay as stored
// (compressed or raw, bag/camera_image.hpp), so a reader decodes only the frames it uses.

#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "bag/camera_image.hpp"
#include "core/time.hpp"

namespace littermap::bag {

struct CompressedRgbd {
  TimestampNs stamp_ns = 0;  // the colour image's
  CameraImage colour, depth;
  // Where each image came from, for errors: "BAG: topic 'T' message #N (t=… ns)" (MessageOrigin).
  std::string colour_origin, depth_origin;
};

// The frame's images decoded (CV_8UC3 BGR; CV_16UC1 millimetres); an image that does not decode
// is a BadInputError naming its origin.
cv::Mat DecodeColor(const CompressedRgbd& frame);
cv::Mat DecodeDepthMm(const CompressedRgbd& frame);

class RgbdPairing {
 public:
  explicit RgbdPairing(double max_gap_s = 0.02);

  // The frame an image completes, if any; an image with no partner within the gap waits for
  // one (a newer image of its kind replaces it).
  std::optional<CompressedRgbd> AddColour(CameraImage image, std::string origin = {});
  std::optional<CompressedRgbd> AddDepth(CameraImage image, std::string origin = {});
  // Forgets the waiting images (a skipped colour image must not pair with its depth).
  void Reset();

 private:
  std::optional<CompressedRgbd> Pair();

  TimestampNs max_gap_ns_;
  std::optional<CameraImage> colour_, depth_;
  std::string colour_origin_, depth_origin_;
};

}  // namespace littermap::bag
