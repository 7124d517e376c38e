// `masonry-joint inp`: the *SURFACE INTERACTION block of a parameter file
// (output/inp_deck.hpp), with props(15..16) only when asked for; with
// --scene or --two-blocks a complete job instead (commands/inp_job.cpp).
#pragma once

#include <iosfwd>
#include <string>

namespace mortar::harness {

struct InpArgs {
  std::string params, scheme, name = "MORTAR";  // scheme: empty = not written
  double stol = 0;
  std::string scene;       // --scene FILE: the scene's wall as an Abaqus/Explicit job
  std::string two_blocks;  // --two-blocks explicit|standard: the two-block job
};

// Writes the block on `out`; throws InputError for a bad file or option.
int inp_command(const InpArgs& args, std::ostream& out);

// Whether the arguments ask for a complete job, and writing it.
bool inp_writes_job(const InpArgs& args);
int inp_job_command(const InpArgs& args, std::ostream& out);

}  // namespace mortar::harness
