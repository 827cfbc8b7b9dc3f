// Reading drawings: images, MNIST files, CSV curves and text, and the errors for bad ones.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <span>

#include "../support/temp_files.h"
#include "../trajectory/glyph_images.h"
#include "animkit/io/curve_csv.h"
#include "animkit/io/image_input.h"
#include "animkit/io/png.h"
#include "animkit/io/text_strokes.h"

namespace animkit {
namespace {

using testing_support::fresh_dir;

void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

// An MNIST IDX image file of `count` 28x28 images; image i is filled with gray 10 * i.
std::vector<unsigned char> mnist_bytes(std::uint32_t magic, std::uint32_t count) {
  std::vector<unsigned char> b;
  for (std::uint32_t v : {magic, count, 28u, 28u}) {
    for (int shift = 24; shift >= 0; shift -= 8)
      b.push_back(static_cast<unsigned char>(v >> shift));
  }
  for (std::uint32_t i = 0; i < count; ++i)
    b.insert(b.end(), 28 * 28, static_cast<unsigned char>(10 * i));
  return b;
}

Image rgba(const GrayImage& gray) {
  Image image(gray.width, gray.height);
  for (std::size_t i = 0; i < gray.pixels.size(); ++i) {
    image.pixels[i] = {gray.pixels[i], gray.pixels[i], gray.pixels[i], 255};
  }
  return image;
}

TEST(ReadGrayImage, ReadsAPngBack) {
  const auto dir = fresh_dir("gray_png");
  ASSERT_TRUE(write_png(dir / "seven.png", rgba(testing_support::seven())).has_value());
  const auto image = read_gray_image(dir / "seven.png");
  ASSERT_TRUE(image.has_value()) << image.error().message;
  EXPECT_EQ(image->width, 64);
  EXPECT_EQ(image->at(30, 12), 0);   // ink
  EXPECT_EQ(image->at(2, 60), 255);  // paper
}

TEST(ReadGrayImage, BadFilesAreClearErrors) {
  const auto dir = fresh_dir("gray_bad");
  EXPECT_EQ(read_gray_image(dir / "missing.png").error().message,
            (dir / "missing.png").string() + ": no such file");
  write_bytes(dir / "empty.png", {});
  EXPECT_EQ(read_gray_image(dir / "empty.png").error().message,
            (dir / "empty.png").string() + ": the file is empty");
  std::ofstream(dir / "notes.png") << "these are not pixels";
  EXPECT_EQ(read_gray_image(dir / "notes.png").error().message,
            (dir / "notes.png").string() +
                ": not an image format animkit reads (supported: PNG, JPEG, BMP, PNM/PGM/PPM/PBM)");
  // A real PNG cut in half.
  ASSERT_TRUE(write_png(dir / "whole.png", rgba(testing_support::seven())).has_value());
  const std::string whole = testing_support::read_file(dir / "whole.png");
  std::ofstream(dir / "cut.png", std::ios::binary) << whole.substr(0, whole.size() / 2);
  const auto cut = read_gray_image(dir / "cut.png");
  ASSERT_FALSE(cut.has_value());
  EXPECT_EQ(cut.error().message.rfind((dir / "cut.png").string() + ": truncated PNG (", 0), 0u);
  // A huge image is refused from its header, before decoding.
  ASSERT_TRUE(write_png(dir / "huge.png", Image(5000, 1)).has_value());
  EXPECT_EQ(read_gray_image(dir / "huge.png").error().message,
            (dir / "huge.png").string() +
                ": the image is 5000x1 pixels, larger than the limit of 4096x4096");
  std::filesystem::create_directory(dir / "folder.png");
  EXPECT_EQ(read_gray_image(dir / "folder.png").error().message,
            (dir / "folder.png").string() + ": is a folder, not a file");
}

TEST(ReadGrayImage, TransparentPaperIsWhite) {
  const auto dir = fresh_dir("gray_alpha");
  Image image(16, 16);                                           // transparent everywhere ...
  for (int x = 2; x < 14; ++x) image.at(x, 8) = {0, 0, 0, 255};  // ... but an opaque black line
  image.at(1, 1) = {0, 0, 0, 128};                               // half-covered ink
  ASSERT_TRUE(write_png(dir / "line.png", image).has_value());
  const auto gray = read_gray_image(dir / "line.png");
  ASSERT_TRUE(gray.has_value());
  EXPECT_EQ(gray->at(0, 0), 255);
  EXPECT_EQ(gray->at(5, 8), 0);
  EXPECT_EQ(gray->at(1, 1), 127);
}

TEST(ReadMnist, ReadsTheImageAtTheIndex) {
  const auto dir = fresh_dir("mnist");
  write_bytes(dir / "images.idx", mnist_bytes(0x00000803u, 3));
  const auto image = read_mnist_image(dir / "images.idx", 2);
  ASSERT_TRUE(image.has_value()) << image.error().message;
  EXPECT_EQ(image->width, 28);
  EXPECT_EQ(image->height, 28);
  EXPECT_EQ(image->at(5, 7), 20);
}

TEST(ReadMnist, BadFilesAreClearErrors) {
  const auto dir = fresh_dir("mnist_bad");
  write_bytes(dir / "labels.idx", mnist_bytes(0x00000801u, 3));
  EXPECT_EQ(read_mnist_image(dir / "labels.idx", 0).error().message,
            (dir / "labels.idx").string() +
                ": not an MNIST image file (magic number 0x00000801, expected 0x00000803)");
  write_bytes(dir / "images.idx", mnist_bytes(0x00000803u, 3));
  EXPECT_EQ(
      read_mnist_image(dir / "images.idx", 3).error().message,
      (dir / "images.idx").string() + ": image index 3 is out of range (the file has 3 images)");
  EXPECT_EQ(
      read_mnist_image(dir / "images.idx", -1).error().message,
      (dir / "images.idx").string() + ": image index -1 is out of range (the file has 3 images)");
  std::vector<unsigned char> cut = mnist_bytes(0x00000803u, 3);
  cut.resize(16 + 28 * 28 + 100);
  write_bytes(dir / "cut.idx", cut);
  EXPECT_EQ(read_mnist_image(dir / "cut.idx", 1).error().message,
            (dir / "cut.idx").string() + ": truncated (900 bytes, image 1 needs 1584)");
  write_bytes(dir / "short.idx", {0, 0, 8, 3});
  EXPECT_EQ(read_mnist_image(dir / "short.idx", 0).error().message,
            (dir / "short.idx").string() + ": too short for an MNIST IDX header (16 bytes)");
}

TEST(ReadCurveCsv, BlankLinesLiftThePen) {
  const auto dir = fresh_dir("curve");
  std::ofstream(dir / "c.csv") << "# my initials\n0,0\n1, 0\n\n\n2,1\n3,1.5\n4,2\n";
  const auto strokes = read_curve_csv(dir / "c.csv");
  ASSERT_TRUE(strokes.has_value()) << strokes.error().message;
  ASSERT_EQ(strokes->size(), 2u);
  EXPECT_EQ((*strokes)[0].size(), 2u);
  EXPECT_EQ((*strokes)[1].size(), 3u);
  EXPECT_EQ((*strokes)[1][2], Point2(4.0, -2.0));  // z down the page is v up
}

TEST(ReadCurveCsv, BadFilesNameTheLine) {
  const auto dir = fresh_dir("curve_bad");
  std::ofstream(dir / "bad.csv") << "0,0\n1,2\nx,3\n";
  EXPECT_EQ(read_curve_csv(dir / "bad.csv").error().message,
            (dir / "bad.csv").string() + " line 3: expected two finite numbers x,z, got 'x,3'");
  std::ofstream(dir / "empty.csv") << "# nothing\n\n";
  EXPECT_EQ(read_curve_csv(dir / "empty.csv").error().message,
            (dir / "empty.csv").string() + ": no points (expected lines of x,z)");
  EXPECT_EQ(read_curve_csv(dir / "missing.csv").error().message,
            (dir / "missing.csv").string() + ": no such file");
  EXPECT_EQ(read_curve_csv(dir).error().message, dir.string() + ": is a folder, not a file");
}

TEST(ReadCurveCsv, NonFinitePointsNameTheFileAndLine) {
  const auto dir = fresh_dir("curve_nonfinite");
  for (const std::string line : {"1e999,0", "nan,1", "0, -inf"}) {
    std::ofstream(dir / "p.csv") << "0,0\n" << line << "\n";
    EXPECT_EQ(read_curve_csv(dir / "p.csv").error().message,
              (dir / "p.csv").string() + " line 2: the point is not finite, got '" + line + "'");
  }
}

TEST(ReadCurveCsv, ANulByteIsRefusedWithItsLine) {
  // Regression: the line was read as "1,2" and the rest of it silently dropped.
  const auto dir = fresh_dir("curve_nul");
  std::ofstream(dir / "nul.csv") << "0,0\n" << std::string("1,2\0 junk", 9) << "\n3,4\n";
  EXPECT_EQ(
      read_curve_csv(dir / "nul.csv").error().message,
      (dir / "nul.csv").string() + " line 2: holds a NUL byte (not a text file?): '1,2\\x00 junk'");
}

TEST(ReadCurveCsv, RawLinesAreQuotedShortAndSafe) {
  const auto dir = fresh_dir("curve_quoted");
  std::ofstream(dir / "long.csv") << "0,0\n" << std::string(10'000'000, '7') << "\n";
  const std::string message = read_curve_csv(dir / "long.csv").error().message;
  EXPECT_LT(message.size(), dir.string().size() + 200) << message.substr(0, 300);
  EXPECT_NE(message.find("...' (10000000 bytes)"), std::string::npos) << message.substr(0, 300);
  std::ofstream(dir / "escape.csv") << "1,\x1b[2J\r\n";
  EXPECT_EQ(read_curve_csv(dir / "escape.csv").error().message,
            (dir / "escape.csv").string() +
                " line 1: expected two finite numbers x,z, got '1,\\x1b[2J\\r'");
}

TEST(TextStrokes, QdHasFourClosedContours) {
  const auto strokes = text_strokes("QD");
  ASSERT_TRUE(strokes.has_value()) << strokes.error().message;
  ASSERT_EQ(strokes->size(), 4u);  // Q: outside and inside; D: outside and inside
  for (const Stroke& s : *strokes) {
    EXPECT_LT((s.front() - s.back()).norm(), 1e-12);  // closed
    EXPECT_GT(s.size(), 8u);                          // curves are flattened into many points
  }
  // The em is 1: capitals are about 0.73 em tall and the two letters about 1.5 em wide.
  Eigen::AlignedBox2d box;
  for (const Stroke& s : *strokes) {
    for (const Point2& p : s) box.extend(p);
  }
  EXPECT_NEAR(box.sizes().y(), 0.9, 0.2);  // Q's tail goes below the baseline
  EXPECT_NEAR(box.sizes().x(), 1.5, 0.25);
}

TEST(TextStrokes, FlatteningFollowsTheTolerance) {
  const auto coarse = text_strokes("O", {.tolerance = 0.02});
  const auto fine = text_strokes("O", {.tolerance = 0.0005});
  ASSERT_TRUE(coarse && fine);
  EXPECT_LT(coarse->front().size() * 3, fine->front().size());
}

TEST(TextStrokes, ABoldTKeepsItsBarAsACentreLine) {
  const auto strokes = text_strokes(
      "T", {.font = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf", .centerline = true});
  ASSERT_TRUE(strokes.has_value()) << strokes.error().message;
  EXPECT_EQ(strokes->size(), 2u);  // three ends at one junction: two strokes
}

TEST(TextStrokes, CentreLinesAreSingleStrokes) {
  const auto strokes = text_strokes("L", {.centerline = true});
  ASSERT_TRUE(strokes.has_value()) << strokes.error().message;
  ASSERT_EQ(strokes->size(), 1u);  // an L is one stroke down and across
  EXPECT_GT((strokes->front().front() - strokes->front().back()).norm(), 0.3);
}

TEST(TextStrokes, BadTextAndFontsAreClearErrors) {
  EXPECT_EQ(text_strokes("").error().message, "the text is empty");
  EXPECT_EQ(text_strokes("   ").error().message, "the text has no visible glyphs");
  for (const char* bad : {"\xff", "\xc0\x8a",
                          "Q\xc0\xaf"
                          "D",
                          "\xed\xa0\x80", "\xf5\x80\x80\x80", "\xe4\xb8"}) {
    EXPECT_EQ(text_strokes(bad).error().message, "the text is not valid UTF-8") << bad;
  }
  EXPECT_EQ(text_strokes("A", {.font = "/nonexistent/font.ttf"}).error().message,
            "font /nonexistent/font.ttf: no such file");
  const auto dir = fresh_dir("font_bad");
  std::ofstream(dir / "fake.ttf") << "not a font";
  EXPECT_EQ(text_strokes("A", {.font = dir / "fake.ttf"})
                .error()
                .message.rfind(
                    "font " + (dir / "fake.ttf").string() + ": not a font FreeType can read", 0),
            0u);
  EXPECT_EQ(text_strokes("\xe4\xb8\xad").error().message,
            "font " + kDefaultFont.string() + " has no glyph for U+4E2D");
}

TEST(TextStrokes, FoldersAndOtherFilesAreNamedForWhatTheyAre) {
  // Regression: a folder was reported as "no such file".
  const auto dir = fresh_dir("font_kinds");
  EXPECT_EQ(text_strokes("A", {.font = dir}).error().message,
            "font " + dir.string() + ": is a folder, not a file");
  std::ofstream(dir / "empty.ttf").flush();
  EXPECT_EQ(text_strokes("A", {.font = dir / "empty.ttf"}).error().message,
            "font " + (dir / "empty.ttf").string() + ": the file is empty");
  std::ofstream(dir / "notes.txt") << "these are not glyphs";
  EXPECT_EQ(
      text_strokes("A", {.font = dir / "notes.txt"}).error().message,
      "font " + (dir / "notes.txt").string() + ": not a font FreeType can read (too short or cut)");
  std::ofstream(dir / "notes-long.txt") << std::string(4000, 'x');
  EXPECT_EQ(text_strokes("A", {.font = dir / "notes-long.txt"}).error().message,
            "font " + (dir / "notes-long.txt").string() +
                ": not a font FreeType can read (unknown file format)");
}

TEST(TextStrokes, AnUnreadableFontSaysWhy) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads any file";
  const auto dir = fresh_dir("font_unreadable");
  std::filesystem::copy_file(kDefaultFont, dir / "locked.ttf");
  std::filesystem::permissions(dir / "locked.ttf", std::filesystem::perms::none);
  EXPECT_EQ(text_strokes("A", {.font = dir / "locked.ttf"}).error().message,
            "font " + (dir / "locked.ttf").string() + ": cannot read it (Permission denied)");
}

TEST(TextStrokes, FontsReadFromMemory) {
  const std::string bytes = testing_support::read_file(kDefaultFont);
  const auto strokes = text_strokes_from_font_data("QD", std::as_bytes(std::span(bytes)), "mem");
  ASSERT_TRUE(strokes.has_value()) << strokes.error().message;
  EXPECT_EQ(strokes->size(), 4u);
  const std::string cut = bytes.substr(0, 1000);
  EXPECT_EQ(text_strokes_from_font_data("Q", std::as_bytes(std::span(cut)), "cut")
                .error()
                .message.rfind("font cut: not a font FreeType can read (", 0),
            0u);
}

}  // namespace
}  // namespace animkit
