// What the Python module adds to a cloth step: ClothSimulator::step() called from C++ against
// `sim.step()` called from Python (a Python function calling the bound method, as a script
// does) on the same cloth, in the same run. Both simulate the same steps: the scene's frames
// 31 to 90 from flat (the warm-up state computed once, restored every kWindow steps, untimed).
// Two cloths: the lab's (121 particles), and a 2 x 2 grid whose step costs about a microsecond,
// where the binding's own cost shows plainly. Prints each pair's difference at the end (the
// target: under 5 microseconds per step).
//
// The interpreter is embedded (pybind11::embed); the module is imported from the build's
// python folder (ANIMKIT_PYTHON_DIR), so build animkit_python first (a dependency here).
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>

#include <cstdio>
#include <map>
#include <string>

#include "animkit/cloth/cloth_world.h"
#include "animkit/scene/cloth_scenes.h"

namespace py = pybind11;

namespace {

constexpr int kWarmUpFrames = 30;  // start timing on a moving, deformed cloth
constexpr int kWindow = 60;        // steps timed from the warm state before restoring it

// The lab's scene with `cells` cells per side (the lab's own: 10).
animkit::ClothWorldDesc lab_scene(int cells) {
  animkit::ClothWorldDesc scene = animkit::find_cloth_scene("lab")->make();
  std::get<animkit::GridClothOptions>(scene.cloth).cells = cells;
  return scene;
}

void cpp_step(benchmark::State& state) {
  const animkit::ClothWorldDesc scene = lab_scene(static_cast<int>(state.range(0)));
  auto world = animkit::build_cloth_world(scene);
  if (!world) {
    state.SkipWithError(world.error().message.c_str());
    return;
  }
  animkit::ClothSimulator& sim = world->simulator;
  for (int f = 0; f < kWarmUpFrames; ++f) (void)sim.step(scene.time_step);
  const animkit::ClothState warm = sim.state();
  long steps = 0;
  for (auto _ : state) {
    if (steps++ % kWindow == 0) {
      state.PauseTiming();
      (void)sim.set_state(warm);
      state.ResumeTiming();
    }
    auto report = sim.step(scene.time_step);
    benchmark::DoNotOptimize(report);
  }
}

// The same in Python: animkit.ClothSimulator of the same scene, the same warm state, and a
// Python function `step()` that calls sim.step() (so a Python frame and the call's argument
// parsing, the GIL's release and the StepReport object are all counted).
void python_step(benchmark::State& state) {
  py::dict scope;
  scope["cells"] = state.range(0);
  scope["warm_frames"] = kWarmUpFrames;
  py::exec(R"(
import animkit
scene = animkit.ClothScene.builtin("lab")
grid = scene.cloth
grid.cells = cells
scene.cloth = grid
sim = animkit.ClothSimulator(scene)
sim.run(frames=warm_frames)
warm = (sim.positions.copy(), sim.velocities.copy(), sim.time)

def step():
    sim.step()

def restore():
    sim.set_state(*warm)
)",
           scope);
  const py::object step = scope["step"];
  const py::object restore = scope["restore"];
  long steps = 0;
  for (auto _ : state) {
    if (steps++ % kWindow == 0) {
      state.PauseTiming();
      restore();
      state.ResumeTiming();
    }
    step();
  }
}

BENCHMARK(cpp_step)->ArgName("cells")->Arg(10)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(python_step)->ArgName("cells")->Arg(10)->Arg(1)->Unit(benchmark::kMicrosecond);

// The console report, remembering each benchmark's median (or single run) real time.
class OverheadReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
      const std::string key = run.run_name.function_name + "/" + run.run_name.args;
      times_[key] = {run.GetAdjustedRealTime(), run.GetAdjustedCPUTime()};
    }
  }
  void print_overhead(const std::string& args) const {
    const auto cpp = times_.find("cpp_step/" + args), python = times_.find("python_step/" + args);
    if (cpp == times_.end() || python == times_.end()) return;
    // Real time, and CPU time (steadier on a machine other programs share).
    std::printf(
        "overhead %-10s real: python %.3f us - C++ %.3f us = %.3f us per step; CPU: "
        "%.3f - %.3f = %.3f us\n",
        args.c_str(), python->second.real, cpp->second.real, python->second.real - cpp->second.real,
        python->second.cpu, cpp->second.cpu, python->second.cpu - cpp->second.cpu);
  }

 private:
  struct Times {
    double real = 0.0, cpu = 0.0;  // us per step
  };
  std::map<std::string, Times> times_;
};

}  // namespace

int main(int argc, char** argv) {
  py::scoped_interpreter interpreter;
  py::module_::import("sys").attr("path").attr("insert")(0, ANIMKIT_PYTHON_DIR);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  OverheadReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_overhead("cells:10");
  reporter.print_overhead("cells:1");
  benchmark::Shutdown();
  return 0;
}
