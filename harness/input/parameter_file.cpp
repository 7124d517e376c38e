#include "input/parameter_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "input/toml_input.hpp"
#include "output/output_paths.hpp"

namespace mortar::harness {

namespace {
// Spellings of each unit in kParameterInfo order; "" pads the list.
const std::array<std::array<const char*, 3>, kParameterCount> kUnitSpellings = {{
    {"N/mm^3", "MPa/mm", "N/mm3"},  // kn
    {"N/mm^3", "MPa/mm", "N/mm3"},  // ks
    {"MPa", "N/mm^2", "N/mm2"},     // ft0
    {"MPa", "N/mm^2", "N/mm2"},     // c0
    {"N/mm", "", ""},               // GIC
    {"N/mm", "", ""},               // GIIC
    {"deg", "degree", "degrees"},   // phi0
    {"deg", "degree", "degrees"},   // phir
    {"mm/N", "", ""},               // m
    {"deg", "degree", "degrees"},   // psi0
    {"deg", "degree", "degrees"},   // psir
    {"mm/N", "", ""},               // n
    {"-", "1", ""},                 // bn
    {"-", "1", ""},                 // bs
}};

// The same for the compression cap's parameters, in kCapParameterInfo order.
const std::array<std::array<const char*, 3>, kCapCount> kCapUnitSpellings = {{
    {"MPa", "N/mm^2", "N/mm2"},  // fc
    {"-", "1", ""},              // Cs
    {"N/mm", "", ""},            // Gfc
    {"mm", "", ""},              // kappa_p
}};

// What an entry's messages and unit check need of its parameter.
struct EntryInfo {
  std::string name;
  const char* meaning;
  const std::array<const char*, 3>& units;
};
EntryInfo parameter_entry(int index) {
  return {kParameterInfo[index].name, kParameterInfo[index].meaning, kUnitSpellings[index]};
}
EntryInfo cap_entry(int index) {
  return {kCapParameterInfo[index].name, kCapParameterInfo[index].meaning, kCapUnitSpellings[index]};
}

std::string unit_list(const EntryInfo& e) {
  std::string s;
  for (const char* u : e.units)
    if (*u) s += std::string(s.empty() ? "" : ", ") + "\"" + u + "\"";
  return s;
}

void check_unit(const std::string& file, const toml::value& unit, const EntryInfo& e) {
  const std::string u = read_string(file, unit, "the unit of '" + e.name + "'");
  for (const char* a : e.units)
    if (*a && u == a) return;
  throw InputError(position_of(file, unit) + ": unit \"" + u + "\" of '" + e.name + "' is not accepted: '" +
                   e.name + "' (" + e.meaning + ") is given in " + unit_list(e) + "; the reader never converts units");
}

// A parameter entry: a number, or {value = number, unit = "..."}.
double read_entry(const std::string& file, const toml::value& v, const EntryInfo& e) {
  if (!v.is_table()) return read_number(file, v, "parameter '" + e.name + "'");
  reject_unknown_keys(file, v, {"value", "unit"}, "the entry of '" + e.name + "'");
  const auto& t = v.as_table();
  if (!t.count("value"))
    throw InputError(position_of(file, v) + ": the entry of '" + e.name + "' has no 'value'");
  if (t.count("unit")) check_unit(file, t.at("unit"), e);
  return read_number(file, t.at("value"), "parameter '" + e.name + "'");
}

[[noreturn]] void throw_rule(const std::string& path, int line, const ValidationError& e) {
  std::ostringstream msg;
  msg.precision(9);
  msg << file_position(path, line) << ": parameter '" << e.name << "' = " << e.value
      << " violates the rule: " << e.rule;
  throw InputError(msg.str());
}

// The shortest decimal that reads back as exactly x.
std::string shortest(double x) {
  char number[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(number, sizeof number, "%.*g", digits, x);
    if (std::strtod(number, nullptr) == x) break;
  }
  return number;
}

void write_entry(std::ostream& out, const EntryInfo& e, double x) {
  if (!std::isfinite(x)) {  // never written as a value: the file would not read back
    out << "# " << e.name << " = not finite (" << x << "): no value\n";
    return;
  }
  char line[160];
  std::snprintf(line, sizeof line, "%-4s = { value = %-12s unit = \"%s\" }", e.name.c_str(),
                (shortest(x) + ",").c_str(), e.units[0]);
  out << line << "  # " << e.meaning << "\n";
}

std::string all_names() {
  std::string s;
  for (const ParameterInfo& p : kParameterInfo) s += std::string(s.empty() ? "" : ", ") + p.name;
  return s;
}
}  // namespace

const std::array<const char*, 3>& accepted_units(int index) { return kUnitSpellings.at(index); }
const std::array<const char*, 3>& accepted_cap_units(int index) { return kCapUnitSpellings.at(index); }

ParameterSet read_parameter_file(const std::string& path) {
  const toml::value root = parse_toml_file(path);
  ParameterSet set;
  set.file = path;
  for (const auto& [key, value] : root.as_table()) {
    if (parameter_index(key) < 0 && cap_parameter_index(key) < 0)
      throw InputError(position_of(path, value) + ": unknown key '" + key +
                       "'; a parameter file holds exactly the 14 parameters " + all_names() +
                       ", and optionally the compression cap's fc, Cs, Gfc, kappa_p (names are case-sensitive)");
  }
  for (int i = 0; i < kParameterCount; ++i) {
    const char* name = kParameterInfo[i].name;
    if (!root.contains(name))
      throw InputError(path + ": missing parameter '" + std::string(name) + "' [" + kParameterInfo[i].unit +
                       "] (" + kParameterInfo[i].meaning + "); every one of the 14 parameters is required");
    const toml::value& v = root.at(name);
    parameter_at(set.values, i) = read_entry(path, v, parameter_entry(i));
    set.line[i] = line_of(v);
  }
  const ValidationError e = validate(set.values);
  if (!e.ok()) throw_rule(path, e.index >= 0 && e.index < kParameterCount ? set.line[e.index] : 0, e);
  for (int i = 0; i < kCapCount; ++i) {
    const char* name = kCapParameterInfo[i].name;
    if (!root.contains(name)) continue;
    const toml::value& v = root.at(name);
    cap_parameter_at(set.cap, i) = read_entry(path, v, cap_entry(i));
    set.cap_line[i] = line_of(v);
  }
  // The cap's rules, props(21..24) (mortar::validate): e.index is its props
  // position.
  const ValidationError c = validate(set.cap, set.values);
  if (!c.ok()) {
    const int i = c.index - kCapFirstProp;
    throw_rule(path, i >= 0 && i < kCapCount ? set.cap_line[i] : 0, c);
  }
  return set;
}

void write_parameter_file(const std::string& path, const Parameters& p, const std::vector<std::string>& header,
                          const CompressionCap& cap) {
  std::ofstream out(path);
  if (!out) throw InputError(cannot_write(path));
  for (const std::string& line : header) out << "# " << line << "\n";
  for (int i = 0; i < kParameterCount; ++i) write_entry(out, parameter_entry(i), parameter_at(p, i));
  if (cap.on()) {
    out << "# the compression cap (props 21-24)\n";
    for (int i = 0; i < kCapCount; ++i) write_entry(out, cap_entry(i), cap_parameter_at(cap, i));
  }
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace mortar::harness
