#pragma once
// PNG decoding through libpng with its messages caught: a damaged PNG is a BadInputError that
// gives libpng's reason, and nothing is printed (OpenCV's decoder lets libpng write
// "libpng error: …" on stderr). The pixels are those OpenCV's imdecode gives.

#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

namespace littermap::bag {

// Whether the bytes begin with the PNG signature.
bool IsPng(std::span<const std::uint8_t> bytes);

// CV_8UC3 BGR from any PNG: grey and palette images are expanded, alpha is dropped and 16-bit
// samples keep their high byte (as cv::IMREAD_COLOR).
cv::Mat DecodePngColor(std::span<const std::uint8_t> bytes);

// A 16-bit single-channel PNG as CV_16UC1; any other PNG is a BadInputError.
cv::Mat DecodePng16(std::span<const std::uint8_t> bytes);

}  // namespace littermap::bag
