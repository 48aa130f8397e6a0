#pragma once
// Converts a TUM RGB-D sequence directory (importers/tum_sequence.hpp) into a littermap run bag:
//   /camera/color/image_raw/compressed   the colour PNG file's bytes, unchanged (lossless,
//                                        "bgr8; png compressed bgr8")
//   /camera/depth/image_raw/compressed   16-bit PNG in millimetres (TUM stores 5000 units per
//                                        metre: mm = round(v / 5)), "16UC1; png compressed"
//   /camera/color/camera_info            the TUM calibration of the sequence's camera
// one of each per associated colour/depth pair, all stamped with the colour frame's time (the
// depth frame is within max_gap_s of it), as a synchronised RGB-D camera would stamp them.
// Colour frames without a depth partner are skipped and counted.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bag/bag_writer.hpp"
#include "bag/image_codec.hpp"
#include "core/progress.hpp"
#include "importers/tum_camera.hpp"

namespace littermap::importers {

struct TumImportOptions {
  std::optional<TumCamera> camera;  // unset: from the directory name (freiburg1/2/3)
  double max_association_gap_s = 0.02;
  double depth_units_per_m = 5000;
  std::filesystem::path reference_path;  // non-empty: write groundtruth.txt's poses there
  bag::ImageCodecOptions codec;
  bag::BagWriterOptions bag;
};

struct TumImportResult {
  TumCamera camera = TumCamera::kFreiburg1;
  bool camera_from_directory = false;
  std::uint64_t colour_listed = 0;
  std::uint64_t depth_listed = 0;
  std::uint64_t pairs_written = 0;  // colour, depth and camera_info messages each
  std::uint64_t colour_without_depth = 0;
  std::uint64_t reference_poses = 0;
  double duration_s = 0;
  std::vector<std::string> warnings;
};

// Throws UsageError when the camera is neither given nor named by the directory, BadInputError
// for malformed lists, missing or undecodable images (naming the file), InternalError for write
// failures. A bag directory this call created is removed again if writing fails.
TumImportResult ImportTumSequence(const std::filesystem::path& directory,
                                  const std::filesystem::path& bag_path,
                                  const TumImportOptions& options = {},
                                  const ProgressCallback& progress = {});

// TUM depth (units_per_m per metre) to millimetres, rounded to nearest; saturates at 65535.
// Throws BadInputError naming `source` if the image is not 16-bit single-channel.
cv::Mat TumDepthToMillimetres(const cv::Mat& depth, double units_per_m, const std::string& source);

}  // namespace littermap::importers
