// Reading pictures from files: broken files (cut short, damaged, lying headers, huge sizes)
// are clear errors naming the file, never a picture with invented pixels. Each file is made
// here from known pixels, then cut or damaged. (All but the huge sizes went wrong with
// stb_image, which the readers replaced.)
#include "animkit/io/image_input.h"

#include <gtest/gtest.h>
#include <png.h>

#include <fstream>

#include "../support/image_encoders.h"
#include "../support/temp_files.h"
#include "animkit/io/png.h"

namespace animkit {
namespace {

using testing_support::Bytes;
using testing_support::fresh_dir;

std::string write(const std::filesystem::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

// The error message of a read, or a note of what was decoded instead.
template <class T>
std::string error_of(const Result<T>& result) {
  if (result)
    return "(no error: decoded " + std::to_string(result->width) + "x" +
           std::to_string(result->height) + ")";
  return result.error().message;
}

Bytes cut(Bytes bytes, std::size_t size) {
  bytes.resize(size);
  return bytes;
}

// A 24-bit BMP with a gradient (rows padded to 4 bytes).
Bytes gradient_bmp(int width, int height) {
  std::vector<Bytes> rows;
  for (int y = 0; y < height; ++y) {
    Bytes row;
    for (int x = 0; x < width; ++x) {
      // push_back, not insert of a list: GCC 12 at -O3 warns falsely (stringop-overflow).
      row.push_back(static_cast<std::uint8_t>(x));
      row.push_back(static_cast<std::uint8_t>(y));
      row.push_back(200);
    }
    row.resize((row.size() + 3) / 4 * 4, 0);
    rows.push_back(row);
  }
  return testing_support::bmp_file(width, height, 24, rows);
}

// A 40x30 gray picture with ink in the middle, as 8-bit gray samples.
Bytes drawing(int width, int height) {
  Bytes samples(static_cast<std::size_t>(width) * height, 255);
  for (int y = height / 4; y < 3 * height / 4; ++y) {
    for (int x = width / 4; x < 3 * width / 4; ++x) samples[y * width + x] = 0;
  }
  return samples;
}

Bytes gray_png(int width, int height) {
  auto spec = testing_support::png_spec(width, height, 8, PNG_COLOR_TYPE_GRAY);
  const Bytes samples = drawing(width, height);
  for (int y = 0; y < height; ++y) {
    spec.rows.emplace_back(samples.begin() + y * width, samples.begin() + (y + 1) * width);
  }
  return testing_support::png_file(spec);
}

// A gray picture with some texture, so its JPEG has plenty of entropy-coded data.
Bytes textured_jpeg() {
  Bytes samples(64 * 64);
  for (int i = 0; i < 64 * 64; ++i)
    samples[i] = static_cast<std::uint8_t>((i * 37) ^ (i / 64 * 11));
  return testing_support::jpeg_file(64, 64, 1, samples, 90);
}

TEST(ReadImageFiles, BmpCutAt60PercentIsTruncated) {
  const auto dir = fresh_dir("bmp_cut");
  const Bytes whole = gradient_bmp(100, 60);
  ASSERT_EQ(whole.size(), 18054u);
  const auto file = write(dir / "cut.bmp", cut(whole, whole.size() * 6 / 10));
  EXPECT_EQ(error_of(read_gray_image(file)),
            file +
                ": truncated BMP (100x60 pixels at 24 bits need 18054 bytes, the file has "
                "10832)");
  EXPECT_EQ(error_of(read_image(file)), error_of(read_gray_image(file)));
}

TEST(ReadImageFiles, BmpHeaderClaimingMoreRowsThanTheFileHoldsIsTruncated) {
  const auto dir = fresh_dir("bmp_lie");
  Bytes bytes = gradient_bmp(100, 10);
  bytes[22] = 100;  // the height says 100 rows; 10 are there
  const auto file = write(dir / "lie.bmp", bytes);
  EXPECT_EQ(error_of(read_gray_image(file)),
            file +
                ": truncated BMP (100x100 pixels at 24 bits need 30054 bytes, the file has "
                "3054)");
}

TEST(ReadImageFiles, PgmWithHalfItsPixelsIsTruncated) {
  const auto dir = fresh_dir("pgm_half");
  Bytes bytes = testing_support::bytes_of("P5\n40 30\n255\n");
  const Bytes pixels = drawing(40, 30);
  bytes.insert(bytes.end(), pixels.begin(), pixels.begin() + pixels.size() / 2);
  const auto file = write(dir / "half.pgm", bytes);
  EXPECT_EQ(error_of(read_gray_image(file)),
            file +
                ": truncated PGM (40x30 pixels need 1200 bytes after the header, only 600 "
                "follow it)");
}

TEST(ReadImageFiles, HugePgmHeaderWithAFewBytesIsTruncatedNotASingleShade) {
  const auto dir = fresh_dir("pgm_huge");
  Bytes bytes = testing_support::bytes_of("P5\n4096 4096\n255\n");
  bytes.insert(bytes.end(), 100, 0);
  const auto file = write(dir / "huge.pgm", bytes);
  EXPECT_EQ(error_of(read_gray_image(file)),
            file +
                ": truncated PGM (4096x4096 pixels need 16777216 bytes after the header, only "
                "100 follow it)");
}

TEST(ReadImageFiles, PngCutInsideItsPixelDataIsTruncated) {
  const auto dir = fresh_dir("png_cut_idat");
  const Bytes whole = gray_png(40, 30);
  const auto file = write(dir / "cut.png", cut(whole, 60));  // IDAT starts at byte 33
  EXPECT_EQ(error_of(read_gray_image(file)),
            file + ": truncated PNG (the file ends after 60 bytes)");
}

TEST(ReadImageFiles, PngCutBeforeIendIsTruncated) {
  const auto dir = fresh_dir("png_cut_iend");
  const Bytes whole = gray_png(40, 30);
  const Bytes short_file = cut(whole, whole.size() - 12);  // IEND is the last 12 bytes
  const auto file = write(dir / "cut.png", short_file);
  EXPECT_EQ(error_of(read_gray_image(file)), file + ": truncated PNG (the file ends after " +
                                                 std::to_string(short_file.size()) + " bytes)");
}

TEST(ReadImageFiles, PngWithADamagedChunkIsCorrupt) {
  const auto dir = fresh_dir("png_crc");
  const Bytes whole = gray_png(40, 30);
  Bytes bad_crc = whole;
  bad_crc[whole.size() - 16] ^= 0x55;  // the IDAT chunk's CRC, just before IEND's 12 bytes
  const auto crc_file = write(dir / "crc.png", bad_crc);
  EXPECT_EQ(error_of(read_gray_image(crc_file)),
            crc_file + ": corrupt PNG (libpng: IDAT: CRC error)");
  // Damaged compressed data: zlib's own checksum fails before the chunk's CRC is reached.
  Bytes bad_data = whole;
  bad_data[45] ^= 0x55;
  const auto data_file = write(dir / "data.png", bad_data);
  EXPECT_EQ(error_of(read_gray_image(data_file)),
            data_file + ": corrupt PNG (libpng: IDAT: incorrect data check)");
}

TEST(ReadImageFiles, JpegCutShortIsTruncated) {
  const auto dir = fresh_dir("jpeg_cut");
  const Bytes whole = textured_jpeg();
  const auto file = write(dir / "cut.jpg", cut(whole, whole.size() * 6 / 10));
  EXPECT_EQ(error_of(read_gray_image(file)),
            file + ": truncated JPEG (libjpeg: Premature end of JPEG file)");
}

TEST(ReadImageFiles, JpegWithGarbageInItsDataIsCorrupt) {
  const auto dir = fresh_dir("jpeg_garbage");
  Bytes bytes = textured_jpeg();
  // Overwrite a stretch in the middle of the entropy-coded data (which runs to the EOI marker
  // in the last two bytes). The garbage decodes as shorter codes, so the picture ends early
  // and the bytes left before EOI give it away (libjpeg would only warn and return pixels).
  for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 40; ++i) bytes[i] = 0xfe;
  const auto file = write(dir / "garbage.jpg", bytes);
  EXPECT_EQ(error_of(read_gray_image(file)),
            file +
                ": corrupt JPEG (libjpeg: Corrupt JPEG data: 145 extraneous bytes before "
                "marker 0xd9)");
}

TEST(ReadImageFiles, HugeDeclaredSizesAreRefusedFromTheHeader) {
  const auto dir = fresh_dir("huge_sizes");
  Bytes bmp = gradient_bmp(4, 4);
  for (int at : {18, 22}) {  // width and height 100000 (0x000186a0)
    bmp[at] = 0xa0;
    bmp[at + 1] = 0x86;
    bmp[at + 2] = 0x01;
  }
  const auto bmp_file = write(dir / "huge.bmp", bmp);
  EXPECT_EQ(error_of(read_gray_image(bmp_file)),
            bmp_file + ": the image is 100000x100000 pixels, larger than the limit of 4096x4096");
  const auto pgm_file = write(dir / "huge.pgm", testing_support::bytes_of("P5 50000 3 255\n"));
  EXPECT_EQ(error_of(read_gray_image(pgm_file)),
            pgm_file + ": the image is 50000x3 pixels, larger than the limit of 4096x4096");
  Bytes jpeg = textured_jpeg();
  for (std::size_t i = 0; i + 8 < jpeg.size(); ++i) {
    if (jpeg[i] == 0xff && jpeg[i + 1] == 0xc0) {  // SOF0: height at +5, width at +7
      jpeg[i + 5] = 0xfd, jpeg[i + 6] = 0xe8, jpeg[i + 7] = 0xfd, jpeg[i + 8] = 0xe8;  // 65000
      break;
    }
  }
  const auto jpeg_file = write(dir / "huge.jpg", jpeg);
  EXPECT_EQ(error_of(read_gray_image(jpeg_file)),
            jpeg_file + ": the image is 65000x65000 pixels, larger than the limit of 4096x4096");
}

TEST(ReadImageFiles, OtherFormatsAreRefusedListingTheSupportedOnes) {
  const auto dir = fresh_dir("other_formats");
  const auto gif = write(dir / "a.gif", testing_support::bytes_of("GIF89a\x01\x00\x01\x00"));
  EXPECT_EQ(error_of(read_gray_image(gif)),
            gif + ": GIF images are not supported (supported: PNG, JPEG, BMP, PNM/PGM/PPM/PBM)");
  const auto text = write(dir / "notes.png", testing_support::bytes_of("these are not pixels"));
  EXPECT_EQ(error_of(read_gray_image(text)),
            text +
                ": not an image format animkit reads (supported: PNG, JPEG, BMP, "
                "PNM/PGM/PPM/PBM)");
}

}  // namespace
}  // namespace animkit
