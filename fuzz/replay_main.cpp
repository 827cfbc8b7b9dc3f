// Replays fuzz inputs without libFuzzer: every file in the folders named on the command line
// goes once through the target's LLVMFuzzerTestOneInput. Linked with each fuzz target into a
// ctest test, so the corpora and the kept crash inputs (regressions) are checked by every
// build, with g++ and under the sanitizers, even where clang is not installed.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  int replayed = 0;
  for (int a = 1; a < argc; ++a) {
    const fs::path folder = argv[a];
    // A target without crashes yet has no regressions folder.
    if (!fs::is_directory(folder)) {
      std::printf("replay: no folder %s, skipped\n", folder.c_str());
      continue;
    }
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());  // the same order on every machine
    for (const fs::path& file : files) {
      std::ifstream in(file, std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
      if (!in.eof() && !in) {
        std::fprintf(stderr, "replay: cannot read %s\n", file.c_str());
        return 1;
      }
      std::printf("replay: %s\n", file.c_str());
      std::fflush(stdout);  // names the input if the target crashes on it
      LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  if (replayed == 0) {
    std::fprintf(stderr, "replay: no inputs found (is the corpus folder missing?)\n");
    return 1;
  }
  std::printf("replay: %d inputs, no crash\n", replayed);
  return 0;
}
