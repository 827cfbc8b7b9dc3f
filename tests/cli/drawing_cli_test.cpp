// Behaviour tests of custom drawings in `animkit ik` and `animkit-viewer`: text, images, MNIST
// digits, CSV curves and even resampling, and a one-line error for every bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/picture_checks.h"
#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "../trajectory/glyph_images.h"
#include "animkit/io/png.h"

namespace drawing_cli_test {

namespace fs = std::filesystem;
using namespace animkit::testing_support;

const std::string kCli = ANIMKIT_CLI_PATH;

fs::path fresh(const std::string& name) {
  return fresh_dir("drawing_cli_" + name);
}

animkit::Image rgba(const animkit::GrayImage& gray) {
  animkit::Image image(gray.width, gray.height);
  for (std::size_t i = 0; i < gray.pixels.size(); ++i) {
    image.pixels[i] = {gray.pixels[i], gray.pixels[i], gray.pixels[i], 255};
  }
  return image;
}

// An MNIST IDX image file with two 28x28 digits, white on black like the real ones: a blank
// one, then a "7".
void write_mnist(const fs::path& path, std::uint32_t magic = 0x00000803u) {
  animkit::GrayImage seven(28, 28, 0);
  paint_line(seven, {6, 6}, {22, 6}, 1.6, 255);
  paint_line(seven, {22, 6}, {11, 23}, 1.6, 255);
  std::vector<unsigned char> bytes;
  for (std::uint32_t v : {magic, 2u, 28u, 28u}) {
    for (int shift = 24; shift >= 0; shift -= 8)
      bytes.push_back(static_cast<unsigned char>(v >> shift));
  }
  bytes.insert(bytes.end(), 28 * 28, 0);
  bytes.insert(bytes.end(), seven.pixels.begin(), seven.pixels.end());
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

nlohmann::json metrics(const fs::path& dir) {
  return nlohmann::json::parse(read_file(dir / "metrics.json"));
}

TEST(DrawingCli, TextIsDrawnInOutlineStrokes) {
  const fs::path out = fresh("text");
  const auto r = run_command(kCli + " ik --text QD --solver fabrik --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("drawing: text QD: 4 strokes"), std::string::npos) << r.out;
  const auto m = metrics(out);
  EXPECT_EQ(m["shape"], "text QD");
  EXPECT_EQ(m["converged_fraction"], 1.0);
  EXPECT_EQ(m["unreachable_targets"], 0);
  EXPECT_EQ(m["drawing"]["strokes"], 4);
  EXPECT_GT(m["drawing"]["pen_up_targets"].get<int>(), 0);
  EXPECT_LT(m["drawing"]["spacing_after"]["cv"].get<double>(), 0.05);
  // path.csv marks the travel between letters with pen_down = 0.
  const std::string csv = read_file(out / "path.csv");
  EXPECT_NE(csv.find(",pen_down\n"), std::string::npos);
  EXPECT_NE(csv.find(",0\n"), std::string::npos);
  const auto image = animkit::read_image(out / "drawing.png");
  ASSERT_TRUE(image.has_value());
  EXPECT_GT(count_pixels(*image, is_red), 2000);
}

TEST(DrawingCli, ImagesAndMnistDigitsAreDrawnAsSkeletons) {
  const fs::path out = fresh("images");
  ASSERT_TRUE(animkit::write_png(out / "eight.png", rgba(eight())).has_value());
  const auto r = run_command(kCli + " ik --image " + (out / "eight.png").string() +
                             " --thinning guo-hall --out " + (out / "eight").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(metrics(out / "eight")["drawing"]["strokes"], 1);
  EXPECT_EQ(metrics(out / "eight")["converged_fraction"], 1.0);
  write_mnist(out / "digits.idx");
  const auto m = run_command(kCli + " ik --mnist " + (out / "digits.idx").string() +
                             " --index 1 --no-picture --out " + (out / "seven").string());
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_EQ(metrics(out / "seven")["shape"], "mnist digits.idx #1");
  EXPECT_EQ(metrics(out / "seven")["drawing"]["strokes"], 1);
  EXPECT_EQ(metrics(out / "seven")["converged_fraction"], 1.0);
}

TEST(DrawingCli, FileNamesWithMarkupOrBadBytesMakeValidReports) {
  // Regression: the SVG was malformed for "a&b<c>.csv" and metrics.json failed on byte 0xff.
  const fs::path dir = fresh("markup_names");
  for (const std::string name : {"a&b<c>.csv", "quote \"\xff\".csv"}) {
    std::ofstream(dir / name) << "0,0\n1,0\n1,1\n";
    const fs::path out = dir / "out";
    const auto r = run_command(kCli + " ik --no-picture --curve '" + (dir / name).string() +
                               "' --out '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(run_command("xmllint --noout '" + (out / "drawing.svg").string() + "'").exit_code, 0)
        << name;
    EXPECT_EQ(metrics(out)["shape"].get<std::string>().rfind("curve ", 0), 0u);
  }
}

TEST(DrawingCli, CurvesAndEvenSpacing) {
  const fs::path out = fresh("curve");
  std::ofstream(out / "ab.csv") << "0,0\n0,1\n1,1\n\n2,0\n3,1\n";
  const auto c = run_command(kCli + " ik --curve " + (out / "ab.csv").string() +
                             " --box 0.1,0.1,0.4 --no-picture --out " + (out / "ab").string());
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_EQ(metrics(out / "ab")["drawing"]["strokes"], 2);
  const auto uneven =
      run_command(kCli + " ik --shape spiral --no-picture --out " + (out / "uneven").string());
  const auto even = run_command(kCli + " ik --shape spiral --spacing 0.01 --no-picture --out " +
                                (out / "even").string());
  ASSERT_EQ(uneven.exit_code, 0);
  ASSERT_EQ(even.exit_code, 0);
  EXPECT_GT(metrics(out / "uneven")["drawing"]["spacing_after"]["cv"].get<double>(), 1.0);
  EXPECT_LT(metrics(out / "even")["drawing"]["spacing_after"]["cv"].get<double>(), 0.05);
}

struct BadDrawing {
  std::string args;     // after "animkit ik", with DIR for the test folder
  std::string message;  // expected start of the message after "animkit: error: "
};

void PrintTo(const BadDrawing& b, std::ostream* os) {
  *os << "animkit ik " << b.args;
}

class DrawingCliBadInput : public testing::TestWithParam<BadDrawing> {
 protected:
  static void SetUpTestSuite() {
    const fs::path dir = fresh("bad");
    std::ofstream(dir / "empty.png");
    std::ofstream(dir / "notes.png") << "not an image";
    ASSERT_TRUE(animkit::write_png(dir / "seven.png", rgba(seven())).has_value());
    const std::string png = read_file(dir / "seven.png");
    std::ofstream(dir / "cut.png", std::ios::binary) << png.substr(0, png.size() / 2);
    ASSERT_TRUE(
        animkit::write_png(dir / "white.png", rgba(animkit::GrayImage(30, 30, 255))).has_value());
    ASSERT_TRUE(
        animkit::write_png(dir / "black.png", rgba(animkit::GrayImage(30, 30, 0))).has_value());
    ASSERT_TRUE(animkit::write_png(dir / "huge.png", animkit::Image(4100, 2)).has_value());
    write_mnist(dir / "labels.idx", 0x00000801u);
    write_mnist(dir / "digits.idx");
    std::ofstream(dir / "bad.csv") << "0,0\n1,x\n";
    std::ofstream(dir / "inf.csv") << "0,0\n1e999,0\n";
    std::ofstream(dir / "far.csv") << "1e308,0\n-1e308,0\n";
    std::ofstream(dir / "nul.csv") << "0,0\n" << std::string("1,1\0", 4) << "\n";
    folder() = dir;
  }
  static fs::path& folder() {
    static fs::path dir;
    return dir;
  }
};

TEST_P(DrawingCliBadInput, OneLineOnStderrAndExitCode2) {
  std::string args = GetParam().args;
  for (auto at = args.find("DIR"); at != std::string::npos; at = args.find("DIR")) {
    args.replace(at, 3, folder().string());
  }
  std::string message = GetParam().message;
  for (auto at = message.find("DIR"); at != std::string::npos; at = message.find("DIR")) {
    message.replace(at, 3, folder().string());
  }
  const auto r = run_command(kCli + " ik " + args + " --no-picture");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("animkit: error: " + message, 0), 0u) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DrawingCliBadInput,
    testing::Values(
        BadDrawing{"--image DIR/missing.png", "DIR/missing.png: no such file"},
        BadDrawing{"--image DIR/empty.png", "DIR/empty.png: the file is empty"},
        BadDrawing{"--image DIR/notes.png",
                   "DIR/notes.png: not an image format animkit reads (supported: PNG, JPEG, BMP, "
                   "PNM/PGM/PPM/PBM)"},
        BadDrawing{"--image DIR/cut.png", "DIR/cut.png: truncated PNG (the file ends after"},
        BadDrawing{"--image DIR/white.png",
                   "DIR/white.png: the image is a single shade (gray 255): nothing to draw"},
        BadDrawing{"--image DIR/black.png",
                   "DIR/black.png: the image is a single shade (gray 0): nothing to draw"},
        BadDrawing{"--image DIR/huge.png", "DIR/huge.png: the image is 4100x2 pixels, larger"},
        BadDrawing{"--mnist DIR/labels.idx",
                   "DIR/labels.idx: not an MNIST image file (magic number 0x00000801"},
        BadDrawing{"--mnist DIR/digits.idx --index 2",
                   "DIR/digits.idx: image index 2 is out of range (the file has 2 images)"},
        BadDrawing{"--mnist DIR/digits.idx --index 0",
                   "DIR/digits.idx: the image is a single shade (gray 0): nothing to draw"},
        BadDrawing{"--text QD --font DIR/none.ttf", "font DIR/none.ttf: no such file"},
        BadDrawing{"--text QD --font DIR/notes.png",
                   "font DIR/notes.png: not a font FreeType can read"},
        BadDrawing{"--text ''", "the text is empty"},
        BadDrawing{"--text ' '", "the text has no visible glyphs"},
        BadDrawing{"--curve DIR/bad.csv",
                   "DIR/bad.csv line 2: expected two finite numbers x,z, got '1,x'"},
        BadDrawing{"--curve DIR/none.csv", "DIR/none.csv: no such file"},
        BadDrawing{"--curve DIR/inf.csv",
                   "DIR/inf.csv line 2: the point is not finite, got '1e999,0'"},
        BadDrawing{"--curve DIR/nul.csv",
                   "DIR/nul.csv line 2: holds a NUL byte (not a text file?): '1,1\\x00'"},
        BadDrawing{"--text QD --font DIR", "font DIR: is a folder, not a file"},
        BadDrawing{"--curve DIR/far.csv",
                   "DIR/far.csv: the drawing is too large to place (its size overflows)"},
        BadDrawing{"--text QD --image DIR/seven.png", "--text excludes --image"},
        BadDrawing{"--image DIR/seven.png --thinning medial", "unknown --thinning 'medial'"},
        BadDrawing{"--image DIR/seven.png --threshold 300",
                   "threshold must be a gray level from 0 to 254"},
        BadDrawing{"--text QD --box 0,0,-1", "--box must be X,Z,HALF with HALF > 0, got '0,0,-1'"},
        BadDrawing{"--shape spiral --spacing 0", "spacing must be a positive finite number, got 0"},
        BadDrawing{"--index 3", "--index requires --mnist"},
        BadDrawing{"--target 1,0,0 --text QD", "--target excludes --text"},
        BadDrawing{"--target 1,0,0 --spacing 0.1", "--target is one point"},
        BadDrawing{"--text QD --threshold 100", "--threshold applies to --image and --mnist only"},
        BadDrawing{"--shape star --thinning guo-hall",
                   "--thinning applies to --image and --mnist only"},
        BadDrawing{"--shape star --picture-frame 400",
                   "--picture-frame 400 is past the last frame (399)"}),
    [](const auto& param_info) { return "case" + std::to_string(param_info.index); });

#ifdef ANIMKIT_VIEWER_PATH
TEST(DrawingViewer, DrawsTextFromTheCommandLine) {
  const fs::path out = fresh("viewer");
  const auto r = run_command(std::string(ANIMKIT_VIEWER_PATH) +
                             " --text AK --frames 400 --capture " + (out / "ak.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto image = animkit::read_image(out / "ak.png");
  ASSERT_TRUE(image.has_value());
  EXPECT_GT(count_pixels(*image, is_red, 380), 1000);
  const auto bad = run_command(std::string(ANIMKIT_VIEWER_PATH) +
                               " --text '' --frames 1 --capture " + (out / "x.png").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err, "animkit-viewer: error: the text is empty\n");
}
#endif

}  // namespace drawing_cli_test
