#pragma once
// Small file helpers shared by the tests that write and read real files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace animkit::testing_support {

/// This process's folder under the test temporary directory: the process id keeps concurrent
/// test runs (release and sanitizer) apart. It is removed, with everything in it, when the
/// process exits, so the suite leaves nothing behind (ctest starts one process a test); set
/// ANIMKIT_KEEP_TEST_FILES=1 to keep it for a look.
inline const std::filesystem::path& process_temp_dir() {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::path(::testing::TempDir()) / ("animkit_" + std::to_string(::getpid()));
    ~Folder() {
      if (std::getenv("ANIMKIT_KEEP_TEST_FILES") != nullptr) return;
      std::error_code ignored;  // nothing to report at exit: a folder left is only untidy
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return folder.path;
}

/// An empty folder `name` in process_temp_dir() (created, emptied first).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = process_temp_dir() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole content of a file ("" if it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace animkit::testing_support
