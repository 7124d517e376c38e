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

std::string unit_list(int index) {
  std::string s;
  for (const char* u : kUnitSpellings[index])
    if (*u) s += std::string(s.empty() ? "" : ", ") + "\"" + u + "\"";
  return s;
}

void check_unit(const std::string& file, const toml::value& unit, int index) {
  const std::string name = kParameterInfo[index].name;
  const std::string u = read_string(file, unit, "the unit of '" + name + "'");
  for (const char* a : kUnitSpellings[index])
    if (*a && u == a) return;
  throw InputError(position_of(file, unit) + ": unit \"" + u + "\" of '" + name + "' is not accepted: '" +
                   name + "' (" + kParameterInfo[index].meaning + ") is given in " + unit_list(index) +
                   "; the reader never converts units");
}

// A parameter entry: a number, or {value = number, unit = "..."}.
double read_entry(const std::string& file, const toml::value& v, int index) {
  const std::string name = kParameterInfo[index].name;
  if (!v.is_table()) return read_number(file, v, "parameter '" + name + "'");
  reject_unknown_keys(file, v, {"value", "unit"}, "the entry of '" + name + "'");
  const auto& t = v.as_table();
  if (!t.count("value"))
    throw InputError(position_of(file, v) + ": the entry of '" + name + "' has no 'value'");
  if (t.count("unit")) check_unit(file, t.at("unit"), index);
  return read_number(file, t.at("value"), "parameter '" + name + "'");
}

std::string all_names() {
  std::string s;
  for (const ParameterInfo& p : kParameterInfo) s += std::string(s.empty() ? "" : ", ") + p.name;
  return s;
}
}  // namespace

const std::array<const char*, 3>& accepted_units(int index) { return kUnitSpellings.at(index); }

ParameterSet read_parameter_file(const std::string& path) {
  const toml::value root = parse_toml_file(path);
  ParameterSet set;
  set.file = path;
  for (const auto& [key, value] : root.as_table()) {
    if (parameter_index(key) < 0)
      throw InputError(position_of(path, value) + ": unknown key '" + key +
                       "'; a parameter file holds exactly the 14 parameters " + all_names() +
                       " (names are case-sensitive)");
  }
  for (int i = 0; i < kParameterCount; ++i) {
    const char* name = kParameterInfo[i].name;
    if (!root.contains(name))
      throw InputError(path + ": missing parameter '" + std::string(name) + "' [" + kParameterInfo[i].unit +
                       "] (" + kParameterInfo[i].meaning + "); every one of the 14 parameters is required");
    const toml::value& v = root.at(name);
    parameter_at(set.values, i) = read_entry(path, v, i);
    set.line[i] = line_of(v);
  }
  const ValidationError e = validate(set.values);
  if (!e.ok()) {
    const int line = e.index >= 0 && e.index < kParameterCount ? set.line[e.index] : 0;
    std::ostringstream msg;
    msg.precision(9);
    msg << file_position(path, line) << ": parameter '" << e.name << "' = " << e.value
        << " violates the rule: " << e.rule;
    throw InputError(msg.str());
  }
  return set;
}

void write_parameter_file(const std::string& path, const Parameters& p, const std::vector<std::string>& header) {
  std::ofstream out(path);
  if (!out) throw InputError(cannot_write(path));
  for (const std::string& line : header) out << "# " << line << "\n";
  for (int i = 0; i < kParameterCount; ++i) {
    const double x = parameter_at(p, i);
    if (!std::isfinite(x)) {  // never written as a value: the file would not read back
      out << "# " << kParameterInfo[i].name << " = not finite (" << x << "): no value\n";
      continue;
    }
    char number[40];
    for (int digits = 6; digits <= 17; ++digits) {
      std::snprintf(number, sizeof number, "%.*g", digits, x);
      if (std::strtod(number, nullptr) == x) break;
    }
    char line[160];
    std::snprintf(line, sizeof line, "%-4s = { value = %-12s unit = \"%s\" }", kParameterInfo[i].name,
                  (std::string(number) + ",").c_str(), kUnitSpellings[i][0]);
    out << line << "  # " << kParameterInfo[i].meaning << "\n";
  }
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace mortar::harness
