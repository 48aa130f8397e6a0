#pragma once
// The largest image the decoders accept, checked against a header before anything is allocated:
// 2^26 pixels (8192 x 8192), far beyond any camera, far below memory trouble.

#include <cstdint>
#include <string>

#include "core/error.hpp"

namespace littermap::bag {

inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 26;

// Throws BadInputError "FORMAT of WxH pixels is larger than … pixels".
inline void CheckImageSize(const char* format, std::uint64_t width, std::uint64_t height) {
  if (width * height > kMaxImagePixels) {
    throw BadInputError(std::string(format) + " of " + std::to_string(width) + "x" +
                        std::to_string(height) + " pixels is larger than " +
                        std::to_string(kMaxImagePixels) + " pixels");
  }
}

}  // namespace littermap::bag
