// Scenes rendered offscreen (EGL on Mesa's llvmpipe in CI, no display) and checked pixel by
// pixel: the colours must be where the scene put its objects.
#include "animkit/render/picture_renderer.h"

#include <gtest/gtest.h>

#include <cstring>

#include "../support/picture_checks.h"
#include "animkit/scene/cloth_scene.h"
#include "animkit/scene/ik_scene.h"
#include "animkit/trajectory/lab_shapes.h"

namespace animkit {
namespace {

using namespace testing_support;

// One renderer for the whole binary (making a context takes a while). Without one, every
// test stops here with the reason rather than crashing.
PictureRenderer* shared_renderer_or_null() {
  static auto renderer = PictureRenderer::create(480, 360);
  if (!renderer) {
    ADD_FAILURE() << renderer.error().message;
    return nullptr;
  }
  return &*renderer;
}
class PictureRendererTest : public testing::Test {
 protected:
  void SetUp() override { ASSERT_NE(shared_renderer_or_null(), nullptr); }
  static PictureRenderer& shared_renderer() { return *shared_renderer_or_null(); }
};

TEST_F(PictureRendererTest, MakesAContextWithoutADisplay) {
  auto& renderer = shared_renderer();
  EXPECT_FALSE(renderer.context().description().empty());
  EXPECT_EQ(renderer.width(), 480);
  EXPECT_EQ(renderer.height(), 360);
}

TEST_F(PictureRendererTest, EmptySceneIsBackgroundEverywhere) {
  const Image image = shared_renderer().render(DrawList{}, OrbitCamera{});
  ASSERT_EQ(image.width, 480);
  for (const Pixel& p : image.pixels) ASSERT_TRUE(is_background(p));
}

TEST_F(PictureRendererTest, IkSceneMidDrawingShowsTargetsPathAndArm) {
  auto scene =
      IkScene::create(lab_arm(), Trajectory::all_pen_down(lab_shape_targets(LabShape::star)));
  ASSERT_TRUE(scene.has_value()) << scene.error().message;
  for (int i = 0; i < 200; ++i) scene->advance();
  DrawList list;
  scene->describe(list);
  auto& renderer = shared_renderer();
  const OrbitCamera camera = OrbitCamera::framing(scene->focus_bounds(), renderer.aspect(),
                                                  kIkPictureYaw, kIkPicturePitch);
  const Image image = renderer.render(list, camera);
  keep_for_inspection(image, "ik_mid_drawing");

  // Targets not drawn yet are green; where the arm has been the path is red. A few may hide
  // behind the arm, so most (not all) must show their colour.
  int green = 0, undrawn = 0;
  for (std::size_t i = 200; i < scene->targets().size(); i += 5, ++undrawn) {
    const Pixel* p = pixel_at(image, camera, scene->targets()[i]);
    ASSERT_NE(p, nullptr);
    green += is_green(*p);
  }
  EXPECT_GE(green, undrawn * 8 / 10) << green << " of " << undrawn << " targets green";
  int red = 0, drawn = 0;
  const std::vector<Vec3>& path = scene->path().front();
  for (std::size_t i = 0; i < path.size(); i += 5, ++drawn) {
    const Pixel* p = pixel_at(image, camera, path[i]);
    ASSERT_NE(p, nullptr);
    red += is_red(*p);
  }
  EXPECT_GE(red, drawn * 8 / 10) << red << " of " << drawn << " path points red";
  // The middle of every bone is drawn in the bone colour.
  const auto& joints = scene->pose().global_positions;
  for (std::size_t i = 1; i < joints.size(); ++i) {
    const Pixel* p = pixel_at(image, camera, 0.5 * (joints[i - 1] + joints[i]));
    ASSERT_NE(p, nullptr);
    EXPECT_TRUE(is_bone_blue(*p)) << "bone " << i << " pixel " << int(p->r) << "," << int(p->g)
                                  << "," << int(p->b);
  }
  // The top corners are sky.
  EXPECT_TRUE(is_background(image.at(2, 2)));
  EXPECT_TRUE(is_background(image.at(image.width - 3, 2)));
}

TEST_F(PictureRendererTest, UnreachableTargetIsMarked) {
  auto scene = IkScene::create(lab_arm(), Trajectory::all_pen_down({Vec3(0.3, 0.0, 0.2)}));
  ASSERT_TRUE(scene.has_value());
  ASSERT_TRUE(scene->follow(Vec3(3.5, 0.0, 0.0)).has_value());
  ASSERT_FALSE(scene->last_solve()->result.reachable);
  DrawList list;
  scene->describe(list);
  auto& renderer = shared_renderer();
  const OrbitCamera camera = OrbitCamera::framing(list.bounds(), renderer.aspect(), 0.0, 0.3);
  const Image image = renderer.render(list, camera);
  keep_for_inspection(image, "ik_unreachable");
  const Pixel* p = pixel_at(image, camera, Vec3(3.5, 0.0, 0.0));
  ASSERT_NE(p, nullptr);
  EXPECT_GT(p->r, 200);
  EXPECT_TRUE(p->g > 100 && p->g < 180 && p->b < 60)
      << int(p->r) << "," << int(p->g) << "," << int(p->b);
}

TEST_F(PictureRendererTest, HangingClothCoversItsArea) {
  auto scene = ClothScene::create();
  ASSERT_TRUE(scene.has_value()) << scene.error().message;
  for (int i = 0; i < 90; ++i) ASSERT_TRUE(scene->step().has_value());
  DrawList list;
  scene->describe(list);
  auto& renderer = shared_renderer();
  const OrbitCamera camera = OrbitCamera::framing(scene->focus_bounds(), renderer.aspect(),
                                                  kClothPictureYaw, kClothPicturePitch);
  const Image image = renderer.render(list, camera);
  keep_for_inspection(image, "cloth_hanging");

  // Triangle centres show cloth (front orange or back blue), not the background; a few seen
  // edge-on along a fold may fall between pixel centres.
  const ClothModel& model = scene->simulator().model();
  const ClothState& state = scene->simulator().state();
  int covered = 0;
  for (const auto& t : model.triangles) {
    const Vec3 centre = (state.position(t[0]) + state.position(t[1]) + state.position(t[2])) / 3.0;
    const Pixel* p = pixel_at(image, camera, centre);
    ASSERT_NE(p, nullptr);
    const bool front = p->r > p->b + 40, back = p->b > p->r + 40;
    covered += (front || back) && !is_background(*p);
  }
  EXPECT_GE(covered, static_cast<int>(model.triangles.size()) * 95 / 100);
  // The pinned corners are marked.
  for (int i = 0; i < model.particle_count(); ++i) {
    if (!model.pinned[i]) continue;
    const Pixel* p = pixel_at(image, camera, state.position(i));
    ASSERT_NE(p, nullptr);
    EXPECT_GT(p->r, 150);
    EXPECT_LT(p->g, 80);
  }
}

TEST_F(PictureRendererTest, OffscreenTargetRejectsAnAbsurdSize) {
  shared_renderer().context().make_current();
  auto target = OffscreenTarget::create(0, 100);
  ASSERT_FALSE(target.has_value());
  EXPECT_EQ(target.error().message, "picture size must be between 1x1 and 8192x8192, got 0x100");
}

// Two renderers side by side (the CLI's demo makes one after another): each draws into its
// own context, and deleting one leaves the other working.
TEST(TwoPictureRenderers, DoNotDisturbEachOther) {
  auto first = PictureRenderer::create(64, 48);
  ASSERT_TRUE(first.has_value()) << first.error().message;
  DrawList list;
  list.add_point(Vec3::Zero(), palette::path, 20.0f);
  OrbitCamera camera;
  camera.focus = Vec3::Zero();
  const Image expected = first->render(list, camera);
  {
    auto second = PictureRenderer::create(64, 48);
    ASSERT_TRUE(second.has_value());
    const Image other = second->render(list, camera);
    EXPECT_EQ(0, std::memcmp(other.pixels.data(), expected.pixels.data(),
                             expected.pixels.size() * sizeof(Pixel)));
  }  // the second one goes while the first one's objects must stay
  const Image again = first->render(list, camera);
  ASSERT_EQ(again.pixels.size(), expected.pixels.size());
  EXPECT_EQ(0, std::memcmp(again.pixels.data(), expected.pixels.data(),
                           expected.pixels.size() * sizeof(Pixel)));
  EXPECT_TRUE(is_red(again.at(32, 24)));
}

}  // namespace
}  // namespace animkit
