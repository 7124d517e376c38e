// Runs the fuzz target over files and directories of inputs without libFuzzer:
// the seed corpus as a regression test in every build (plain, ASan+UBSan),
// with any compiler. Usage: fuzz_replay [--flush-denormals] <file-or-directory>...
// --flush-denormals: with the CPU's flush-to-zero and denormals-are-zero
// modes set (x86-64), as Intel-compiled solvers may run the routine.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fp_modes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  int first = 1;
  if (argc > 1 && std::string(argv[1]) == "--flush-denormals") {
#if MJ_FP_MODES
    static const mj_test::FlushDenormals modes;  // for the whole replay
    if (!mj_test::denormals_flushed()) {
      std::fprintf(stderr, "fuzz_replay: flush-to-zero and denormals-are-zero did not take effect\n");
      return 2;
    }
    first = 2;
#else
    std::fprintf(stderr, "fuzz_replay: --flush-denormals needs an x86-64 CPU (its MXCSR register)\n");
    return 2;
#endif
  }
  for (int i = first; i < argc; ++i) {
    const fs::path p = argv[i];
    if (fs::is_directory(p)) {
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (fs::is_regular_file(p)) {
      files.push_back(p);
    } else {
      std::fprintf(stderr, "fuzz_replay: no such file or directory: %s\n", argv[i]);
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "fuzz_replay: no inputs\n");
    return 2;
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("fuzz_replay: %zu inputs replayed%s, every property held\n", files.size(),
              first == 2 ? " with flush-to-zero and denormals-are-zero set" : "");
  return 0;
}
