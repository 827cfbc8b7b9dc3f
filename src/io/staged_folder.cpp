#include "animkit/io/staged_folder.h"

#include <fcntl.h>
#include <stdio.h>  // renameat2 (glibc >= 2.28)
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/io/atomic_write.h"
#include "cleanup_registry.h"

namespace animkit {

namespace {

namespace fs = std::filesystem;

// What earlier versions wrote, before folders listed their own entries.
constexpr std::array<std::string_view, 10> kEarlierOutputNames = {
    "metrics.json", "path.csv",  "drawing.svg", "drawing.png", "summary.csv",
    "cloth.obj",    "cloth.pc2", "final.png",   "ik",          "cloth"};

std::string shown(const fs::path& path) {
  return path.string();
}

// The names a results folder lists in its ".animkit-outputs".
std::set<std::string> listed_outputs(const fs::path& folder) {
  std::set<std::string> names;
  std::ifstream in(folder / kOutputListName);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') names.insert(line);
  }
  return names;
}

// The first entry of `folder` that animkit did not write, if any.
std::optional<std::string> foreign_entry(const fs::path& folder) {
  const std::set<std::string> listed = listed_outputs(folder);
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    pid_t pid = 0;
    if (name == kOutputListName || listed.contains(name) || is_animkit_temporary(name, pid) ||
        std::find(kEarlierOutputNames.begin(), kEarlierOutputNames.end(), name) !=
            kEarlierOutputNames.end()) {
      continue;
    }
    return name;
  }
  if (error) return "(unreadable: " + error.message() + ")";
  return std::nullopt;
}

Result<void> check_target(const fs::path& target) {
  std::error_code error;
  const fs::file_status status = fs::status(target, error);
  if (!fs::exists(status)) return {};
  if (!fs::is_directory(status)) {
    return fail("output folder " + shown(target) + " is a file, not a folder");
  }
  if (auto entry = foreign_entry(target)) {
    return fail("output folder " + shown(target) + " holds " + quote_input(*entry) +
                ", which animkit did not write; a run replaces its folder whole, so give it a "
                "new or empty folder");
  }
  return {};
}

// Syncs a folder's entries (the names of the files in it) to disk.
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

Result<void> write_output_list(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    names.push_back(it->path().filename().string());
  }
  if (error) return fail("cannot list " + shown(folder) + ": " + error.message());
  std::sort(names.begin(), names.end());
  std::string text =
      "# Written by animkit. The next run into this folder replaces it whole;\n"
      "# it holds only these entries and this list.\n";
  for (const std::string& name : names) text += name + "\n";
  return write_file_atomic(folder / kOutputListName, text);
}

}  // namespace

StagedFolder::StagedFolder(fs::path target, fs::path staging)
    : target_(std::move(target)), staging_(std::move(staging)), cleanup_(staging_), open_(true) {}

StagedFolder::StagedFolder(StagedFolder&& other) noexcept
    : target_(std::move(other.target_)),
      staging_(std::move(other.staging_)),
      cleanup_(std::move(other.cleanup_)),
      open_(std::exchange(other.open_, false)) {}

StagedFolder::~StagedFolder() {
  abandon();
}

void StagedFolder::abandon() {
  if (!open_) return;
  open_ = false;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  cleanup_.release();
}

Result<StagedFolder> StagedFolder::begin(const fs::path& requested) {
  if (requested.empty()) return fail("the output folder name is empty");
  std::error_code error;
  fs::path target = fs::weakly_canonical(fs::absolute(requested, error), error);
  if (error) return fail("output folder " + shown(requested) + ": " + error.message());
  if (!target.has_filename()) target = target.parent_path();  // "out/" is "out"
  if (target == target.root_path()) {
    return fail("output folder " + shown(requested) +
                " is the root folder; give the run a "
                "folder of its own");
  }
  const fs::path cwd = fs::weakly_canonical(fs::current_path(error), error);
  if (!error) {
    const auto [diverge, rest] =
        std::mismatch(target.begin(), target.end(), cwd.begin(), cwd.end());
    if (diverge == target.end()) {
      return fail("output folder " + shown(requested) +
                  " is the current folder or contains it; a run replaces its folder whole, so "
                  "give it a folder of its own");
    }
  }
  if (auto ok = check_target(target); !ok) return fail(ok.error().message);
  const fs::path parent = target.parent_path();
  fs::create_directories(parent, error);
  if (error)
    return fail("cannot create output folder " + shown(requested) + ": " + error.message());
  remove_stale_temporaries(parent);
  const fs::path staging = unique_sibling(target, "staging");
  if (::mkdir(staging.c_str(), 0777) != 0) {
    return fail("cannot create output folder " + shown(requested) + ": " + std::strerror(errno));
  }
  return StagedFolder(target, staging);
}

Result<fs::path> StagedFolder::redirect(const fs::path& path) const {
  std::error_code error;
  const fs::path full = fs::weakly_canonical(fs::absolute(path, error), error);
  if (error) return path;
  const auto [diverge, rest] =
      std::mismatch(target_.begin(), target_.end(), full.begin(), full.end());
  if (diverge != target_.end()) return path;  // not inside the target
  if (full.parent_path() == target_) return staging_ / full.filename();
  return fail(shown(path) + " is inside a subfolder of the output folder " + shown(target_) +
              ", which the run replaces whole; write it directly in that folder or elsewhere");
}

Result<void> StagedFolder::commit() {
  if (!open_) return fail("output folder " + shown(target_) + " is already committed");
  if (auto ok = write_output_list(staging_); !ok) return ok;
  sync_folder(staging_);
  int error = 0;
  bool exchanged = false;
  {
    // Not cut in half by the signal clean-up: the swap is done or not begun.
    auto lock = detail::lock_cleanup_registry();
    if (auto ok = check_target(target_); !ok) return ok;  // changed during the run
    for (int attempt = 0; attempt < 8; ++attempt) {
      if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_NOREPLACE) ==
          0) {
        error = 0;
        break;
      }
      error = errno;
      if (error != EEXIST && error != ENOTEMPTY) break;
      // The target exists (or another run just made it): swap the two in one step.
      if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) ==
          0) {
        error = 0;
        exchanged = true;
        break;
      }
      error = errno;
      if (error == ENOENT) continue;  // the target vanished meanwhile: plain rename again
      if (error != EINVAL && error != ENOSYS && error != EXDEV) break;
      // No atomic exchange on this file system: move the old folder aside, then rename. A run
      // that dies between the two leaves the old folder at an ".old" name, which the next
      // run puts back (remove_stale_temporaries).
      const fs::path old = unique_sibling(target_, "old");
      if (::rename(target_.c_str(), old.c_str()) != 0) {
        error = errno;
        break;
      }
      if (::rename(staging_.c_str(), target_.c_str()) != 0) {
        error = errno;
        ::rename(old.c_str(), target_.c_str());
        break;
      }
      ::rename(old.c_str(), staging_.c_str());  // so the clean-up below finds it
      error = 0;
      exchanged = true;
      break;
    }
  }
  if (error != 0) {
    return fail("cannot replace output folder " + shown(target_) + ": " + std::strerror(error));
  }
  sync_folder(target_.parent_path());
  open_ = false;
  if (exchanged) {
    std::error_code ignored;  // the previous results, now at the staging name
    fs::remove_all(staging_, ignored);
  }
  cleanup_.release();
  return {};
}

}  // namespace animkit
