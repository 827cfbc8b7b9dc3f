#include "run_output.h"

namespace animkit::cli {

Result<RunOutput> RunOutput::begin(const std::string& out, std::string& video) {
  RunOutput output;
  if (out.empty()) return output;
  auto folder = StagedFolder::begin(out);
  if (!folder) return fail(folder.error().message);
  if (!video.empty()) {
    auto redirected = folder->redirect(video);
    if (!redirected) return fail(redirected.error().message);
    video = redirected->string();
  }
  output.folder_.emplace(std::move(*folder));
  return output;
}

Result<void> RunOutput::commit() {
  if (!folder_) return {};
  return folder_->commit();
}

}  // namespace animkit::cli
