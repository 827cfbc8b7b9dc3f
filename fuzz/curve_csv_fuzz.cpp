// Fuzzes the CSV curve parser (`animkit ik --curve FILE`) and the placement of what it reads.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "animkit/io/curve_csv.h"
#include "animkit/trajectory/trajectory.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using animkit::fuzz::check;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto strokes = animkit::parse_curve_csv(text, "fuzz.csv");
  if (!strokes) {
    animkit::fuzz::check_message(strokes.error().message, "fuzz.csv");
    return 0;
  }
  check(!strokes->empty(), "a parsed curve has a stroke");
  for (const animkit::Stroke& stroke : *strokes) {
    check(!stroke.empty(), "a parsed stroke has a point");
    for (const animkit::Point2& p : stroke) check(p.allFinite(), "parsed points are finite");
  }
  // What the CLI does next: scale into the arm's reach.
  const auto placed =
      animkit::fit_to_box(*strokes, {.center_x = 0.0, .center_z = 0.0, .half_extent = 1.0});
  if (placed) {
    for (const animkit::Stroke& stroke : *placed) {
      for (const animkit::Point2& p : stroke) {
        check(p.allFinite() && p.cwiseAbs().maxCoeff() <= 1.0 + 1e-9,
              "placed points are in the box");
      }
    }
  }
  return 0;
}
