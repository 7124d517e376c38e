// `masonry-joint inp`: the *SURFACE INTERACTION block of a parameter file
// (output/inp_deck.hpp), with props(15..16) only when asked for.
#pragma once

#include <iosfwd>
#include <string>

namespace mortar::harness {

struct InpArgs {
  std::string params, scheme, name = "MORTAR";  // scheme: empty = not written
  double stol = 0;
};

// Writes the block on `out`; throws InputError for a bad file or option.
int inp_command(const InpArgs& args, std::ostream& out);

}  // namespace mortar::harness
