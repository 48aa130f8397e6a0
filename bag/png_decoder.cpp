#include "bag/png_decoder.hpp"

#include <png.h>

#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "bag/image_size_limit.hpp"
#include "core/error.hpp"

namespace littermap::bag {
namespace {

struct Source {
  std::span<const std::uint8_t> bytes;
  std::size_t offset = 0;
};

[[noreturn]] void OnPngError(png_structp, png_const_charp message) {
  throw BadInputError(std::string("PNG does not decode: ") + message);
}

void OnPngWarning(png_structp, png_const_charp) {}

void ReadFromSpan(png_structp png, png_bytep out, png_size_t size) {
  auto* source = static_cast<Source*>(png_get_io_ptr(png));
  if (source->bytes.size() - source->offset < size) png_error(png, "the data ends early");
  std::memcpy(out, source->bytes.data() + source->offset, size);
  source->offset += size;
}

// Owns libpng's read state. Errors come back as exceptions thrown from OnPngError through
// libpng's frames, as in png16.cpp.
struct PngReader {
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, OnPngError, OnPngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
};

enum class Target { kColor, kDepth };

cv::Mat Decode(std::span<const std::uint8_t> bytes, Target target) {
  if (!IsPng(bytes)) throw BadInputError("PNG does not decode: no PNG signature");
  PngReader reader;
  if (reader.png == nullptr || reader.info == nullptr) throw std::bad_alloc();
  Source source{bytes};
  png_set_read_fn(reader.png, &source, ReadFromSpan);
  png_read_info(reader.png, reader.info);
  const png_uint_32 width = png_get_image_width(reader.png, reader.info);
  const png_uint_32 height = png_get_image_height(reader.png, reader.info);
  const int bit_depth = png_get_bit_depth(reader.png, reader.info);
  const int colour_type = png_get_color_type(reader.png, reader.info);
  CheckImageSize("PNG", width, height);
  cv::Mat image;
  if (target == Target::kDepth) {
    if (bit_depth != 16 || colour_type != PNG_COLOR_TYPE_GRAY) {
      throw BadInputError("PNG is not 16-bit single-channel");
    }
    png_set_swap(reader.png);  // PNG stores 16-bit samples big-endian
    image.create(static_cast<int>(height), static_cast<int>(width), CV_16UC1);
  } else {
    if (bit_depth == 16) png_set_strip_16(reader.png);
    if (colour_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(reader.png);
    if (bit_depth < 8 && (colour_type & PNG_COLOR_MASK_COLOR) == 0) {
      png_set_expand_gray_1_2_4_to_8(reader.png);
    }
    if ((colour_type & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(reader.png);
    png_set_strip_alpha(reader.png);
    png_set_bgr(reader.png);
    image.create(static_cast<int>(height), static_cast<int>(width), CV_8UC3);
  }
  png_set_interlace_handling(reader.png);
  png_read_update_info(reader.png, reader.info);
  if (png_get_rowbytes(reader.png, reader.info) != image.step[0]) {
    throw BadInputError("PNG rows do not have the size of its header's image");
  }
  std::vector<png_bytep> rows(image.rows);
  for (int row = 0; row < image.rows; ++row) rows[row] = image.ptr<png_byte>(row);
  png_read_image(reader.png, rows.data());
  png_read_end(reader.png, nullptr);
  return image;
}

}  // namespace

bool IsPng(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0;
}

cv::Mat DecodePngColor(std::span<const std::uint8_t> bytes) {
  return Decode(bytes, Target::kColor);
}

cv::Mat DecodePng16(std::span<const std::uint8_t> bytes) { return Decode(bytes, Target::kDepth); }

}  // namespace littermap::bag
