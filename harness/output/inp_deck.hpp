// The Abaqus input-deck block that makes the routine available to general
// contact: *SURFACE INTERACTION with USER=INTERACTION, PROPERTIES, DEPVAR and
// the props on data lines (eight per line).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace mortar::harness {

struct InpOptions {
  std::string name = "MORTAR";  // the interaction's NAME
  std::vector<double> props;    // props(1..nProps)
  int depvar = 0;               // DEPVAR
};

void write_surface_interaction(std::ostream& out, const InpOptions& options);

// Shortest decimal text that reads back as exactly x.
std::string exact_decimal(double x);

}  // namespace mortar::harness
