#pragma once
// A labelled object crop, the unit of classifier training, and the sample directory format
// `littermap samples` writes and `littermap train` reads, so users can add their own objects:
//
//   SAMPLES/labels.csv   crop,mask,label,size_m,width_m,height_m,range_m[,source]
//   SAMPLES/<crop>       colour crop (PNG or JPEG, any size)
//   SAMPLES/<mask>       8-bit mask of the crop's size, non-zero = object pixel
//
// crop and mask are paths relative to SAMPLES. label: a litter class (can, bottle, cup, carton,
// food_container, plastic_bag, other), "natural" (flowers, leaves, stones, cones, branches, ...)
// or "clutter" (anything else the segmentation cut out: grass tufts, roots, trunk feet). The
// geometry columns come from depth: size_m the largest horizontal extent, width_m the extent
// across it, height_m the highest point above the ground, range_m the distance from the camera.
// Extra columns (source: where the crop came from) are ignored.

#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/object_classes.hpp"

namespace littermap::detect {

struct ObjectSample {
  cv::Mat colour_bgr;  // CV_8UC3 crop
  cv::Mat mask;        // CV_8U of the crop's size, non-zero = object
  double size_m = 0;
  double width_m = 0;
  double height_m = 0;
  double range_m = 0;
  std::string label;
  std::string source;
};

// Reads SAMPLES/labels.csv and every crop and mask. Throws BadInputError "labels.csv:LINE: ..."
// naming the column or file at fault.
std::vector<ObjectSample> ReadSamples(const std::filesystem::path& directory);

// Writes samples to a directory (created; labels.csv replaced) as crop_NNNNNN.png and
// mask_NNNNNN.png. Throws InternalError when a file cannot be written.
void WriteSamples(const std::filesystem::path& directory, const std::vector<ObjectSample>& samples);

}  // namespace littermap::detect
