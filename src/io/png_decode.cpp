#include "png_decode.h"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "animkit/trajectory/image_strokes.h"
#include "image_limits.h"

namespace animkit::image_detail {

namespace {

// What libpng's callbacks read and write. A plain struct: libpng reports errors by longjmp,
// which must not cross a frame holding an object with a destructor, so the messages are
// copied into fixed buffers here and turned into strings after the jump.
struct PngState {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t offset;
  bool ran_out;      // the read callback was asked for bytes past the end of the file
  char error[200];   // libpng's error message
  char damage[200];  // the first warning that means lost or wrong pixels
};

void read_callback(png_structp png, png_bytep out, png_size_t count) {
  auto* state = static_cast<PngState*>(png_get_io_ptr(png));
  if (count > state->size - state->offset) {
    state->ran_out = true;
    png_error(png, "the file ends early");
  }
  std::memcpy(out, state->data + state->offset, count);
  state->offset += count;
}

void error_callback(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(state->error, sizeof state->error, "%s", message);
  png_longjmp(png, 1);
}

// libpng only warns (a "benign error") about some damage to the pixel data: extra or bad
// compressed data in IDAT and palette indices past the palette. Those pixels are not what the
// file meant, so they fail the decode; warnings about ancillary chunks (colour profiles, text)
// lose no pixels and are ignored.
void warning_callback(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  const bool damage = std::strncmp(message, "IDAT", 4) == 0 ||
                      std::strstr(message, "image data") != nullptr ||
                      std::strstr(message, "palette index") != nullptr;
  if (damage && state->damage[0] == '\0') {
    std::snprintf(state->damage, sizeof state->damage, "%s", message);
  }
}

enum class PngOutcome { decoded, failed, too_large };

// Runs libpng from the signature to IEND, into `out` as 8-bit RGBA. Nothing in this frame has
// a destructor (see PngState). IEND is read too, so a file cut after its pixels still fails.
PngOutcome run_libpng(png_structp png, png_infop info, Image* out, png_uint_32* width,
                   png_uint_32* height) {
  if (setjmp(png_jmpbuf(png))) return PngOutcome::failed;
  png_set_user_limits(png, kMaxImageSide, kMaxImageSide);
  png_set_chunk_malloc_max(png, 8u << 20);  // text or profile chunks are small
  png_read_info(png, info);
  int bit_depth = 0, color_type = 0;
  png_get_IHDR(png, info, width, height, &bit_depth, &color_type, nullptr, nullptr, nullptr);
  if (*width > png_uint_32{kMaxImageSide} || *height > png_uint_32{kMaxImageSide}) {
    return PngOutcome::too_large;
  }
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (bit_depth == 16) png_set_scale_16(png);  // rounds 16-bit samples to the nearest 8-bit
  if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) {
    png_set_gray_to_rgb(png);
  }
  png_set_filler(png, 0xff, PNG_FILLER_AFTER);  // opaque alpha where the file has none
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != std::size_t{*width} * 4) {
    png_error(png, "unexpected row size after conversion to RGBA");
  }
  *out = Image(static_cast<int>(*width), static_cast<int>(*height));
  for (int pass = 0; pass < passes; ++pass) {
    for (png_uint_32 y = 0; y < *height; ++y) {
      png_read_row(png, reinterpret_cast<png_bytep>(&out->at(0, static_cast<int>(y))), nullptr);
    }
  }
  png_read_end(png, nullptr);
  return PngOutcome::decoded;
}

std::uint32_t big_endian(const std::uint8_t* b) {
  return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) |
         std::uint32_t{b[3]};
}

}  // namespace

Result<Image> decode_png(std::span<const std::uint8_t> bytes, std::string_view name) {
  // The size from IHDR (always the first chunk) before libpng allocates anything.
  if (bytes.size() >= 24 && std::memcmp(bytes.data() + 12, "IHDR", 4) == 0) {
    if (auto ok =
            check_image_side(big_endian(bytes.data() + 16), big_endian(bytes.data() + 20), name);
        !ok) {
      return fail(ok.error().message);
    }
  }
  PngState state{bytes.data(), bytes.size(), 0, false, {}, {}};
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, error_callback, warning_callback);
  if (png == nullptr) return fail(std::string(name) + ": libpng could not start");
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return fail(std::string(name) + ": libpng could not start");
  }
  png_set_read_fn(png, &state, read_callback);
  Image image;
  png_uint_32 width = 0, height = 0;
  const PngOutcome outcome = run_libpng(png, info, &image, &width, &height);
  png_destroy_read_struct(&png, &info, nullptr);
  switch (outcome) {
    case PngOutcome::decoded:
      if (state.damage[0] != '\0')
        return corrupt(name, "PNG", std::string("libpng: ") + state.damage);
      return image;
    case PngOutcome::too_large:
      if (auto ok = check_image_side(width, height, name); !ok) return fail(ok.error().message);
      return fail(std::string(name) + ": the image is too large");
    case PngOutcome::failed:
      break;
  }
  if (state.ran_out) {
    return truncated(name, "PNG", "the file ends after " + std::to_string(bytes.size()) + " bytes");
  }
  if (std::strstr(state.error, "Not enough image data") != nullptr) {
    return truncated(name, "PNG", std::string("libpng: ") + state.error);
  }
  return corrupt(name, "PNG", std::string("libpng: ") + state.error);
}

}  // namespace animkit::image_detail
