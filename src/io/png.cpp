#include "animkit/io/png.h"

#include <png.h>

#include <cstdio>
#include <string_view>

#include "animkit/io/atomic_write.h"
#include "animkit/io/image_decode.h"
#include "image_file.h"

namespace animkit {

namespace {

// What libpng's callbacks touch. libpng reports errors by longjmp, which must not skip a
// destructor: the output vector lives in the caller's frame, the message in a fixed buffer.
struct PngSink {
  std::vector<unsigned char>* bytes;
  char error[200];
};

void write_callback(png_structp png, png_bytep data, png_size_t size) {
  auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
  sink->bytes->insert(sink->bytes->end(), data, data + size);
}

void flush_callback(png_structp) {}

void error_callback(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
  std::snprintf(sink->error, sizeof sink->error, "%s", message);
  png_longjmp(png, 1);
}

void warning_callback(png_structp, png_const_charp) {}

// 8-bit RGBA rows through libpng. Nothing in this frame has a destructor (see PngSink).
bool run_encoder(png_structp png, png_infop info, const Image* image) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, static_cast<png_uint_32>(image->width),
               static_cast<png_uint_32>(image->height), 8, PNG_COLOR_TYPE_RGB_ALPHA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image->height; ++y) {
    png_write_row(png, reinterpret_cast<png_const_bytep>(&image->at(0, y)));
  }
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

Result<std::vector<unsigned char>> encode_png(const Image& image) {
  if (image.empty() || image.width <= 0 || image.height <= 0) {
    return fail("cannot encode an empty image as PNG");
  }
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * image.height) {
    return fail("image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " has " + std::to_string(image.pixels.size()) + " pixels");
  }
  static_assert(sizeof(Pixel) == 4, "Pixel must be 4 packed bytes for the encoder");
  std::vector<unsigned char> bytes;
  PngSink sink{&bytes, {}};
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, error_callback, warning_callback);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return fail("libpng could not start the PNG encoder");
  }
  png_set_write_fn(png, &sink, write_callback, flush_callback);
  const bool encoded = run_encoder(png, info, &image);
  png_destroy_write_struct(&png, &info);
  if (!encoded) {
    return fail("the PNG encoder failed on a " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " image (libpng: " + sink.error + ")");
  }
  return bytes;
}

Result<void> write_png(const std::filesystem::path& path, const Image& image) {
  auto bytes = encode_png(image);
  if (!bytes) return fail(path.string() + ": " + bytes.error().message);
  return write_file_atomic(
      path, std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()));
}

Result<Image> read_image(const std::filesystem::path& path) {
  auto bytes = io_detail::read_file_bytes(path);
  if (!bytes) return fail(bytes.error().message);
  return decode_rgba_image(*bytes, path.string());
}

}  // namespace animkit
