#include "output/csv.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "input/input_error.hpp"
#include "output/output_paths.hpp"

namespace mortar::harness {

const std::vector<std::string>& run_columns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c = {"time", "delta_n", "delta_s1", "delta_s2", "sigma_n", "tau_1", "tau_2"};
    // State variables by SDV number and name (the SDV numbers users see in
    // Abaqus); the prefix keeps SDV12-14 (delta) apart from the imposed
    // separation columns.
    for (int i = 0; i < kStateCount; ++i) c.push_back("SDV" + std::to_string(i + 1) + "_" + kStateNames[i]);
    for (const char* e : {"elastic_energy", "dissipation_increment", "dissipation", "external_work", "increment",
                          "step", "newton_iterations", "traction_residual"})
      c.push_back(e);
    return c;
  }();
  return columns;
}

std::vector<double> run_row_values(const Sample& s) {
  std::vector<double> v = {s.time,        s.separation[0], s.separation[1], s.separation[2],
                           s.traction[0], s.traction[1],   s.traction[2]};
  v.insert(v.end(), s.state.begin(), s.state.end());
  for (double x : {s.elastic_energy, s.dissipation_increment, s.dissipation, s.external_work, double(s.increment),
                   double(s.step), double(s.iterations), s.traction_residual})
    v.push_back(x);
  return v;
}

void write_run_header(std::ostream& out) {
  const char* sep = "";
  for (const std::string& c : run_columns()) {
    out << sep << c;
    sep = ",";
  }
  out << '\n';
}

namespace {
void write_values(std::ostream& out, const std::vector<double>& v) {
  char buf[32];
  for (size_t i = 0; i < v.size(); ++i) {
    // 12 significant digits: well below every tolerance the harness checks,
    // and a third smaller than round-trip precision.
    std::snprintf(buf, sizeof buf, "%.12g", v[i]);
    if (i) out << ',';
    out << buf;
  }
  out << '\n';
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(trimmed(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}
}  // namespace

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

void write_run_row(std::ostream& out, const Sample& s) { write_values(out, run_row_values(s)); }

int CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

int CsvTable::require(const std::string& name) const {
  const int c = column(name);
  if (c < 0) throw InputError(file + ": has no column '" + name + "'");
  return c;
}

std::vector<double> CsvTable::values(const std::string& name) const {
  const int c = require(name);
  std::vector<double> v;
  v.reserve(rows.size());
  for (const auto& r : rows) v.push_back(r[c]);
  return v;
}

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file for reading");
  CsvTable t;
  t.file = path;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string> cells = split(line);
    if (t.header.empty()) {
      t.header = cells;
      continue;
    }
    if (cells.size() != t.header.size())
      throw InputError(path + ":" + std::to_string(number) + ": " + std::to_string(cells.size()) +
                       " values, but the header has " + std::to_string(t.header.size()) + " columns");
    std::vector<double> row;
    for (const std::string& c : cells) {
      char* end = nullptr;
      const double x = std::strtod(c.c_str(), &end);
      if (c.empty() || *end != '\0' || !std::isfinite(x))
        throw InputError(path + ":" + std::to_string(number) + ": '" + c + "' is not a finite number");
      row.push_back(x);
    }
    t.rows.push_back(std::move(row));
  }
  if (t.header.empty()) throw InputError(path + ": empty file (a header line is required)");
  return t;
}

void write_csv(const std::string& path, const std::vector<std::string>& header,
               const std::vector<std::vector<double>>& rows) {
  std::ofstream out(path);
  if (!out) throw InputError(cannot_write(path));
  const char* sep = "";
  for (const std::string& h : header) {
    out << sep << h;
    sep = ",";
  }
  out << '\n';
  for (const auto& r : rows) write_values(out, r);
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace mortar::harness
