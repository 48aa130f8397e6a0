#include "bag/png16.hpp"

#include <png.h>
#include <zlib.h>

#include "core/error.hpp"

namespace littermap::bag {
namespace {

void AppendToVector(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + size);
}

void NoFlush(png_structp) {}

[[noreturn]] void OnPngError(png_structp, png_const_charp message) {
  throw InternalError(std::string("PNG encoding failed: ") + message);
}

void OnPngWarning(png_structp, png_const_charp) {}

// Owns libpng's write state. Errors come back as exceptions thrown from OnPngError through
// libpng's frames, which the x86-64 and arm64 ABIs make unwindable (C is compiled with unwind
// tables there); this path is only reachable on allocation failure, as inputs are checked.
struct PngWriter {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, OnPngError, OnPngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
};

}  // namespace

std::vector<std::uint8_t> EncodePng16(const cv::Mat& image, const Png16Options& options) {
  if (image.type() != CV_16UC1) throw InternalError("EncodePng16: image is not 16UC1");
  PngWriter writer;
  if (writer.png == nullptr || writer.info == nullptr) {
    throw InternalError("PNG encoding failed: out of memory");
  }
  std::vector<std::uint8_t> out;
  out.reserve(image.total());
  png_set_write_fn(writer.png, &out, AppendToVector, NoFlush);
  png_set_IHDR(writer.png, writer.info, static_cast<png_uint_32>(image.cols),
               static_cast<png_uint_32>(image.rows), 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(writer.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(writer.png, options.zlib_level);
  png_set_compression_strategy(writer.png, Z_RLE);
  png_write_info(writer.png, writer.info);
  png_set_swap(writer.png);  // PNG stores 16-bit samples big-endian
  for (int row = 0; row < image.rows; ++row) {
    png_write_row(writer.png, const_cast<png_bytep>(image.ptr<png_byte>(row)));
  }
  png_write_end(writer.png, writer.info);
  return out;
}

}  // namespace littermap::bag
