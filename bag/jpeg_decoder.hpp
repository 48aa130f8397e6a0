#pragma once
// JPEG decoding through libjpeg with its messages caught: a JPEG libjpeg cannot decode is a
// BadInputError with libjpeg's reason, and nothing is printed (OpenCV's decoder lets libjpeg write
// "Corrupt JPEG data: …" on stderr). The pixels are those OpenCV's imdecode gives (the same
// libjpeg-turbo, the same defaults).

#include <cstdint>
#include <span>
#include <string>

#include <opencv2/core.hpp>

namespace littermap::bag {

// Whether the bytes begin with a JPEG start-of-image marker.
bool IsJpeg(std::span<const std::uint8_t> bytes);

struct JpegImage {
  cv::Mat bgr;         // CV_8UC3; grey JPEGs expanded, as cv::IMREAD_COLOR gives them
  std::string damage;  // libjpeg's first warning (e.g. corrupt entropy data), empty when clean
};

// Throws BadInputError when libjpeg gives up. A JPEG it decodes despite damage (a bit-flipped
// entropy segment decodes to wrong pixels) comes back with `damage` set: the pipeline uses such
// frames as OpenCV would, `info --verify` reports them.
JpegImage DecodeJpeg(std::span<const std::uint8_t> bytes);

}  // namespace littermap::bag
