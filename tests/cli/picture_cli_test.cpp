// Behaviour tests of the pictures: PNGs and videos from `animkit`, and `animkit-viewer`
// (headless capture, a real window under Xvfb, and no display at all).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/picture_checks.h"
#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "animkit/io/png.h"
#include "animkit/io/video_writer.h"

namespace picture_cli_test {

namespace fs = std::filesystem;
using animkit::Image;
using animkit::Pixel;
using animkit::read_image;
using animkit::testing_support::run_command;
using namespace animkit::testing_support;

const std::string kCli = ANIMKIT_CLI_PATH;
// No window system and no EGL vendor: glvnd finds no driver, GLFW no display.
const std::string kNoDisplayNoEgl =
    "env -u DISPLAY -u WAYLAND_DISPLAY "
    "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json ";

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("pictures_" + name);
}

Image read_png(const fs::path& path) {
  auto image = read_image(path);
  EXPECT_TRUE(image.has_value()) << image.error().message;
  return image ? *image : Image{};
}

TEST(IkPictures, DrawingPngShowsTheFinishedDrawingAndTheArm) {
  const fs::path out = fresh_dir("ik");
  const auto r = run_command(kCli + " ik --shape star --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("drawing.png"), std::string::npos);
  const Image image = read_png(out / "drawing.png");
  ASSERT_EQ(image.width, 960);
  ASSERT_EQ(image.height, 720);
  EXPECT_GT(count_pixels(image, is_red), 1000);        // the star, drawn
  EXPECT_GT(count_pixels(image, is_bone_blue), 3000);  // the arm
  EXPECT_FALSE(fs::exists(out / "drawing.png.tmp"));
}

TEST(IkPictures, NoPictureWritesNoPng) {
  const fs::path out = fresh_dir("ik_none");
  const auto r = run_command(kCli + " ik --no-picture --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "metrics.json"));
  EXPECT_FALSE(fs::exists(out / "drawing.png"));
}

TEST(ClothPictures, FinalPngShowsTheCloth) {
  const fs::path out = fresh_dir("cloth");
  const auto r =
      run_command(kCli + " cloth --frames 300 --picture-size 480x360 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_png(out / "final.png");
  ASSERT_EQ(image.width, 480);
  EXPECT_GT(count_pixels(image, is_cloth), 480 * 360 / 20);
}

TEST(ClothPictures, AStretchedSheetStaysWholeInFinalPngAndIsSaidToStretch) {
  // The lab's per-particle parameters on a 41 x 41 grid: the sheet hangs 1.9 times its length,
  // far out of the box the start frames. final.png frames the end too: no cloth on its edges.
  const fs::path out = fresh_dir("stretched");
  const auto r = run_command(kCli + " cloth --grid 40 --frames 300 --picture-size 480x360 --out " +
                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("animkit: note: the lab's mass and stiffness are per particle and "
                       "spring, so 41 x 41 particles make a heavier, stretchier sheet"),
            std::string::npos)
      << r.err;
  const Image image = read_png(out / "final.png");
  ASSERT_EQ(image.width, 480);
  EXPECT_GT(count_pixels(image, is_cloth), 480 * 360 / 40);
  int on_edges = 0;
  for (int x = 0; x < image.width; ++x) {
    on_edges += is_cloth(image.at(x, 0)) + is_cloth(image.at(x, image.height - 1));
  }
  for (int y = 0; y < image.height; ++y) {
    on_edges += is_cloth(image.at(0, y)) + is_cloth(image.at(image.width - 1, y));
  }
  EXPECT_EQ(on_edges, 0);
  // A material's sheet is the same at any grid: nothing to say.
  const auto cotton = run_command(kCli + " cloth --material cotton --grid 40 --size 1 --frames 1");
  EXPECT_EQ(cotton.err, "");
}

TEST(Video, EveryFrameGoesToTheVideo) {
  if (!animkit::find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path out = fresh_dir("video");
  const auto r = run_command(kCli + " ik --shape square --picture-size 320x240 --video " +
                             (out / "square.gif").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // One GIF frame per target: the square has 150.
  const auto gif_frames = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 "
      "-show_entries stream=nb_read_frames -of csv=p=0 " +
      (out / "square.gif").string());
  EXPECT_EQ(gif_frames.out, "125\n");  // 150 frames at 60 fps, kept at 50 fps for GIF
  const auto c = run_command(kCli + " cloth --frames 30 --picture-size 320x240 --video " +
                             (out / "cloth.mp4").string());
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_GT(fs::file_size(out / "cloth.mp4"), 1'000u);
  // ffmpeg reads it back with one frame per step plus the start.
  const auto probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 "
      "-show_entries stream=nb_read_frames -of csv=p=0 " +
      (out / "cloth.mp4").string());
  EXPECT_EQ(probe.out, "31\n");
}

TEST(Video, MissingFfmpegStopsTheRunBeforeAnyFile) {
  const fs::path out = fresh_dir("video_missing");
  const auto r = run_command("PATH=/nonexistent " + kCli + " ik --video " +
                             (out / "a.mp4").string() + " --out " + (out / "run").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "animkit: error: cannot write " + (out / "a.mp4").string() +
                       ": ffmpeg is not installed (on Debian: apt-get install ffmpeg)\n");
  EXPECT_FALSE(fs::exists(out / "run"));
}

TEST(Video, AVideoInAMissingFolderIsOneLineAndStopsFirst) {
  if (!animkit::find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const auto r = run_command(kCli + " cloth --frames 5 --video /nonexistent-animkit/a.gif");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "animkit: error: cannot write /nonexistent-animkit/a.gif: no folder "
            "/nonexistent-animkit\n");
}

TEST(Video, AFastSimulationIsCappedAt60FramesPerSecondAtMost) {
  if (!animkit::find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path out = fresh_dir("video_fast");
  // 200 steps per second: every 4th step goes into a 50 fps video (the next stride that
  // stays within 60 fps).
  const auto r = run_command(kCli +
                             " cloth --frames 120 --dt 0.005 --picture-size 160x120 "
                             "--video " +
                             (out / "c.mp4").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto probe = run_command(
      "ffprobe -v error -select_streams v:0 -count_frames "
      "-show_entries stream=nb_read_frames,r_frame_rate -of csv=p=0 " +
      (out / "c.mp4").string());
  EXPECT_EQ(probe.out, "50/1,31\n");  // 121 states (start and 120 steps), every 4th
}

TEST(Pictures, NoDisplayAndNoEglIsAClearErrorAndWritesNothing) {
  const fs::path out = fresh_dir("no_gl");
  const auto r = run_command(kNoDisplayNoEgl + kCli + " cloth --frames 5 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("animkit: error: cannot render pictures: no OpenGL 3.3 context (", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("pass --no-picture"), std::string::npos);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(out / "metrics.json"));
  const auto without =
      run_command(kNoDisplayNoEgl + kCli + " cloth --frames 5 --no-picture --out " + out.string());
  EXPECT_EQ(without.exit_code, 0) << without.err;
}

TEST(Pictures, BadPictureSizeIsRejected) {
  const auto r = run_command(kCli + " ik --picture-size 10x10");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--picture-size: must be WIDTHxHEIGHT, each 16..8192, got '10x10'"),
            std::string::npos)
      << r.err;
}

#ifdef ANIMKIT_VIEWER_PATH
const std::string kViewer = ANIMKIT_VIEWER_PATH;

TEST(Viewer, CapturesTheIkSceneMidDrawingWithItsPanel) {
  const fs::path out = fresh_dir("viewer_ik");
  const auto r = run_command(kViewer + " --scene ik --shape star --frames 200 --capture " +
                             (out / "ik.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_png(out / "ik.png");
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(image.height, 800);
  const int panel = 380;
  EXPECT_GT(count_pixels(image, is_green, panel), 500);       // targets still to draw
  EXPECT_GT(count_pixels(image, is_red, panel), 500);         // the half-drawn path
  EXPECT_GT(count_pixels(image, is_bone_blue, panel), 2000);  // the arm
  // The side panel: dark ImGui background over most of its area.
  int dark_panel = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < panel; ++x) dark_panel += is_dark(image.at(x, y));
  }
  EXPECT_GT(dark_panel, panel * image.height / 2);
}

TEST(Viewer, CapturesTheHangingCloth) {
  const fs::path out = fresh_dir("viewer_cloth");
  const auto r = run_command(kViewer + " --scene cloth --frames 300 --size 800x600 --capture " +
                             (out / "cloth.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_png(out / "cloth.png");
  ASSERT_EQ(image.width, 800);
  EXPECT_GT(count_pixels(image, is_cloth, 380), 420 * 600 / 10);
  EXPECT_GT(count_pixels(image, is_cloth_front, 380),
            420 * 600 / 20);  // hanging: its front faces us
}

// The BVH scene's captured foot trail (orange) and the limit drawn for the selected joint
// (pink), as lines on the light background.
bool is_trail_orange(const Pixel& p) {
  return p.r > 200 && p.g > 90 && p.g < 170 && p.b < 90;
}
bool is_limit_pink(const Pixel& p) {
  return p.r > 200 && p.g < 140 && p.b > 150;
}

TEST(Viewer, CapturesTheWalkWithTrailsALimitAndAHeldWrist) {
  const fs::path out = fresh_dir("viewer_bvh");
  const auto r = run_command(kViewer +
                             " --scene bvh --paused --frame 120 --close-up --select LeftKnee "
                             "--hold LeftWrist:0.1,0.35,0.25 --frames 3 --size 900x600 --capture " +
                             (out / "bvh.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_png(out / "bvh.png");
  ASSERT_EQ(image.width, 900);
  const int panel = 380;
  EXPECT_GT(count_pixels(image, is_bone_blue, panel), 3000);    // the skeleton
  EXPECT_GT(count_pixels(image, is_trail_orange, panel), 100);  // the captured foot trails
  EXPECT_GT(count_pixels(image, is_limit_pink, panel), 100);    // the knee's hinge arc
  EXPECT_GT(count_pixels(image, is_green, panel), 10);          // the held wrist's target
}

TEST(Viewer, RefusesAHeldJointTheClipDoesNotHave) {
  const auto r = run_command(kViewer + " --scene bvh --hold Tail:0,0.1,0 --frames 1 --capture " +
                             (fresh_dir("viewer_bvh_bad") / "x.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--hold: the clip has no joint named 'Tail'"), std::string::npos) << r.err;
  const auto bad = run_command(kViewer + " --scene bvh --hold LeftWrist:1,2 --frames 1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--hold must be JOINT:DX,DY,DZ (metres from the joint), got "
                         "'LeftWrist:1,2'"),
            std::string::npos)
      << bad.err;
  const auto solver = run_command(kViewer + " --scene bvh --solver newton --frames 1");
  EXPECT_EQ(solver.exit_code, 2);
  EXPECT_NE(solver.err.find("unknown solver 'newton' for the BVH scene (expected fabrik, ccd, "
                            "dls or sdls)"),
            std::string::npos)
      << solver.err;
  const auto frame = run_command(kViewer + " --scene bvh --frame 994 --frames 1 --capture " +
                                 (fresh_dir("viewer_bvh_frame") / "x.png").string());
  EXPECT_EQ(frame.exit_code, 2);
  EXPECT_NE(frame.err.find("--frame must be in [0, 993]"), std::string::npos) << frame.err;
}

// The collider's violet (palette::collider), lit: bluer than red, red at least green, unlike
// the background and the floor grid (greener than red) and the cloth's back (far bluer).
bool is_collider_violet(const Pixel& p) {
  return p.r > 60 && p.b > p.r + 8 && p.b > p.g + 12 && p.r + 2 >= p.g && p.b < p.r + 45;
}

TEST(Viewer, CapturesASceneFileWithItsColliderAndContactPoints) {
  // A small cotton sheet dropped half over a ball on the ground: it slides off the ball and
  // lies on the ground, every particle in contact with it.
  const fs::path out = fresh_dir("viewer_scene_file");
  std::ofstream(out / "side.json") << R"({
    "cloth": {"grid": 8, "size": 0.6, "height": 0.45, "pins": "none", "material": "cotton",
              "offset": [-0.3, 0, 0]},
    "colliders": [{"name": "ball", "shape": "sphere", "radius": 0.2, "position": [0.3, 0.2, 0],
                   "tessellation": 2}],
    "ground": {"height": 0}, "solver": {"integrator": "implicit-multigrid", "tolerance": 1e-4},
    "dt": 0.0333333})";
  const auto r = run_command(kViewer + " --scene " + (out / "side.json").string() +
                             " --contacts --frames 12 --size 800x600 --capture " +
                             (out / "side.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_png(out / "side.png");
  const int violet = count_pixels(image, is_collider_violet, 380);
  const int cloth = count_pixels(image, is_cloth, 380);
  const int red = count_pixels(image, is_red, 380);  // contact points (and the x axis)
  EXPECT_GT(violet, 3000);
  EXPECT_GT(cloth, 3000);
  EXPECT_GT(red, 400);
}

TEST(Viewer, RunsThreeFramesInAWindowAndExits) {
  if (run_command("command -v xvfb-run").exit_code != 0) GTEST_SKIP() << "xvfb-run not installed";
  // Leak checking is off for this one run (sanitizer builds): Mesa's GLX driver is unloaded by
  // glfwTerminate with a few allocations LeakSanitizer can then no longer attribute. The
  // viewer's own code is leak-checked by the headless capture tests above.
  const auto r = run_command("ASAN_OPTIONS=detect_leaks=0 xvfb-run -a -s '-screen 0 1400x900x24' " +
                             kViewer + " --frames 3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(Viewer, NoDisplayAndNoEglIsAClearErrorNotACrash) {
  const auto window = run_command(kNoDisplayNoEgl + kViewer + " --frames 3");
  EXPECT_EQ(window.exit_code, 1);
  EXPECT_EQ(window.err.rfind("animkit-viewer: error: cannot open a window (", 0), 0u) << window.err;
  const fs::path out = fresh_dir("viewer_no_gl");
  const auto capture =
      run_command(kNoDisplayNoEgl + kViewer + " --frames 3 --capture " + (out / "x.png").string());
  EXPECT_EQ(capture.exit_code, 1);
  EXPECT_EQ(capture.err.rfind("animkit-viewer: error: no OpenGL 3.3 context (", 0), 0u)
      << capture.err;
  EXPECT_FALSE(fs::exists(out / "x.png"));
}

TEST(Viewer, BadOptionsAreRejected) {
  for (const std::string args :
       {"--scene water", "--solver newton", "--shape hexagon --capture x.png --frames 1",
        "--capture x.png", "--size 10x10", "--frames -1", "--integrator rk4",
        "--scene cloth --grid 0 --capture x.png --frames 1",
        "--scene drape-sphere --mass 2 --capture x.png --frames 1",
        "--scene missing-scene.json --capture x.png --frames 1"}) {
    const auto r = run_command(kViewer + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("animkit-viewer: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}
#endif

}  // namespace picture_cli_test
