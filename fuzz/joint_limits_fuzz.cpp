// Fuzzes the joint limits reader (`animkit ik --limits FILE.json`, `reach --limits`): any bytes
// give either a set of valid limits or one clean error line naming the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "animkit/io/joint_limits_file.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto limits = animkit::read_joint_limits(text, "fuzz.json");
  if (!limits) animkit::fuzz::check_message(limits.error().message, "fuzz.json");
  return 0;
}
