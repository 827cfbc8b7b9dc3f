#pragma once
// Constants that several unit-test files use, defined once: the unit tests compile as unity
// batches (tests/CMakeLists.txt), where two files' own definitions of one name would clash.
// A file takes the ones it uses with `using testing_support::kFrame;` (a using-declaration may
// be repeated, a definition may not).
#include <filesystem>
#include <limits>
#include <numbers>

namespace animkit::testing_support {

/// One frame at 60 Hz (s).
inline constexpr double kFrame = 1.0 / 60.0;

inline constexpr double kPi = std::numbers::pi;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

#ifdef ANIMKIT_TEST_DATA_DIR
/// The CMU motion-capture walk (data/cmu/131_01.bvh), in the file's own units.
inline const std::filesystem::path kWalk = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";
#endif

}  // namespace animkit::testing_support
