#pragma once
// Where the viewer's frames go: a window on the screen, or an offscreen picture.
#include <filesystem>

#include "viewer_app.h"

namespace animkit::viewer {

/// Exit code when no window or OpenGL context can be had (bad input is 2).
constexpr int kExitNoDisplay = 1;

/// Opens a window and runs until it is closed, or for `frames` frames when > 0.
int run_window(const ViewerOptions& options, int frames);

/// Runs `frames` frames offscreen (no display needed: EGL on Mesa) and writes the last one,
/// side panel included, to `capture` as PNG.
int run_headless(const ViewerOptions& options, int frames, const std::filesystem::path& capture);

/// Prints "animkit-viewer: error: <message>" on stderr and returns `code`.
int report_error(const std::string& message, int code);

}  // namespace animkit::viewer
