// What the two compare programs (abi_compare.cpp: the Explicit routines,
// uinter_compare.cpp: UINTER) share: reading the records file a Fortran
// caller wrote (PROPS lines, then one line per call), the props of a run with
// the product's documented defaults (docs/abaqus.md, written out here
// independently of the adapter), and the value-by-value comparison with a
// relative tolerance and an absolute floor.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

namespace mj_abi_compare {

constexpr int kStates = mortar::kStateCount;

// The model and shear sign of one run (one PROPS line).
struct RunSetup {
  mortar::Model model;
  double shear_sign = 0;
};

// What props(15) = 0 and props(20) = 0 (or absent) mean for a product.
struct ProductDefaults {
  mortar::Scheme scheme;
  double shear_sign;
};

// "PROPS tag n props(1..n)" into `setup`; false if the line or props are bad.
inline bool read_setup(const std::string& line, const ProductDefaults& defaults, std::string& tag, RunSetup& setup) {
  std::istringstream in(line);
  std::string word;
  int n = 0;
  in >> word >> tag >> n;
  std::vector<double> props(n);
  for (double& v : props) in >> v;
  if (!in) return false;
  mortar::Parameters p;
  mortar::Controls c;
  if (!mortar::read_props(props.data(), std::min(n, 19), p, c).ok()) return false;
  if (n < 15 || props[14] == 0) c.scheme = defaults.scheme;
  setup.model = mortar::make_model(p, c);
  setup.shear_sign = (n >= 20 && props[19] != 0) ? props[19] : defaults.shear_sign;
  return true;
}

template <std::size_t N>
void read_values(std::istream& in, double (&values)[N]) {
  for (double& v : values) in >> v;
}

// Value-by-value agreement: |got - expected| <= rtol (|expected| + scale);
// in single precision the expected value is first rounded as the routine
// rounds its outputs. Prints the first 20 mismatches.
class Agreement {
 public:
  Agreement(double rtol, bool single) : rtol_(rtol), single_(single) {}

  template <class Record>
  void check(const Record& r, const char* what, double got, double expected, double scale) {
    if (single_) expected = double(float(expected));
    const double tol = rtol_ * (std::abs(expected) + scale);
    const double dev = std::abs(got - expected);
    worst_ = std::max(worst_, dev / tol);
    ++values_;
    if (dev <= tol) return;
    if (++mismatches_ <= 20)
      std::printf("MISMATCH %s step %d point %d %s: got %.17g expected %.17g\n", r.tag.c_str(), r.step, r.point,
                  what, got, expected);
  }

  // check() of got[i] against expected[i], i < n, each named by `format`
  // with i + 1 (e.g. "SDV %d") and floored by scale(i).
  template <class Record, class Scale>
  void check_each(const Record& r, const char* format, const double* got, const double* expected, int n,
                  Scale scale) {
    char name[40];
    for (int i = 0; i < n; ++i) {
      std::snprintf(name, sizeof name, format, i + 1);
      check(r, name, got[i], expected[i], scale(i));
    }
  }

  double rtol() const { return rtol_; }
  double worst() const { return worst_; }
  long values() const { return values_; }
  long mismatches() const { return mismatches_; }

 private:
  double rtol_;
  bool single_;
  double worst_ = 0;
  long values_ = 0, mismatches_ = 0;
};

// Reads the records file at `path`: each PROPS line sets up its run, each
// other line is one call of a run, handed to compare(setup, record).
// Returns 0, or 2 if the file cannot be read, 1 on a bad line.
template <class Record, class ReadRecord, class Compare>
int replay_records(const char* program, const char* path, const ProductDefaults& defaults, ReadRecord read_record,
                   Compare compare) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "%s: cannot read %s\n", program, path);
    return 2;
  }
  std::map<std::string, RunSetup> setups;
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, 5, "PROPS") == 0) {
      std::string tag;
      RunSetup s;
      if (!read_setup(line, defaults, tag, s)) {
        std::fprintf(stderr, "%s: bad props line: %s\n", program, line.c_str());
        return 1;
      }
      setups[tag] = s;
      continue;
    }
    Record r;
    if (!read_record(line, r) || !setups.count(r.tag)) {
      std::fprintf(stderr, "%s: bad record: %s\n", program, line.c_str());
      return 1;
    }
    compare(setups[r.tag], r);
  }
  return 0;
}

}  // namespace mj_abi_compare
