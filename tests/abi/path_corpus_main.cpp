// path_corpus write FILE | compare FILE: runs the random-path corpus through
// the vuinteraction_ this program is linked with and writes its hashes, or
// compares them with a file (exit 1 on any difference).
#include <cstdio>
#include <cstring>

#include "path_corpus.hpp"

int main(int argc, char** argv) {
  if (argc != 3 || (std::strcmp(argv[1], "write") != 0 && std::strcmp(argv[1], "compare") != 0)) {
    std::fprintf(stderr, "usage: %s write|compare FILE\n", argv[0]);
    return 2;
  }
  const std::vector<mj_corpus::CaseHash> hashes = mj_corpus::run_corpus();
  if (std::strcmp(argv[1], "write") == 0) return mj_corpus::write_hashes(hashes, argv[2]) ? 0 : 1;
  const std::vector<std::string> differ = mj_corpus::compare_hashes(hashes, argv[2]);
  for (const std::string& d : differ) std::fprintf(stderr, "path corpus: %s differs\n", d.c_str());
  std::printf("path corpus: %zu cases, %zu differ\n", hashes.size(), differ.size());
  return differ.empty() ? 0 : 1;
}
