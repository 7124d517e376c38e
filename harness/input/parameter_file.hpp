// Parameter files: the 14 parameters of the law by their names (kn, ks, ft0,
// c0, GIC, GIIC, phi0, phir, m, psi0, psir, n, bn, bs), in TOML, each either a
// bare number in the documented unit or {value = ..., unit = "..."} so that
// the file states its units and the reader checks them. Every parameter is
// required; unknown keys, wrong units and values that break a rule of the
// law are InputError with file, line, value and rule.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

struct ParameterSet {
  Parameters values;
  std::string file;
  std::array<int, kParameterCount> line{};  // line of each parameter in `file`
};

ParameterSet read_parameter_file(const std::string& path);

// Writes a parameter file that read_parameter_file reads back exactly: every
// parameter as {value, unit} with the shortest decimal that round-trips, its
// meaning as a comment, and `header` as '#' lines first. A non-finite value is
// never written: its line is a comment saying so (the file then does not read).
void write_parameter_file(const std::string& path, const Parameters& p, const std::vector<std::string>& header);

// The unit spellings accepted for parameter `index` (the canonical one first).
// They are spellings of one unit, never conversions.
const std::array<const char*, 3>& accepted_units(int index);

}  // namespace mortar::harness
