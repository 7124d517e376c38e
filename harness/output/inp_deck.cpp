#include "output/inp_deck.hpp"

#include <cstdio>
#include <cstdlib>
#include <ostream>

#include "mortar/parameters.hpp"
#include "mortar/state_layout.hpp"

namespace mortar::harness {

std::string exact_decimal(double x) {
  char buf[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  std::string s = buf;
  // Fortran list-directed input reads "3" and "3." alike; the dot says REAL.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".";
  return s;
}

std::string abaqus_name_problem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > 80) return "has " + std::to_string(name.size()) + " characters";
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  if (!letter(name[0])) return "does not start with a letter";
  for (const char c : name) {
    if (letter(c) || (c >= '0' && c <= '9') || c == '_' || c == '-') continue;
    if (c == ' ') return "holds a space";
    if (c < 32 || c > 126) return "holds a character outside printable ASCII";
    return std::string("holds '") + c + "'";
  }
  return "";
}

namespace {
std::string prop_name(size_t i) {
  if (i < static_cast<size_t>(kParameterCount)) return kParameterInfo[i].name;
  static const char* controls[] = {"scheme", "STOL", "FTOL", "max substeps", "min substep", "shear sign"};
  if (i - kParameterCount < 6) return controls[i - kParameterCount];
  return i - kCapFirstProp < static_cast<size_t>(kCapCount) ? kCapParameterInfo[i - kCapFirstProp].name : "unused";
}
}  // namespace

std::vector<double> deck_props(const Parameters& p, bool controls, bool scheme_given, Scheme scheme, double stol,
                               const CompressionCap& cap) {
  Controls c;
  c.scheme = scheme;
  c.stol = stol;
  const auto props = to_props(p, c);
  std::vector<double> out(props.begin(), props.begin() + kParameterCount + (controls ? 2 : 0));
  if (controls && !scheme_given) out[kParameterCount] = 0.0;
  if (cap.on()) {
    out.resize(kCapFirstProp + kCapCount, 0.0);
    for (int i = 0; i < kCapCount; ++i) out[static_cast<size_t>(kCapFirstProp + i)] = cap_parameter_at(cap, i);
  }
  return out;
}

int deck_depvar(const std::vector<double>& props, bool standard) {
  const bool cap = props.size() > static_cast<size_t>(kCapFirstProp) && props[kCapFirstProp] > 0;
  if (standard) return cap ? kCappedStateCountDouble : kStateCount;
  return cap ? kCappedStateCountSingle : kFlaggedStateCount;
}

void write_surface_interaction(std::ostream& out, const InpOptions& o) {
  if (o.standard) {
    // The first data line of a USER interaction in Abaqus/Standard is the
    // out-of-plane thickness or node area: blank for element-based 3D surfaces.
    out << "** Mortar-joint law (coupled damage-plasticity), Abaqus/Standard contact pairs (UINTER).\n"
        << "** Use on *CONTACT PAIR, INTERACTION=" << o.name << ". Run without user=: usub_lib_dir in\n"
        << "** abaqus_v6.env names the folder of libstandardU.so (Windows: standardU.dll); docs/abaqus.md.\n"
        << "*SURFACE INTERACTION, NAME=" << o.name << ", USER, PROPERTIES=" << o.props.size()
        << ", DEPVAR=" << o.depvar << ", UNSYMM\n\n";
  } else {
    out << "** Mortar-joint law (coupled damage-plasticity), Abaqus/Explicit general contact.\n"
        << "** Assign with *CONTACT PROPERTY ASSIGNMENT. Run without user=: usub_lib_dir in abaqus_v6.env\n"
        << "** names the folder of libexplicitU.so / libexplicitU-D.so (Windows: explicitU.dll,\n"
        << "** explicitU-D.dll); docs/abaqus.md.\n"
        << "*SURFACE INTERACTION, NAME=" << o.name << ", USER=INTERACTION, PROPERTIES=" << o.props.size()
        << ", DEPVAR=" << o.depvar << "\n";
  }
  for (size_t first = 0; first < o.props.size(); first += 8) {
    const size_t last = std::min(first + 8, o.props.size());
    out << "** props(" << first + 1 << ".." << last << "):";
    for (size_t i = first; i < last; ++i) out << ' ' << prop_name(i);
    out << "\n";
    for (size_t i = first; i < last; ++i) out << (i == first ? "" : ", ") << exact_decimal(o.props[i]);
    out << "\n";
  }
}

}  // namespace mortar::harness
