// Errors in user input (parameter files, loading programs, data folders,
// command-line values). The message always names the file (and the line
// where one applies), the offending value and the rule it breaks.
#pragma once

#include <stdexcept>
#include <string>

namespace mortar::harness {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "file:line" (or "file" when the line is unknown, line <= 0).
std::string file_position(const std::string& file, int line);

// A number as the user gave it, for a message: 9 significant digits, and
// nan or inf spelt out.
std::string input_number(double x);

}  // namespace mortar::harness
