#include "core/utf8.hpp"

#include <cstddef>
#include <cstdint>

#include "core/error.hpp"

namespace littermap {
namespace {

// Index of the first byte that does not start a well-formed sequence, or text.size().
std::size_t FirstInvalidByte(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
    const std::uint8_t lead = byte(i);
    std::size_t length = 0;
    std::uint8_t low = 0x80, high = 0xBF;  // the range of the second byte (RFC 3629, table 3-7)
    if (lead < 0x80) {
      ++i;
      continue;
    } else if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
      if (lead == 0xE0) low = 0xA0;   // no overlong forms
      if (lead == 0xED) high = 0x9F;  // no surrogates
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
      if (lead == 0xF0) low = 0x90;   // no overlong forms
      if (lead == 0xF4) high = 0x8F;  // nothing above U+10FFFF
    } else {
      return i;
    }
    if (i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high) return i;
    for (std::size_t k = 2; k < length; ++k) {
      if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return i;
    }
    i += length;
  }
  return i;
}

}  // namespace

bool IsUtf8(std::string_view text) { return FirstInvalidByte(text) == text.size(); }

void RequireUtf8(std::string_view text, const std::string& what) {
  const std::size_t at = FirstInvalidByte(text);
  if (at != text.size()) {
    throw BadInputError(what + " is not valid UTF-8 (byte " + std::to_string(at + 1) + " of " +
                        std::to_string(text.size()) + ")");
  }
}

}  // namespace littermap
