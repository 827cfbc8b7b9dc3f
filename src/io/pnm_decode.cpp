#include "pnm_decode.h"

#include <string>

#include "animkit/core/quote.h"
#include "image_limits.h"

namespace animkit::image_detail {

namespace {

bool is_space(std::uint8_t c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}
bool is_digit(std::uint8_t c) {
  return c >= '0' && c <= '9';
}

// Reads the header's numbers and the ASCII rasters: decimal numbers separated by whitespace,
// with '#' comments running to the end of a line (Netpbm's rules).
class PnmReader {
 public:
  PnmReader(std::span<const std::uint8_t> bytes, std::string_view name, std::string_view format)
      : bytes_(bytes), name_(name), format_(format) {}

  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }
  void skip(std::size_t n) { pos_ += n; }

  void skip_space_and_comments() {
    while (pos_ < bytes_.size()) {
      if (is_space(bytes_[pos_])) {
        ++pos_;
      } else if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else {
        break;
      }
    }
  }

  // The next number, at most `limit`. `label` names it in messages ("the width"); for raster
  // samples it is empty and `sample` (from 1) names it, so no string is built per sample.
  Result<std::uint32_t> number(std::string_view label, std::uint64_t limit,
                               std::uint64_t sample = 0) {
    const auto what = [&] {
      return sample ? "sample " + std::to_string(sample) : std::string(label);
    };
    skip_space_and_comments();
    if (pos_ == bytes_.size()) return truncated(name_, format_, "the file ends before " + what());
    const std::size_t start = pos_;
    std::uint64_t value = 0;
    while (pos_ < bytes_.size() && is_digit(bytes_[pos_]) && pos_ - start < 10) {
      value = value * 10 + (bytes_[pos_] - '0');
      ++pos_;
    }
    if (pos_ == start || (pos_ < bytes_.size() && is_digit(bytes_[pos_]))) {
      std::size_t end = start;
      while (end < bytes_.size() && end - start < 20 && !is_space(bytes_[end])) ++end;
      const std::string_view token(reinterpret_cast<const char*>(bytes_.data()) + start,
                                   end - start);
      return corrupt(name_, format_, "expected " + what() + ", found " + quote_input(token));
    }
    if (value > limit) {
      return corrupt(name_, format_,
                     what() + " is " + std::to_string(value) + ", above " + std::to_string(limit));
    }
    return static_cast<std::uint32_t>(value);
  }

  // One P1 sample (from 1): a single digit 0 or 1; neighbours need no whitespace between them.
  Result<std::uint32_t> bit(std::uint64_t sample) {
    const auto what = [&] { return "sample " + std::to_string(sample); };
    skip_space_and_comments();
    if (pos_ == bytes_.size()) return truncated(name_, format_, "the file ends before " + what());
    const std::uint8_t c = bytes_[pos_];
    if (c != '0' && c != '1') {
      return corrupt(name_, format_,
                     "expected 0 or 1 for " + what() + ", found " +
                         quote_input(std::string_view(reinterpret_cast<const char*>(&c), 1)));
    }
    ++pos_;
    return c - '0';
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::string_view name_, format_;
  std::size_t pos_ = 0;
};

}  // namespace

Result<Image> decode_pnm(std::span<const std::uint8_t> bytes, std::string_view name) {
  if (bytes.size() < 2 || bytes[0] != 'P' || bytes[1] < '1' || bytes[1] > '6') {
    return corrupt(name, "PNM", "no P1 to P6 signature");
  }
  const int kind = bytes[1] - '0';
  const bool binary = kind >= 4;
  const bool bitmap = kind == 1 || kind == 4;
  const int channels = kind == 3 || kind == 6 ? 3 : 1;
  const std::string_view format = bitmap ? "PBM" : channels == 3 ? "PPM" : "PGM";

  PnmReader in(bytes, name, format);
  in.skip(2);
  if (in.remaining() > 0 && !is_space(bytes[2]) && bytes[2] != '#') {
    return corrupt(name, format, "no whitespace after the signature");
  }
  constexpr std::uint64_t kMaxDeclared = 9'999'999'999;  // ten digits
  auto width = in.number("the width", kMaxDeclared);
  if (!width) return fail(width.error().message);
  auto height = in.number("the height", kMaxDeclared);
  if (!height) return fail(height.error().message);
  if (*width == 0 || *height == 0) {
    return corrupt(name, format, "size " + std::to_string(*width) + "x" + std::to_string(*height));
  }
  if (auto ok = check_image_side(*width, *height, name); !ok) return fail(ok.error().message);
  std::uint32_t maxval = 1;
  if (!bitmap) {
    auto declared = in.number("the maxval", 65535);
    if (!declared) return fail(declared.error().message);
    if (*declared == 0) return corrupt(name, format, "maxval is 0");
    maxval = *declared;
  }
  const std::uint64_t samples = std::uint64_t{*width} * *height * channels;
  const std::string size = std::to_string(*width) + "x" + std::to_string(*height) + " pixels";

  // Every size is checked against the bytes present before the pixels are allocated.
  if (binary) {
    // Exactly one whitespace byte separates the header from the raster.
    if (in.remaining() == 0) return truncated(name, format, "the file ends after the header");
    if (!is_space(bytes[in.position()])) {
      return corrupt(name, format, "no whitespace between the header and the pixels");
    }
    in.skip(1);
    const std::uint64_t sample_bytes = maxval > 255 ? 2 : 1;
    const std::uint64_t needed =
        bitmap ? (std::uint64_t{*width} + 7) / 8 * *height : samples * sample_bytes;
    if (in.remaining() < needed) {
      return truncated(name, format,
                       size + " need " + std::to_string(needed) + " bytes after the header, only " +
                           std::to_string(in.remaining()) + " follow it");
    }
  } else {
    // At least one digit a sample, and whitespace between numbers (not between P1's bits).
    const std::uint64_t needed = bitmap ? samples : 2 * samples - 1;
    if (in.remaining() < needed) {
      return truncated(name, format,
                       size + " need at least " + std::to_string(needed) +
                           " bytes of numbers after the header, only " +
                           std::to_string(in.remaining()) + " follow it");
    }
  }

  Image image(static_cast<int>(*width), static_cast<int>(*height));
  const std::uint8_t* raster = bytes.data() + in.position();
  const std::uint64_t row_bytes = (std::uint64_t{*width} + 7) / 8;  // P4 rows are whole bytes
  std::vector<std::uint32_t> pixel(channels);
  std::uint64_t sample = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < channels; ++c, ++sample) {
        if (kind == 4) {
          pixel[c] = (raster[y * row_bytes + x / 8] >> (7 - x % 8)) & 1;
        } else if (binary) {
          pixel[c] = maxval > 255
                         ? (std::uint32_t{raster[2 * sample]} << 8) | raster[2 * sample + 1]
                         : raster[sample];
          if (pixel[c] > maxval) {
            return corrupt(name, format,
                           "sample " + std::to_string(sample + 1) + " is " +
                               std::to_string(pixel[c]) + ", above the maxval " +
                               std::to_string(maxval));
          }
        } else {
          auto value = bitmap ? in.bit(sample + 1) : in.number("", maxval, sample + 1);
          if (!value) return fail(value.error().message);
          pixel[c] = *value;
        }
      }
      Pixel& p = image.at(x, y);
      if (bitmap) {
        const std::uint8_t v = pixel[0] ? 0 : 255;  // PBM: 1 is ink (black)
        p = {v, v, v, 255};
      } else {
        auto scale = [&](std::uint32_t v) {
          return static_cast<std::uint8_t>((std::uint64_t{v} * 255 + maxval / 2) / maxval);
        };
        const std::uint8_t r = scale(pixel[0]);
        p = channels == 3 ? Pixel{r, scale(pixel[1]), scale(pixel[2]), 255} : Pixel{r, r, r, 255};
      }
    }
  }
  return image;
}

}  // namespace animkit::image_detail
