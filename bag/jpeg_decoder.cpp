#include "bag/jpeg_decoder.hpp"

// jpeglib.h needs FILE and size_t declared before it.
#include <cstddef>
#include <cstdio>

#include <jpeglib.h>

#include "bag/image_size_limit.hpp"
#include "core/error.hpp"

namespace littermap::bag {
namespace {

// libjpeg's error manager, extended with the first warning's text. Fatal errors come back as
// exceptions thrown from error_exit through libjpeg's frames, as libpng's do in png16.cpp.
struct ErrorManager {
  jpeg_error_mgr base;
  std::string first_warning;
};

std::string MessageOf(j_common_ptr cinfo) {
  char text[JMSG_LENGTH_MAX];
  (*cinfo->err->format_message)(cinfo, text);
  return text;
}

[[noreturn]] void OnError(j_common_ptr cinfo) {
  throw BadInputError("JPEG does not decode: " + MessageOf(cinfo));
}

// Level -1: a warning (corrupt data); 0 and up: trace messages, ignored. Nothing is printed.
void OnMessage(j_common_ptr cinfo, int level) {
  if (level >= 0) return;
  auto* errors = reinterpret_cast<ErrorManager*>(cinfo->err);
  if (errors->first_warning.empty()) errors->first_warning = MessageOf(cinfo);
  ++cinfo->err->num_warnings;
}

struct Decompressor {
  jpeg_decompress_struct cinfo{};
  ErrorManager errors;
  Decompressor() {
    cinfo.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = OnError;
    errors.base.emit_message = OnMessage;
    jpeg_create_decompress(&cinfo);
  }
  ~Decompressor() { jpeg_destroy_decompress(&cinfo); }
  Decompressor(const Decompressor&) = delete;
  Decompressor& operator=(const Decompressor&) = delete;
};

}  // namespace

bool IsJpeg(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
}

JpegImage DecodeJpeg(std::span<const std::uint8_t> bytes) {
  if (!IsJpeg(bytes)) throw BadInputError("JPEG does not decode: no start-of-image marker");
  Decompressor jpeg;
  jpeg_mem_src(&jpeg.cinfo, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&jpeg.cinfo, TRUE);
  CheckImageSize("JPEG", jpeg.cinfo.image_width, jpeg.cinfo.image_height);
  jpeg.cinfo.out_color_space = JCS_EXT_BGR;  // libjpeg-turbo: grey and YCbCr both come out BGR
  jpeg_start_decompress(&jpeg.cinfo);
  JpegImage image;
  image.bgr.create(static_cast<int>(jpeg.cinfo.output_height),
                   static_cast<int>(jpeg.cinfo.output_width), CV_8UC3);
  while (jpeg.cinfo.output_scanline < jpeg.cinfo.output_height) {
    JSAMPROW row = image.bgr.ptr<JSAMPLE>(static_cast<int>(jpeg.cinfo.output_scanline));
    jpeg_read_scanlines(&jpeg.cinfo, &row, 1);
  }
  jpeg_finish_decompress(&jpeg.cinfo);
  image.damage = jpeg.errors.first_warning;
  return image;
}

}  // namespace littermap::bag
