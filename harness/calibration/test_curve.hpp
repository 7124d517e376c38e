// A user's test curve for calibration: one digitised or recorded test of a
// joint, as CSV with metadata comment lines that state the kind of test and,
// for shear, the constant normal stress. The format extends the experimental
// curves of calibration_data/ compatibly (validate reads the same files and
// skips the comment lines); it is documented in calibration_data/README.md
// and harness/README.md:
//
//   # kind: shear                 tension | cyclic_tension | shear | cyclic_shear | compression
//   # sigma_n: -0.5 MPa           shear kinds only; law signs, compression < 0
//                                 (cyclic_shear may hold a tension, > 0: its
//                                 unloading branches are open and give bs)
//   slip_mm,tau_MPa,uplift_mm     tension: opening_mm,sigma_MPa
//                                 compression: closure_mm,sigma_MPa (closure
//                                 >= 0, never decreasing; sigma law signs, <= 0)
//
// Units are part of the column names and of the sigma_n line; the reader
// never converts.
#pragma once

#include <string>
#include <vector>

namespace mortar::harness {

enum class TestKind { tension, cyclic_tension, shear, cyclic_shear, compression };
const char* test_kind_name(TestKind k);

struct TestCurve {
  std::string file;  // where it was read from ("" when made in memory)
  std::string name;  // file stem: names the curve in the report and the plots
  TestKind kind = TestKind::shear;
  double sigma_n = 0;         // constant normal stress of a shear test [MPa], law signs (compression < 0)
  std::vector<double> x;      // opening (tension), slip (shear) or closure (compression, >= 0) [mm], in test order
  std::vector<double> y;      // sigma_n (tension, compression: law signs) or tau (shear) [MPa]
  std::vector<double> uplift; // normal opening since the start of shearing [mm]; empty when not measured

  bool compression() const { return kind == TestKind::compression; }
  bool shear() const { return kind == TestKind::shear || kind == TestKind::cyclic_shear; }
  // Unloading-reloading or reversals: the abscissa may decrease.
  bool cycles() const { return kind == TestKind::cyclic_tension || kind == TestKind::cyclic_shear; }
  bool has_uplift() const { return !uplift.empty(); }
  // Shear at constant compression: the tests that show the hyperbola's peak.
  bool shear_under_compression() const { return shear() && sigma_n < 0; }
  // The damage ratio the curve's unloading branches show (docs/model.md 6):
  // "bn" for cyclic tension, "bs" for cyclic shear at constant tension (open
  // while it unloads), nullptr otherwise (closed shear unloads through its
  // plastic slip alone).
  const char* unloading_shows() const {
    if (kind == TestKind::cyclic_tension) return "bn";
    return kind == TestKind::cyclic_shear && sigma_n > 0 ? "bs" : nullptr;
  }
};

// Reads one curve; InputError naming the file, the line, the value and the
// rule for anything that breaks the format.
TestCurve read_test_curve(const std::string& path);

// Every *.csv under `dir`, in path order, except the regression baselines in
// folders named `reference` (the project's own output, not test data).
// InputError when `dir` is not a folder or holds no curve.
std::vector<TestCurve> read_test_curves(const std::string& dir);

// Writes a curve in the format above; `comments` become '#' lines first.
void write_test_curve(const std::string& path, const TestCurve& curve, const std::vector<std::string>& comments);

}  // namespace mortar::harness
