// `masonry-joint scene FILE.toml`: a wall of rigid blocks through
// vuinteraction_ (scenes/wall.hpp, solvers/block_solver.hpp); writes the
// history CSV, the wall snapshots, the charts and the summary into --out.
#pragma once

#include <iosfwd>
#include <string>

namespace mortar::harness {

struct SceneArgs {
  std::string file, out = "out/scene";
  int threads = 1, block = 136;
  bool plots = true, quiet = false;
};

// Returns the exit status (0, or 1 when the run failed); InputError for bad
// input.
int scene_command(const SceneArgs& args, std::ostream& out, std::ostream& err);

}  // namespace mortar::harness
