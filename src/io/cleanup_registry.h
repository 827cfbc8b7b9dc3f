#pragma once
// Internal to animkit_io: the lock of the clean-up registry (temporary_files.h), for steps that
// must not be cut in half by the signal clean-up (the renames of a folder swap).
#include <mutex>

namespace animkit::detail {

/// Held while it lives: the signal clean-up waits for it, so a swap is done or not begun.
std::unique_lock<std::mutex> lock_cleanup_registry();

}  // namespace animkit::detail
