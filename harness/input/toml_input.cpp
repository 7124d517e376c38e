#include "input/toml_input.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace mortar::harness {

std::string file_position(const std::string& file, int line) {
  return line > 0 ? file + ":" + std::to_string(line) : file;
}

std::string input_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

toml::value parse_toml_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a folder; a TOML file is needed");
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file for reading (" + std::strerror(errno) + ")");
  try {
    return toml::parse(in, path);
  } catch (const toml::syntax_error& e) {
    throw InputError(path + ": not valid TOML:\n" + e.what());
  } catch (const std::exception& e) {
    throw InputError(path + ": cannot be read as TOML: " + e.what());
  }
}

int line_of(const toml::value& v) { return static_cast<int>(v.location().line()); }

std::string position_of(const std::string& file, const toml::value& v) {
  return file_position(file_of(v, file), line_of(v));
}

std::string file_of(const toml::value& v, const std::string& fallback) {
  const std::string f = v.location().file_name();
  return f.empty() || f == "unknown file" ? fallback : f;
}

namespace {
const char* type_name(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean: return "a boolean";
    case toml::value_t::integer: return "an integer";
    case toml::value_t::floating: return "a number";
    case toml::value_t::string: return "a string";
    case toml::value_t::array: return "an array";
    case toml::value_t::table: return "a table";
    default: return "a date or time";
  }
}
}  // namespace

double read_number(const std::string& file, const toml::value& v, const std::string& what) {
  double x = 0;
  if (v.is_integer()) {
    x = static_cast<double>(v.as_integer());
  } else if (v.is_floating()) {
    x = v.as_floating();
  } else {
    throw InputError(position_of(file, v) + ": " + what + " must be a number, found " + type_name(v));
  }
  if (!std::isfinite(x)) throw InputError(position_of(file, v) + ": " + what + " must be a finite number");
  return x;
}

long read_integer(const std::string& file, const toml::value& v, const std::string& what, long min, long max) {
  if (!v.is_integer())
    throw InputError(position_of(file, v) + ": " + what + " must be a whole number, found " + type_name(v));
  const long x = static_cast<long>(v.as_integer());
  if (x < min || x > max)
    throw InputError(position_of(file, v) + ": " + what + " = " + std::to_string(x) + " must lie in [" +
                     std::to_string(min) + ", " + std::to_string(max) + "]");
  return x;
}

std::string read_string(const std::string& file, const toml::value& v, const std::string& what) {
  if (!v.is_string())
    throw InputError(position_of(file, v) + ": " + what + " must be a string, found " + type_name(v));
  return v.as_string().str;
}

void reject_unknown_keys(const std::string& file, const toml::value& table,
                         std::initializer_list<const char*> allowed, const std::string& context) {
  // Report the unknown key that comes first in the file, so the message does
  // not depend on the hash order of the table.
  const toml::value* first = nullptr;
  std::string first_key;
  for (const auto& [key, value] : table.as_table()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (known) continue;
    if (!first || line_of(value) < line_of(*first)) {
      first = &value;
      first_key = key;
    }
  }
  if (!first) return;
  std::ostringstream list;
  const char* sep = "";
  for (const char* a : allowed) {
    list << sep << a;
    sep = ", ";
  }
  throw InputError(position_of(file, *first) + ": unknown key '" + first_key + "' in " + context +
                   "; the keys allowed there are: " + list.str());
}

}  // namespace mortar::harness
