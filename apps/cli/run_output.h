#pragma once
// Where a CLI run writes: its --out folder, filled through a staging folder and swapped in
// whole at the end (StagedFolder), or nowhere when no --out was given.
#include <filesystem>
#include <optional>
#include <string>

#include "animkit/core/result.h"
#include "animkit/io/staged_folder.h"

namespace animkit::cli {

class RunOutput {
 public:
  /// Starts the run's output. `out` empty: no folder. `video` (may be empty), if it lies
  /// directly in the --out folder, is redirected into the staging folder so it arrives with
  /// the rest. Errors: those of StagedFolder::begin and StagedFolder::redirect.
  static Result<RunOutput> begin(const std::string& out, std::string& video);

  bool has_folder() const { return folder_.has_value(); }
  /// Where the files go until commit(); empty without a folder.
  std::filesystem::path dir() const { return folder_ ? folder_->dir() : std::filesystem::path(); }
  /// Swaps the finished folder in (nothing without a folder).
  Result<void> commit();

 private:
  std::optional<StagedFolder> folder_;
};

}  // namespace animkit::cli
