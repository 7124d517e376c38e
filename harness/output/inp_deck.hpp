// The Abaqus input-deck block that makes the routine available: for
// Abaqus/Explicit general contact *SURFACE INTERACTION with USER=INTERACTION
// (VUINTERACTION), for Abaqus/Standard contact pairs with USER and UNSYMM
// (UINTER, whose first data line is the blank area/thickness line); then
// PROPERTIES, DEPVAR and the props on data lines (eight per line). Every deck
// the harness writes (inp, inp --scene, inp --two-blocks) goes through here.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "mortar/parameters.hpp"

namespace mortar::harness {

struct InpOptions {
  std::string name = "MORTAR";  // the interaction's NAME
  std::vector<double> props;    // props(1..nProps)
  int depvar = 0;               // DEPVAR
  bool standard = false;        // UINTER (Abaqus/Standard) instead of VUINTERACTION
};

// "" when `name` is a valid unquoted Abaqus name (the input syntax rules:
// 1-80 characters, the first a letter, then letters, digits, '_' or '-' as
// in Abaqus/CAE's own "Part-1"); otherwise what is wrong with it.
std::string abaqus_name_problem(const std::string& name);
inline constexpr const char* kAbaqusNameRule =
    "an Abaqus name has 1 to 80 characters, starts with a letter and holds only letters, digits, '_' and '-'";

void write_surface_interaction(std::ostream& out, const InpOptions& options);

// props(1..14), and props(15..16) (scheme, STOL; 0 = the routine's default)
// when `controls`: absent props, and zero ones, mean the routine's defaults.
// With cap.on(), props(21..24) too (props(15..20) 0 where not given).
std::vector<double> deck_props(const Parameters& p, bool controls, bool scheme_given, Scheme scheme, double stol,
                               const CompressionCap& cap = CompressionCap{});

// The DEPVAR of a deck with `props`: Abaqus/Explicit loads the
// single-precision routine unless the job says double=both; it keeps its
// state as float pairs with DEPVAR >= 34 and either routine the integration
// flags with DEPVAR >= 35 (docs/model.md 3, 9): 35; with a cap (props(21) =
// fc > 0) kappa_c's float pair in SDV 36-37: 37. UINTER (`standard`, double
// precision): the law's 23, with a cap 36.
int deck_depvar(const std::vector<double>& props, bool standard);

// Shortest decimal text that reads back as exactly x.
std::string exact_decimal(double x);

}  // namespace mortar::harness
