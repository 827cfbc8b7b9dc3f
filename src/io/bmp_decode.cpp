#include "bmp_decode.h"

#include <array>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "image_limits.h"

namespace animkit::image_detail {

namespace {

constexpr std::uint32_t kRgb = 0, kRle8 = 1, kRle4 = 2, kBitfields = 3, kJpeg = 4, kPng = 5,
                        kAlphaBitfields = 6;

std::uint32_t le16(std::span<const std::uint8_t> b, std::size_t at) {
  return std::uint32_t{b[at]} | (std::uint32_t{b[at + 1]} << 8);
}
std::uint32_t le32(std::span<const std::uint8_t> b, std::size_t at) {
  return le16(b, at) | (le16(b, at + 2) << 16);
}

// One channel of a BI_BITFIELDS pixel: its bits must be contiguous; they are scaled to 0..255.
struct Channel {
  std::uint32_t mask = 0;
  int shift = 0;
  std::uint64_t max = 0;  // the largest value the channel's bits hold; 0 for no channel

  std::uint8_t read(std::uint32_t pixel, std::uint8_t absent) const {
    if (max == 0) return absent;
    const std::uint64_t v = (pixel & mask) >> shift;
    return static_cast<std::uint8_t>((v * 255 + max / 2) / max);
  }
};

std::optional<Channel> channel_of(std::uint32_t mask) {
  Channel c;
  c.mask = mask;
  if (mask == 0) return c;
  c.shift = std::countr_zero(mask);
  c.max = mask >> c.shift;
  if ((c.max & (c.max + 1)) != 0) return std::nullopt;  // a gap inside the mask
  return c;
}

std::string hex(std::uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", v);
  return text;
}

}  // namespace

Result<Image> decode_bmp(std::span<const std::uint8_t> bytes, std::string_view name) {
  const std::size_t size = bytes.size();
  if (size < 18) {
    return truncated(name, "BMP",
                     "the file has " + std::to_string(size) + " bytes, too few for the headers");
  }
  const std::uint64_t pixel_offset = le32(bytes, 10);
  const std::uint32_t header_size = le32(bytes, 14);
  const bool core_header = header_size == 12;  // OS/2 BITMAPCOREHEADER: 16-bit sizes
  if (!core_header && header_size != 40 && header_size != 52 && header_size != 56 &&
      header_size != 108 && header_size != 124) {
    return corrupt(name, "BMP",
                   "info header of " + std::to_string(header_size) +
                       " bytes, expected 12, 40, 52, 56, 108 or 124");
  }
  if (14 + header_size > size) {
    return truncated(name, "BMP",
                     "the " + std::to_string(header_size) +
                         "-byte info header does not fit in the file's " + std::to_string(size) +
                         " bytes");
  }
  std::int64_t width = 0, height = 0;
  std::uint32_t planes = 0, bpp = 0, compression = kRgb, colors_used = 0;
  if (core_header) {
    width = le16(bytes, 18);
    height = le16(bytes, 20);
    planes = le16(bytes, 22);
    bpp = le16(bytes, 24);
  } else {
    width = static_cast<std::int32_t>(le32(bytes, 18));
    height = static_cast<std::int32_t>(le32(bytes, 22));
    planes = le16(bytes, 26);
    bpp = le16(bytes, 28);
    compression = le32(bytes, 30);
    colors_used = le32(bytes, 46);
  }
  // A negative height means rows are stored top-down; positive, bottom-up.
  const bool top_down = height < 0;
  height = std::abs(height);
  if (width <= 0 || height == 0) {
    return corrupt(name, "BMP", "size " + std::to_string(width) + "x" + std::to_string(height));
  }
  if (auto ok = check_image_side(static_cast<std::uint64_t>(width),
                                 static_cast<std::uint64_t>(height), name);
      !ok) {
    return fail(ok.error().message);
  }
  if (planes != 1) return corrupt(name, "BMP", std::to_string(planes) + " planes, expected 1");
  if (compression == kRle8 || compression == kRle4) {
    return fail(std::string(name) +
                ": RLE-compressed BMP is not supported (save it as an uncompressed BMP or a PNG)");
  }
  if (compression == kJpeg || compression == kPng) {
    return fail(std::string(name) + ": BMP holding a " + (compression == kJpeg ? "JPEG" : "PNG") +
                " is not supported (save the picture as a plain JPEG or PNG)");
  }
  const bool bitfields = compression == kBitfields || compression == kAlphaBitfields;
  if (compression != kRgb && !bitfields) {
    return corrupt(name, "BMP", "unknown compression " + std::to_string(compression));
  }
  const bool depth_ok =
      bitfields ? (bpp == 16 || bpp == 32)
                : (bpp == 1 || bpp == 4 || bpp == 8 || bpp == 16 || bpp == 24 || bpp == 32);
  if (!depth_ok) {
    return corrupt(name, "BMP",
                   std::to_string(bpp) + " bits per pixel" +
                       (bitfields ? " with BI_BITFIELDS (expected 16 or 32)" : ""));
  }

  // Colour masks: in the header from version 2 on, else right after a 40-byte header.
  std::size_t tables = 14 + header_size;
  std::array<std::uint32_t, 4> masks{0x7c00, 0x03e0, 0x001f, 0};  // BI_RGB 16-bit is 5-5-5
  if (bitfields) {
    const int count = compression == kAlphaBitfields || header_size >= 56 ? 4 : 3;
    const std::size_t at = header_size == 40 ? tables : 14 + 40;
    if (at + 4 * count > size) {
      return truncated(
          name, "BMP",
          "the colour masks do not fit in the file's " + std::to_string(size) + " bytes");
    }
    masks = {0, 0, 0, 0};
    for (int i = 0; i < count; ++i) masks[i] = le32(bytes, at + 4 * i);
    if (header_size == 40) tables += 4 * count;
  }
  std::array<Channel, 4> channels;
  for (int i = 0; i < 4; ++i) {
    auto c = channel_of(masks[i]);
    if (!c) return corrupt(name, "BMP", "colour mask " + hex(masks[i]) + " is not contiguous");
    channels[i] = *c;
  }

  // The palette of 1-, 4- and 8-bit images: 3 bytes an entry after a core header, else 4.
  std::vector<Pixel> palette;
  if (bpp <= 8) {
    const std::uint64_t count = colors_used != 0 ? colors_used : (1u << bpp);
    if (count > (1u << bpp)) {
      return corrupt(
          name, "BMP",
          std::to_string(count) + " palette colours for " + std::to_string(bpp) + "-bit pixels");
    }
    const std::size_t entry = core_header ? 3 : 4;
    if (tables + count * entry > size) {
      return truncated(name, "BMP",
                       "the palette of " + std::to_string(count) +
                           " colours does not fit in the file's " + std::to_string(size) +
                           " bytes");
    }
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t at = tables + i * entry;
      palette.push_back({bytes[at + 2], bytes[at + 1], bytes[at], 255});
    }
    tables += count * entry;
  }
  if (pixel_offset < tables) {
    return corrupt(name, "BMP",
                   "the pixels start at byte " + std::to_string(pixel_offset) +
                       ", inside the headers that end at byte " + std::to_string(tables));
  }
  // Rows are padded to 4 bytes; the last row's padding may be missing without losing pixels.
  const std::uint64_t row_bits = static_cast<std::uint64_t>(width) * bpp;
  const std::uint64_t stride = (row_bits + 31) / 32 * 4;
  const std::uint64_t needed =
      pixel_offset + stride * static_cast<std::uint64_t>(height - 1) + (row_bits + 7) / 8;
  if (needed > size) {
    return truncated(name, "BMP",
                     std::to_string(width) + "x" + std::to_string(height) + " pixels at " +
                         std::to_string(bpp) + " bits need " + std::to_string(needed) +
                         " bytes, the file has " + std::to_string(size));
  }

  Image image(static_cast<int>(width), static_cast<int>(height));
  bool any_alpha = false;  // BI_RGB 32-bit: the fourth byte is alpha only if some pixel uses it
  for (int row = 0; row < image.height; ++row) {
    const std::uint8_t* in = bytes.data() + pixel_offset + stride * static_cast<std::uint64_t>(row);
    const int y = top_down ? row : image.height - 1 - row;
    for (int x = 0; x < image.width; ++x) {
      Pixel& p = image.at(x, y);
      if (bpp <= 8) {
        const int per_byte = 8 / static_cast<int>(bpp);
        const int shift = 8 - static_cast<int>(bpp) * (x % per_byte + 1);
        const std::size_t index = (in[x / per_byte] >> shift) & ((1u << bpp) - 1);
        if (index >= palette.size()) {
          return corrupt(name, "BMP",
                         "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                             ") uses colour " + std::to_string(index) + " of a palette of " +
                             std::to_string(palette.size()));
        }
        p = palette[index];
      } else if (bpp == 24) {
        p = {in[3 * x + 2], in[3 * x + 1], in[3 * x], 255};
      } else if (bpp == 32 && !bitfields) {
        p = {in[4 * x + 2], in[4 * x + 1], in[4 * x], in[4 * x + 3]};
        any_alpha = any_alpha || p.a != 0;
      } else {
        const std::uint32_t v = bpp == 16 ? le16({in, 2 * std::size_t(x) + 2}, 2 * std::size_t(x))
                                          : le32({in, 4 * std::size_t(x) + 4}, 4 * std::size_t(x));
        p = {channels[0].read(v, 0), channels[1].read(v, 0), channels[2].read(v, 0),
             channels[3].read(v, 255)};
      }
    }
  }
  if (bpp == 32 && !bitfields && !any_alpha) {
    for (Pixel& p : image.pixels) p.a = 255;  // an unused fourth byte, not a transparent image
  }
  return image;
}

}  // namespace animkit::image_detail
