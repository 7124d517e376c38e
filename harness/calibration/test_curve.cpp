#include "calibration/test_curve.hpp"

#include "calibration/curve_checks.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "input/input_error.hpp"
#include "output/csv.hpp"
#include "output/output_paths.hpp"

namespace fs = std::filesystem;

namespace mortar::harness {

const char* test_kind_name(TestKind k) {
  switch (k) {
    case TestKind::tension: return "tension";
    case TestKind::cyclic_tension: return "cyclic_tension";
    case TestKind::shear: return "shear";
    case TestKind::cyclic_shear: return "cyclic_shear";
    case TestKind::compression: return "compression";
  }
  return "unknown";
}

namespace {

struct Metadata {
  std::string kind, sigma_n;
  int kind_line = 0, sigma_line = 0;
};

// The "# kind: ..." and "# sigma_n: ..." lines; every other comment is text.
Metadata read_metadata(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file for reading");
  Metadata m;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] != '#') continue;
    const std::string body = trimmed(line.substr(1));
    for (auto [key, value, at] : {std::tuple{"kind:", &m.kind, &m.kind_line},
                                  std::tuple{"sigma_n:", &m.sigma_n, &m.sigma_line}}) {
      if (body.rfind(key, 0) != 0) continue;
      if (*at) throw InputError(path + ":" + std::to_string(number) + ": a second '" + key + "' line (first at line " +
                                std::to_string(*at) + ")");
      *value = trimmed(body.substr(std::string(key).size()));
      *at = number;
    }
  }
  return m;
}

TestKind parse_kind(const std::string& path, const Metadata& m) {
  if (!m.kind_line)
    throw InputError(path + ": states no kind of test: a test curve needs a line '# kind: tension', "
                            "'# kind: cyclic_tension', '# kind: shear', '# kind: cyclic_shear' or '# kind: compression'");
  for (TestKind k : {TestKind::tension, TestKind::cyclic_tension, TestKind::shear, TestKind::cyclic_shear,
                     TestKind::compression})
    if (m.kind == test_kind_name(k)) return k;
  throw InputError(path + ":" + std::to_string(m.kind_line) + ": kind '" + m.kind +
                   "' is not one of tension, cyclic_tension, shear, cyclic_shear, compression");
}

// "-0.5 MPa": the number and its unit, which must be MPa (never converted).
// A monotonic shear test is at constant compression; a cyclic one may be at
// constant tension, where its unloading branches show the crack slip (bs).
double parse_sigma_n(const std::string& path, const Metadata& m, TestKind kind) {
  const std::string where = path + ":" + std::to_string(m.sigma_line);
  std::istringstream in(m.sigma_n);
  std::string number, unit, extra;
  in >> number >> unit >> extra;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !std::isfinite(value))
    throw InputError(where + ": sigma_n '" + m.sigma_n + "' must be a finite number followed by its unit, e.g. '-0.5 MPa'");
  if ((unit != "MPa" && unit != "N/mm^2") || !extra.empty())
    throw InputError(where + ": sigma_n '" + m.sigma_n + "' must state its unit as MPa (or N/mm^2); the reader never converts");
  if (kind == TestKind::cyclic_shear ? value == 0 : !(value < 0))
    throw InputError(where + ": sigma_n = " + number + " MPa violates the rule: " +
                     (kind == TestKind::cyclic_shear
                          ? "a cyclic shear test at constant compression (sigma_n < 0) or tension (sigma_n > 0, below "
                            "ft0), not 0"
                          : "a shear test at constant compression, sigma_n < 0 (law signs: tension positive; a test at "
                            "constant tension with unloading branches is kind cyclic_shear)"));
  return value;
}

void check_columns(const CsvTable& t, TestKind kind) {
  const std::vector<std::string> allowed = kind == TestKind::compression ? std::vector<std::string>{"closure_mm", "sigma_MPa"}
                                          : kind == TestKind::tension || kind == TestKind::cyclic_tension
                                              ? std::vector<std::string>{"opening_mm", "sigma_MPa"}
                                              : std::vector<std::string>{"slip_mm", "tau_MPa", "uplift_mm"};
  for (const std::string& h : t.header)
    if (std::find(allowed.begin(), allowed.end(), h) == allowed.end()) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw InputError(t.file + ": column '" + h + "' is not a column of a " + test_kind_name(kind) +
                       " curve (" + list + "; the unit is part of the name)");
    }
}

}  // namespace

TestCurve read_test_curve(const std::string& path) {
  const Metadata m = read_metadata(path);
  TestCurve c;
  c.file = path;
  c.name = fs::path(path).stem().string();
  c.kind = parse_kind(path, m);
  if (c.shear() && !m.sigma_line)
    throw InputError(path + ": a " + std::string(test_kind_name(c.kind)) +
                     " curve needs its constant normal stress: a line '# sigma_n: -0.5 MPa'");
  if (!c.shear() && m.sigma_line)
    throw InputError(path + ":" + std::to_string(m.sigma_line) +
                     ": a " + test_kind_name(c.kind) + " curve has no constant normal stress; remove the sigma_n line");
  if (c.shear()) c.sigma_n = parse_sigma_n(path, m, c.kind);
  const CsvTable t = read_csv(path);
  check_columns(t, c.kind);
  c.x = t.values(c.shear() ? "slip_mm" : c.compression() ? "closure_mm" : "opening_mm");
  c.y = t.values(c.shear() ? "tau_MPa" : "sigma_MPa");
  if (t.column("uplift_mm") >= 0) c.uplift = t.values("uplift_mm");
  if (c.x.size() < 4)
    throw InputError(path + ": " + std::to_string(c.x.size()) + " points; a curve needs at least 4");
  check_curve_values(c);  // before the order: a negative slip is a sign mistake
  if (!c.cycles())
    for (size_t i = 1; i < c.x.size(); ++i)
      if (c.x[i] < c.x[i - 1])
        throw InputError(path + ": row " + std::to_string(i + 1) + ": " + (c.shear() ? "slip" : c.compression() ? "closure" : "opening") + " " +
                         std::to_string(c.x[i]) + " mm is below the row before (" + std::to_string(c.x[i - 1]) +
                         " mm): a monotonic test's abscissa never decreases (tests with unloading: kind cyclic_tension or "
                         "cyclic_shear)");
  return c;
}

std::vector<TestCurve> read_test_curves(const std::string& dir) {
  if (!fs::is_directory(dir)) throw InputError("--data " + dir + ": not a directory");
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const fs::path& p = e.path();
    if (!e.is_regular_file() || p.extension() != ".csv") continue;
    if (p.parent_path().filename() == "reference") continue;
    files.push_back(p.string());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError("--data " + dir + ": holds no test curve (*.csv)");
  std::vector<TestCurve> curves;
  for (const std::string& f : files) curves.push_back(read_test_curve(f));
  return curves;
}

void write_test_curve(const std::string& path, const TestCurve& c, const std::vector<std::string>& comments) {
  std::ofstream out(path);
  if (!out) throw InputError(cannot_write(path));
  for (const std::string& line : comments) out << "# " << line << "\n";
  out << "# kind: " << test_kind_name(c.kind) << "\n";
  out.precision(6);
  if (c.shear()) out << "# sigma_n: " << c.sigma_n << " MPa\n";
  out << (c.shear() ? "slip_mm,tau_MPa" : c.compression() ? "closure_mm,sigma_MPa" : "opening_mm,sigma_MPa") << (c.has_uplift() ? ",uplift_mm" : "") << "\n";
  out.precision(7);
  for (size_t i = 0; i < c.x.size(); ++i) {
    out << c.x[i] << "," << c.y[i];
    if (c.has_uplift()) out << "," << c.uplift[i];
    out << "\n";
  }
  if (!out) throw InputError(path + ": write failed");
}

}  // namespace mortar::harness
