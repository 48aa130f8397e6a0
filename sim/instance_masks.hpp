#pragma once
// Ground-truth instance masks of a subset of the recorded camera frames, for scoring litter
// segmentation (which pixels show which object):
//
//   TRUTH_DIR/masks/frame_NNNNNN.png  16-bit single-channel PNG at the camera resolution,
//                                     NNNNNN = camera frame index (0-based, /camera/... order)
//   TRUTH_DIR/masks/index.csv         frame,stamp_ns,file — stamp_ns is the header stamp of the
//                                     colour and depth images the mask belongs to, file the
//                                     PNG's path relative to TRUTH_DIR
//   TRUTH_DIR/masks/visible.csv       frame,object_id,pixels,depth_pixels — every object seen in
//                                     a masked frame, how many pixels show it and how many of
//                                     those have a depth reading (within the depth camera's
//                                     range: what an RGB-D detector can place)
//
// Pixel value v: 0 = ground (terrain), 65535 = sky / nothing within the colour range, otherwise
// v - 1 = the world object id (`id` in world.json, litter.csv and natural.csv). Multi-part
// objects (a bench's seat, back and legs) are one id per primitive; world.json's `group` joins
// them.

#include <cstdint>
#include <filesystem>

#include <opencv2/core.hpp>

#include "core/output_file.hpp"
#include "core/time.hpp"

namespace littermap::sim {

inline constexpr std::uint16_t kMaskGround = 0;
inline constexpr std::uint16_t kMaskSky = 65535;

// CV_32SC1 renderer instance ids (sim/rgbd_camera.hpp) to the mask values above. Throws
// InternalError for an id that does not fit 16 bits.
cv::Mat InstanceIdsToMask(const cv::Mat& instance_ids);

class InstanceMaskWriter {
 public:
  // Creates TRUTH_DIR/masks. Throws InternalError when it cannot.
  explicit InstanceMaskWriter(const std::filesystem::path& truth_dir);

  // Writes the mask of camera frame `frame` stamped stamp_ns; depth_mm (CV_16UC1, 0 = none) is
  // the frame's depth image. Throws InternalError on failure.
  void Write(std::size_t frame, TimestampNs stamp_ns, const cv::Mat& instance_ids,
             const cv::Mat& depth_mm);
  // Flushes index.csv and visible.csv; throws InternalError if it could not be written.
  void Close();

  std::size_t written() const { return written_; }

 private:
  std::filesystem::path directory_;
  OutputFile index_;
  OutputFile visible_;
  std::size_t written_ = 0;
};

}  // namespace littermap::sim
