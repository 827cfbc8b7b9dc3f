// Decoding pictures from memory: every supported kind decodes to exactly the pixels it was
// made from, and bad data gives a message naming the problem. Files are made here: PNG and
// JPEG through libpng and libjpeg, BMP and PNM byte by byte.
#include "animkit/io/image_decode.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdlib>

#include "../support/image_encoders.h"

namespace animkit {
namespace {

using testing_support::Bytes;
using testing_support::bytes_of;

std::string error_of(const Result<Image>& result) {
  return result ? "(no error)" : result.error().message;
}

bool same(const Pixel& a, const Pixel& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

::testing::AssertionResult pixels_are(const Result<Image>& image, int width, int height,
                                      const std::vector<Pixel>& expected) {
  if (!image) return ::testing::AssertionFailure() << image.error().message;
  if (image->width != width || image->height != height) {
    return ::testing::AssertionFailure() << "size " << image->width << "x" << image->height;
  }
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Pixel& p = image->pixels[i];
    if (!same(p, expected[i])) {
      return ::testing::AssertionFailure()
             << "pixel " << i << " is " << int(p.r) << "," << int(p.g) << "," << int(p.b) << ","
             << int(p.a) << ", expected " << int(expected[i].r) << "," << int(expected[i].g) << ","
             << int(expected[i].b) << "," << int(expected[i].a);
    }
  }
  return ::testing::AssertionSuccess();
}

Pixel gray(std::uint8_t v, std::uint8_t a = 255) {
  return {v, v, v, a};
}

TEST(DecodePng, SixteenBitSamplesRoundToEightBits) {
  // 2x1 RGB at 16 bits: 257 * v is exactly v at 8 bits.
  auto spec = testing_support::png_spec(2, 1, 16, PNG_COLOR_TYPE_RGB);
  spec.rows = {{0x00, 0x00, 0x80, 0x80, 0xff, 0xff, 0x0a, 0x0a, 0x14, 0x14, 0x1e, 0x1e}};
  EXPECT_TRUE(pixels_are(decode_rgba_image(png_file(spec), "a.png"), 2, 1,
                         {{0, 128, 255, 255}, {10, 20, 30, 255}}));
}

TEST(DecodePng, PaletteWithTransparency) {
  // 4-bit indices into a 3-colour palette; entry 2 is half transparent.
  auto spec = testing_support::png_spec(3, 2, 4, PNG_COLOR_TYPE_PALETTE);
  spec.palette = {255, 0, 0, 0, 255, 0, 0, 0, 255};
  spec.alphas = {255, 255, 128};
  spec.rows = {{0x01, 0x20}, {0x21, 0x00}};
  EXPECT_TRUE(pixels_are(decode_rgba_image(png_file(spec), "p.png"), 3, 2,
                         {{255, 0, 0, 255},
                          {0, 255, 0, 255},
                          {0, 0, 255, 128},
                          {0, 0, 255, 128},
                          {0, 255, 0, 255},
                          {255, 0, 0, 255}}));
}

TEST(DecodePng, GrayAndAlphaCompositesOverWhiteForGray) {
  auto spec = testing_support::png_spec(3, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA);
  spec.rows = {{0, 255, 0, 0, 0, 128}};  // black opaque, black transparent, black half
  const Bytes file = png_file(spec);
  EXPECT_TRUE(pixels_are(decode_rgba_image(file, "ga.png"), 3, 1,
                         {gray(0, 255), gray(0, 0), gray(0, 128)}));
  const auto g = decode_gray_image(file, "ga.png");
  ASSERT_TRUE(g.has_value()) << g.error().message;
  EXPECT_EQ(g->pixels, (std::vector<std::uint8_t>{0, 255, 127}));
}

TEST(DecodePng, OneBitGrayAndInterlacedRgb) {
  auto bits = testing_support::png_spec(10, 1, 1, PNG_COLOR_TYPE_GRAY);
  bits.rows = {{0b10110000, 0b01000000}};
  std::vector<Pixel> expected;
  for (int bit : {1, 0, 1, 1, 0, 0, 0, 0, 0, 1}) expected.push_back(gray(bit ? 255 : 0));
  EXPECT_TRUE(pixels_are(decode_rgba_image(png_file(bits), "b.png"), 10, 1, expected));

  auto adam7 = testing_support::png_spec(9, 9, 8, PNG_COLOR_TYPE_RGB);
  adam7.interlaced = true;
  expected.clear();
  for (int y = 0; y < 9; ++y) {
    Bytes row;
    for (int x = 0; x < 9; ++x) {
      const Pixel p{static_cast<std::uint8_t>(20 * x), static_cast<std::uint8_t>(20 * y),
                    static_cast<std::uint8_t>(x * y), 255};
      row.push_back(p.r);
      row.push_back(p.g);
      row.push_back(p.b);
      expected.push_back(p);
    }
    adam7.rows.push_back(row);
  }
  EXPECT_TRUE(pixels_are(decode_rgba_image(png_file(adam7), "i.png"), 9, 9, expected));
}

// Gray JPEGs of flat 8x8 blocks at quality 100 decode exactly: each block is only its DC term.
Bytes flat_blocks(int width, int height) {
  Bytes samples(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) samples[y * width + x] = (x / 8 + y / 8) % 2 ? 40 : 200;
  }
  return samples;
}

TEST(DecodeJpeg, BaselineAndProgressiveGray) {
  const Bytes samples = flat_blocks(32, 16);
  std::vector<Pixel> expected;
  for (std::uint8_t v : samples) expected.push_back(gray(v));
  for (bool progressive : {false, true}) {
    const Bytes file = testing_support::jpeg_file(32, 16, 1, samples, 100, progressive);
    EXPECT_TRUE(pixels_are(decode_rgba_image(file, "g.jpg"), 32, 16, expected)) << progressive;
  }
}

TEST(DecodeJpeg, ColourIsCloseToTheOriginal) {
  // YCbCr with subsampled chroma is lossy even at quality 100: within a few levels.
  Bytes samples;
  for (int i = 0; i < 16 * 16; ++i) samples.insert(samples.end(), {200, 60, 30});
  const auto image = decode_rgba_image(testing_support::jpeg_file(16, 16, 3, samples), "c.jpg");
  ASSERT_TRUE(image.has_value()) << image.error().message;
  for (const Pixel& p : image->pixels) {
    EXPECT_LE(std::abs(p.r - 200) + std::abs(p.g - 60) + std::abs(p.b - 30), 6);
    EXPECT_EQ(p.a, 255);
  }
}

// Little-endian helpers for the BMP tables.
void put32(Bytes& b, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

TEST(DecodeBmp, PalettedOneFourAndEightBits) {
  const Bytes two = {0, 0, 0, 0, 255, 255, 255, 0};  // black, white (b, g, r, 0)
  // 1-bit, 10x2, bottom-up: the first stored row is the bottom one.
  const Bytes one_bit = testing_support::bmp_file(
      10, 2, 1, {{0b10000000, 0b01000000, 0, 0}, {0xff, 0xc0, 0, 0}}, two);
  std::vector<Pixel> expected(20, gray(255));
  for (int x = 0; x < 10; ++x) expected[10 + x] = gray(x == 0 || x == 9 ? 255 : 0);
  EXPECT_TRUE(pixels_are(decode_rgba_image(one_bit, "1.bmp"), 10, 2, expected));

  Bytes four;
  for (int i = 0; i < 16; ++i)
    four.insert(four.end(), {std::uint8_t(i), std::uint8_t(16 * i), 0, 0});
  const Bytes four_bit = testing_support::bmp_file(3, 1, 4, {{0x1f, 0x20, 0, 0}}, four);
  EXPECT_TRUE(pixels_are(decode_rgba_image(four_bit, "4.bmp"), 3, 1,
                         {{0, 16, 1, 255}, {0, 240, 15, 255}, {0, 32, 2, 255}}));

  const Bytes eight_bit =
      testing_support::bmp_file(2, -2, 8, {{1, 0, 0, 0}, {0, 1, 0, 0}}, two, 0, 40, 2);  // top-down
  EXPECT_TRUE(pixels_are(decode_rgba_image(eight_bit, "8.bmp"), 2, 2,
                         {gray(255), gray(0), gray(0), gray(255)}));
}

TEST(DecodeBmp, TrueColourAndBitfields) {
  // 24-bit: b, g, r; rows padded to 4 bytes.
  const Bytes rgb24 = testing_support::bmp_file(1, 2, 24, {{1, 2, 3, 0}, {4, 5, 6, 0}});
  EXPECT_TRUE(
      pixels_are(decode_rgba_image(rgb24, "24.bmp"), 1, 2, {{6, 5, 4, 255}, {3, 2, 1, 255}}));
  // 32-bit BI_RGB with the fourth byte unused (all zero): opaque.
  const Bytes rgb32 = testing_support::bmp_file(2, 1, 32, {{10, 20, 30, 0, 40, 50, 60, 0}});
  EXPECT_TRUE(
      pixels_are(decode_rgba_image(rgb32, "32.bmp"), 2, 1, {{30, 20, 10, 255}, {60, 50, 40, 255}}));
  // 16-bit BI_RGB is 5-5-5: 0x7fff white, 0x7c00 red.
  const Bytes rgb555 = testing_support::bmp_file(2, 1, 16, {{0xff, 0x7f, 0x00, 0x7c}});
  EXPECT_TRUE(pixels_are(decode_rgba_image(rgb555, "555.bmp"), 2, 1,
                         {{255, 255, 255, 255}, {255, 0, 0, 255}}));
  // 16-bit BI_BITFIELDS 5-6-5 (masks after the 40-byte header): 0x07e0 is pure green.
  Bytes masks;
  for (std::uint32_t m : {0xf800u, 0x07e0u, 0x001fu}) put32(masks, m);
  const Bytes rgb565 = testing_support::bmp_file(2, 1, 16, {{0xe0, 0x07, 0x1f, 0x00}}, masks, 3);
  EXPECT_TRUE(
      pixels_are(decode_rgba_image(rgb565, "565.bmp"), 2, 1, {{0, 255, 0, 255}, {0, 0, 255, 255}}));
  // 32-bit BI_BITFIELDS with alpha, masks inside a version-4 (108-byte) header.
  Bytes v4 = testing_support::bmp_file(1, 1, 32, {{0x11, 0x22, 0x33, 0x80}}, {}, 3, 108);
  Bytes in_header;
  for (std::uint32_t m : {0x00ff0000u, 0x0000ff00u, 0x000000ffu, 0xff000000u}) put32(in_header, m);
  std::copy(in_header.begin(), in_header.end(), v4.begin() + 54);
  EXPECT_TRUE(pixels_are(decode_rgba_image(v4, "v4.bmp"), 1, 1, {{0x33, 0x22, 0x11, 0x80}}));
}

TEST(DecodeBmp, UnsupportedOrDamagedFilesAreClearErrors) {
  EXPECT_EQ(
      error_of(
          decode_rgba_image(testing_support::bmp_file(2, 1, 8, {{0, 0, 0, 0}}, {}, 1), "rle.bmp")),
      "rle.bmp: RLE-compressed BMP is not supported (save it as an uncompressed BMP or a PNG)");
  const Bytes two = {0, 0, 0, 0, 255, 255, 255, 0};
  EXPECT_EQ(error_of(decode_rgba_image(
                testing_support::bmp_file(2, 1, 8, {{1, 7, 0, 0}}, two, 0, 40, 2), "pal.bmp")),
            "pal.bmp: corrupt BMP (pixel (1, 0) uses colour 7 of a palette of 2)");
  Bytes gappy;
  for (std::uint32_t m : {0xf0f0u, 0x0f00u, 0x000fu}) put32(gappy, m);
  EXPECT_EQ(error_of(decode_rgba_image(
                testing_support::bmp_file(1, 1, 16, {{0, 0, 0, 0}}, gappy, 3), "mask.bmp")),
            "mask.bmp: corrupt BMP (colour mask 0x0000f0f0 is not contiguous)");
  EXPECT_EQ(error_of(decode_rgba_image(Bytes{'B', 'M', 0x10, 0, 0, 0}, "tiny.bmp")),
            "tiny.bmp: truncated BMP (the file has 6 bytes, too few for the headers)");
}

TEST(DecodePnm, EveryKindWithComments) {
  const std::vector<Pixel> checker = {gray(0), gray(255), gray(255), gray(0)};
  EXPECT_TRUE(pixels_are(decode_rgba_image(bytes_of("P1\n# a comment\n2 2\n1001"), "a.pbm"), 2, 2,
                         checker));
  // P4 rows are padded to whole bytes: 10 pixels take 2 bytes.
  Bytes p4 = bytes_of("P4 10 1\n");
  p4.insert(p4.end(), {0b10000000, 0b01000000});
  std::vector<Pixel> line(10, gray(255));
  line[0] = line[9] = gray(0);
  EXPECT_TRUE(pixels_are(decode_rgba_image(p4, "b.pbm"), 10, 1, line));
  EXPECT_TRUE(pixels_are(decode_rgba_image(bytes_of("P2 2 2 #c\n 10\n0 10 5 10"), "c.pgm"), 2, 2,
                         {gray(0), gray(255), gray(128), gray(255)}));
  EXPECT_TRUE(
      pixels_are(decode_rgba_image(bytes_of("P3 1 1 255 1 2 3"), "d.ppm"), 1, 1, {{1, 2, 3, 255}}));
  Bytes p5 = bytes_of("P5 2 1 65535\n");
  p5.insert(p5.end(), {0xff, 0xff, 0x80, 0x80});  // 16-bit big-endian samples
  EXPECT_TRUE(pixels_are(decode_rgba_image(p5, "e.pgm"), 2, 1, {gray(255), gray(128)}));
  Bytes p6 = bytes_of("P6 1 1 255\n");
  p6.insert(p6.end(), {9, 8, 7});
  EXPECT_TRUE(pixels_are(decode_rgba_image(p6, "f.ppm"), 1, 1, {{9, 8, 7, 255}}));
}

TEST(DecodePnm, BadHeadersAndSamplesAreClearErrors) {
  EXPECT_EQ(error_of(decode_rgba_image(bytes_of("P2 2 x\x1b[2J 255"), "a.pgm")),
            "a.pgm: corrupt PGM (expected the height, found 'x\\x1b[2J')");
  EXPECT_EQ(error_of(decode_rgba_image(bytes_of("P2 1 1 99999 1"), "b.pgm")),
            "b.pgm: corrupt PGM (the maxval is 99999, above 65535)");
  EXPECT_EQ(error_of(decode_rgba_image(bytes_of("P3 1 1 100 1 200 3"), "c.ppm")),
            "c.ppm: corrupt PPM (sample 2 is 200, above 100)");
  EXPECT_EQ(error_of(decode_rgba_image(bytes_of("P2 2 2 255 1 2 3    "), "d.pgm")),
            "d.pgm: truncated PGM (the file ends before sample 4)");
  EXPECT_EQ(error_of(decode_rgba_image(bytes_of("P6 2 2"), "e.ppm")),
            "e.ppm: truncated PPM (the file ends before the maxval)");
}

TEST(DecodeImage, EmptyAndUnknownInput) {
  EXPECT_EQ(error_of(decode_rgba_image({}, "x")), "x: the file is empty");
  EXPECT_EQ(error_of(decode_rgba_image(bytes_of("II*\0"), "x.tif")),
            "x.tif: TIFF images are not supported (supported: PNG, JPEG, BMP, PNM/PGM/PPM/PBM)");
}

TEST(DecodeMnist, TheImageAtTheIndex) {
  Bytes idx = {0, 0, 8, 3, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 3};
  for (std::uint8_t v = 0; v < 12; ++v) idx.push_back(v);
  const auto image = decode_mnist_image(idx, 1, "m.idx");
  ASSERT_TRUE(image.has_value()) << image.error().message;
  EXPECT_EQ(image->width, 3);
  EXPECT_EQ(image->height, 2);
  EXPECT_EQ(image->pixels, (std::vector<std::uint8_t>{6, 7, 8, 9, 10, 11}));
  idx.pop_back();
  EXPECT_EQ(decode_mnist_image(idx, 1, "m.idx").error().message,
            "m.idx: truncated (27 bytes, image 1 needs 28)");
}

}  // namespace
}  // namespace animkit
