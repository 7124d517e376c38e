// Parameter files: the 14 parameters of the law by their names (kn, ks, ft0,
// c0, GIC, GIIC, phi0, phir, m, psi0, psir, n, bn, bs), in TOML, each either a
// bare number in the documented unit or {value = ..., unit = "..."} so that
// the file states its units and the reader checks them. Every parameter is
// required. The compression cap's fc, Cs, Gfc, kappa_p (props 21-24) are
// optional: a missing one is 0, and fc = 0 (or no cap key) is no cap.
// Unknown keys, wrong units and values that break a rule of the law are
// InputError with file, line, value and rule.
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
  CompressionCap cap;                       // off unless the file gives fc > 0
  std::array<int, kCapCount> cap_line{};    // line of each cap key in `file`, 0 if absent
};

ParameterSet read_parameter_file(const std::string& path);

// Writes a parameter file that read_parameter_file reads back exactly: every
// parameter as {value, unit} with the shortest decimal that round-trips, its
// meaning as a comment, and `header` as '#' lines first. A non-finite value is
// never written: its line is a comment saying so (the file then does not read).
// The cap's keys are written only when cap.on().
void write_parameter_file(const std::string& path, const Parameters& p, const std::vector<std::string>& header,
                          const CompressionCap& cap = CompressionCap{});

// The unit spellings accepted for parameter `index` (the canonical one first),
// and for cap parameter `index` (kCapParameterInfo's order). They are
// spellings of one unit, never conversions.
const std::array<const char*, 3>& accepted_units(int index);
const std::array<const char*, 3>& accepted_cap_units(int index);

}  // namespace mortar::harness
