#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

#include "hosts.h"

namespace animkit::viewer {

namespace {
std::string last_glfw_error;

void remember_glfw_error(int /*code*/, const char* description) {
  last_glfw_error = description ? description : "unknown GLFW error";
}
}  // namespace

int run_window(const ViewerOptions& options, int frames) {
  glfwSetErrorCallback(remember_glfw_error);
  if (!glfwInit()) {
    return report_error("cannot open a window (" + last_glfw_error +
                            "); to render without a display use --capture FILE.png",
                        kExitNoDisplay);
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "animkit viewer", nullptr, nullptr);
  if (!window) {
    const std::string reason = last_glfw_error;
    glfwTerminate();
    return report_error("cannot open an OpenGL 3.3 window (" + reason + ")", kExitNoDisplay);
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int code = 0;
  {
    auto app = ViewerApp::create(options);
    if (!app) {
      code = report_error(app.error().message, 2);
    } else {
      for (int frame = 0; !glfwWindowShouldClose(window) && (frames <= 0 || frame < frames);
           ++frame) {
        glfwPollEvents();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        int width = 0, height = 0, fb_width = 0, fb_height = 0;
        glfwGetWindowSize(window, &width, &height);
        glfwGetFramebufferSize(window, &fb_width, &fb_height);
        app->update(width, height);
        ImGui::Render();
        if (fb_width > 0 && fb_height > 0) app->render(fb_width, fb_height);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(window);
      }
    }
  }  // the app's OpenGL objects go while the context exists
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return code;
}

}  // namespace animkit::viewer
