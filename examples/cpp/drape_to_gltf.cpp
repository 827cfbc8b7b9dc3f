// The README's C++ example: a built-in scene (a cotton sheet dropped onto a ball) simulated and
// written as glTF 2.0, the library's own run loop handing every frame to the file's sink.
#include <cstdio>

#include "animkit/cloth/cloth_run.h"
#include "animkit/io/gltf_sink.h"
#include "animkit/scene/cloth_scenes.h"

int main() {
  using namespace animkit;
  ClothWorldDesc scene = find_cloth_scene("drape-sphere")->make();
  scene.frames = 10;  // a third of a second: the sheet falls onto the ball
  auto world = build_cloth_world(scene);
  if (!world) return std::fprintf(stderr, "%s\n", world.error().message.c_str()), 2;
  GltfSink gltf("drape.glb");
  ClothSink* const sinks[] = {&gltf};
  auto run = run_cloth(*world, scene.frames, scene.time_step, sinks);
  if (!run || run->divergence) return std::fprintf(stderr, "the run failed\n"), 2;
  std::printf("wrote drape.glb: %d frames\n", summarize(run->steps).frames);
}
