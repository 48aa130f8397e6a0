#pragma once
// Colour and depth images as sensor_msgs/CompressedImage, the way a run bag stores them:
// colour as JPEG ("bgr8; jpeg compressed bgr8"), depth as a 16-bit single-channel PNG in
// millimetres ("16UC1; png compressed"), the format compressed_image_transport writes. Decoding
// also accepts PNG colour and compressed_depth_image_transport's "compressedDepth" payloads.

#include <cstdint>
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

#include "bag/ros_messages.hpp"

namespace littermap::bag {

struct ImageCodecOptions {
  int jpeg_quality = 90;    // 0..100
  int png_compression = 1;  // zlib level 0..9; 1 is fast and near the best size for depth
};

// colour_bgr: CV_8UC3. Throws InternalError if OpenCV cannot encode.
msg::CompressedImage EncodeColorJpeg(const cv::Mat& colour_bgr, const msg::Header& header,
                                     const ImageCodecOptions& options = {});
// depth_mm: CV_16UC1, millimetres, 0 = no reading.
msg::CompressedImage EncodeDepthPng(const cv::Mat& depth_mm, const msg::Header& header,
                                    const ImageCodecOptions& options = {});

// Returns CV_8UC3 BGR. Throws BadInputError if the payload does not decode.
cv::Mat DecodeColor(const msg::CompressedImage& image);
// Returns CV_16UC1 depth in millimetres. Throws BadInputError if the payload does not decode or
// is not 16-bit single-channel.
cv::Mat DecodeDepthMm(const msg::CompressedImage& image);

// Writes an image file in the format of its extension (.png, .jpg, .pgm), all or nothing (through
// FILE.tmp, see core/output_file.hpp). Throws the FileFailure naming the file.
void WriteImageFile(const std::filesystem::path& file, const cv::Mat& image,
                    const std::vector<int>& parameters = {});

}  // namespace littermap::bag
