// CSV files of the harness: the run format (one row per increment, written
// while running) and a small reader for reference and experimental curves.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "solvers/explicit_run.hpp"

namespace mortar::harness {

// Column names of a run CSV, in order (documented in harness/README.md).
const std::vector<std::string>& run_columns();
void write_run_header(std::ostream& out);
void write_run_row(std::ostream& out, const Sample& s);

// The value of every run column for one sample, in run_columns() order.
std::vector<double> run_row_values(const Sample& s);

// A numeric CSV with a header line. Lines starting with '#' are comments.
struct CsvTable {
  std::string file;
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  // Index of a column, or -1.
  int column(const std::string& name) const;
  // Index of a column; InputError naming the file when it is missing.
  int require(const std::string& name) const;
  std::vector<double> values(const std::string& name) const;
};

// s without its leading and trailing blanks (spaces, tabs, carriage returns).
std::string trimmed(const std::string& s);

// Reads a CSV; InputError with file and line for anything that is not a
// finite number or a row of the wrong width.
CsvTable read_csv(const std::string& path);

// Writes selected columns of a table.
void write_csv(const std::string& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& rows);

}  // namespace mortar::harness
