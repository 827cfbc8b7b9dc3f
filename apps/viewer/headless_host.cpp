#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "animkit/io/png.h"
#include "animkit/render/gl_context.h"
#include "animkit/render/offscreen_target.h"
#include "hosts.h"

namespace animkit::viewer {

int run_headless(const ViewerOptions& options, int frames, const std::filesystem::path& capture) {
  auto context = OffscreenContext::create();
  if (!context) return report_error(context.error().message, kExitNoDisplay);
  auto target = OffscreenTarget::create(options.width, options.height);
  if (!target) return report_error(target.error().message, 2);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(static_cast<float>(options.width), static_cast<float>(options.height));
  io.DeltaTime = 1.0f / 60.0f;  // the frames are not shown: pretend a 60 Hz screen
  ImGui::StyleColorsDark();
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int code = 0;
  {
    auto app = ViewerApp::create(options);
    if (!app) {
      code = report_error(app.error().message, 2);
    } else {
      for (int frame = 0; frame < frames; ++frame) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        app->update(options.width, options.height);
        ImGui::Render();
        target->bind();
        app->render(options.width, options.height);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      }
      if (auto written = write_png(capture, target->read()); !written) {
        code = report_error(written.error().message, 2);
      }
    }
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
  return code;
}

}  // namespace animkit::viewer
