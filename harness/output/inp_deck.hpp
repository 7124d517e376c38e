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

// "" when `name` is a valid unquoted Abaqus name (the input syntax rules:
// 1-80 characters, the first a letter, then letters, digits, '_' or '-' as
// in Abaqus/CAE's own "Part-1"); otherwise what is wrong with it.
std::string abaqus_name_problem(const std::string& name);
inline constexpr const char* kAbaqusNameRule =
    "an Abaqus name has 1 to 80 characters, starts with a letter and holds only letters, digits, '_' and '-'";

void write_surface_interaction(std::ostream& out, const InpOptions& options);

// Shortest decimal text that reads back as exactly x.
std::string exact_decimal(double x);

}  // namespace mortar::harness
