// The random-path corpus: blocks of points on random loading paths through
// vuinteraction_ (the routine's precision mj_real), 2D and 3D, with and
// without turning dRot, every scheme, several DEPVAR layouts. Each case ends
// in one 64-bit hash of every output of every call, so that two builds of the
// routine (with and without the fast paths, or two commits) agree bit for bit
// exactly when their hashes do.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mj_corpus {

struct CaseHash {
  std::string name;
  std::uint64_t hash;
};

// Runs the whole corpus (fixed seeds).
std::vector<CaseHash> run_corpus();

// One line per case: "<name> <hash in hex>".
bool write_hashes(const std::vector<CaseHash>& hashes, const std::string& path);
// The cases whose hash differs from the file's, or are missing on either side
// (empty: identical); a file that cannot be read is one entry naming it.
std::vector<std::string> compare_hashes(const std::vector<CaseHash>& hashes, const std::string& path);

}  // namespace mj_corpus
