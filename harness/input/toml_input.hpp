// Reading TOML input files with messages that point at the file and line:
// thin helpers over toml11 that turn its exceptions and type mismatches into
// InputError, and reject keys that the format does not define (a misspelt
// key must never be silently ignored).
#pragma once

#include <initializer_list>
#include <string>

#include <toml.hpp>

#include "input/input_error.hpp"

namespace mortar::harness {

// Parses a whole file; InputError when it cannot be read or is not TOML.
toml::value parse_toml_file(const std::string& path);

// Line of a value in its file (0 when toml11 does not know it).
int line_of(const toml::value& v);

// "file:line" of a value.
// The file a value was read from (a scene's `extends` merges two), or fallback.
std::string file_of(const toml::value& v, const std::string& fallback);
std::string position_of(const std::string& file, const toml::value& v);

// A finite number (TOML integer or float). `what` names the value in messages.
double read_number(const std::string& file, const toml::value& v, const std::string& what);

// A whole number in [min, max].
long read_integer(const std::string& file, const toml::value& v, const std::string& what, long min, long max);

std::string read_string(const std::string& file, const toml::value& v, const std::string& what);

// InputError at the first key (in file order) of `table` that is not in
// `allowed`, listing the allowed keys. `context` says where the table is
// ("the parameter file", "step 3", ...).
void reject_unknown_keys(const std::string& file, const toml::value& table,
                         std::initializer_list<const char*> allowed, const std::string& context);

}  // namespace mortar::harness
