// Validation: the closed-form peak, the regression baselines (a moved curve
// fails), and the comparison with digitised experimental curves (tested with
// a synthetic curve made here, never stored as experimental data).
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "commands/validate.hpp"
#include "output/csv.hpp"
#include "support.hpp"
#include "validation/checks.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;
namespace fs = std::filesystem;

namespace {
// A private copy of one series of calibration_data/, to modify.
fs::path copy_series(const std::string& test, const std::string& series) {
  const fs::path root = fresh_directory(test);
  fs::create_directories(root / "data" / series);
  fs::copy(fs::path(MJ_CALIBRATION_DATA_DIR) / series, root / "data" / series, fs::copy_options::recursive);
  return root;
}

// The first line of the table that contains `needle` ("" if none). Matching
// single lines keeps std::regex, which recurses per character, off the whole
// table.
std::string line_with(const std::string& table, const std::string& needle) {
  std::istringstream in(table);
  std::string line;
  while (std::getline(in, line))
    if (line.find(needle) != std::string::npos) return line;
  return "";
}

int validate_quietly(const fs::path& root, const std::string& series, std::string& table) {
  ValidateOptions o;
  o.data_dir = (root / "data").string();
  o.out_dir = (root / "out").string();
  o.series = {series};
  o.quiet = true;
  o.wide = true;  // the table as validation.txt has it: one line a check
  o.plots = false;
  std::ostringstream out, err;
  const int status = run_validation(o, out, err);
  table = out.str();
  return status;
}
}  // namespace

TEST_CASE("The closed-form peak of docs/model.md 4 for the van der Pluijm set", "[validation]") {
  Parameters p{209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};
  // sqrt((beta0 - sigma_n tan phi0)^2 - alpha0^2), evaluated independently.
  CHECK(closed_form_peak_shear(p, -0.1) == Approx(0.97652227).epsilon(1e-8));
  CHECK(closed_form_peak_shear(p, -0.5) == Approx(1.34951521).epsilon(1e-8));
  CHECK(closed_form_peak_shear(p, -1.0) == Approx(1.80139224).epsilon(1e-8));
}

TEST_CASE("A series passes against its own baselines", "[validation]") {
  const fs::path root = copy_series("baseline_pass", "almeida_tension");
  std::string table;
  CHECK(validate_quietly(root, "almeida_tension", table) == 0);
  CHECK_THAT(table, Catch::Contains("reference curve: worst relative difference"));
  CHECK_THAT(table, !Catch::Contains("FAIL"));
}

TEST_CASE("A curve moved by more than the regression tolerance fails", "[validation]") {
  // Arrange: move one traction of the stored M34 baseline by 3e-6 of the peak.
  const fs::path root = copy_series("baseline_moved", "almeida_tension");
  const fs::path ref = root / "data" / "almeida_tension" / "reference" / "almeida_M34.csv";
  CsvTable t = read_csv(ref.string());
  const int sigma = t.require("sigma_n");
  t.rows[t.rows.size() / 3][sigma] += 3e-6 * 0.91;
  write_csv(ref.string(), t.header, t.rows);
  // Act
  std::string table;
  const int status = validate_quietly(root, "almeida_tension", table);
  // Assert
  CHECK(status == 1);
  CHECK_THAT(line_with(table, "FAIL"),
             Catch::Matches(".*reference curve: worst relative difference +3e-06 .*sigma_n at increment [0-9]+ +<= 1e-06 +FAIL"));
}

TEST_CASE("A missing baseline fails rather than passing silently", "[validation]") {
  const fs::path root = copy_series("baseline_missing", "almeida_tension");
  fs::remove(root / "data" / "almeida_tension" / "reference" / "almeida_M15.csv");
  std::string table;
  CHECK(validate_quietly(root, "almeida_tension", table) == 1);
  CHECK_THAT(line_with(table, "reference curve"),
             Catch::Matches(".*reference curve +missing +reference/almeida_M15\\.csv .*FAIL"));
}

TEST_CASE("Experimental curves, when present, are compared by RMS difference", "[validation]") {
  // Arrange: a synthetic "experiment" 0.01 MPa above the simulated curve at
  // the baseline's openings, plus one point beyond the simulated range.
  const fs::path root = copy_series("experimental", "almeida_tension");
  const fs::path series = root / "data" / "almeida_tension";
  const CsvTable ref = read_csv((series / "reference" / "almeida_M15.csv").string());
  std::vector<std::vector<double>> rows;
  for (const auto& r : ref.rows) rows.push_back({r[ref.require("delta_n")], r[ref.require("sigma_n")] + 0.01});
  rows.push_back({1.0, 0.0});
  fs::create_directories(series / "experimental");
  write_csv((series / "experimental" / "almeida_M15.csv").string(), {"opening_mm", "sigma_MPa"}, rows);
  // Act
  std::string table;
  const int status = validate_quietly(root, "almeida_tension", table);
  // Assert: reported, not judged
  CHECK(status == 0);
  CHECK_THAT(line_with(table, "experimental curve"),
             Catch::Matches(".*experimental curve: RMS difference \\[MPa\\] +0\\.01 +" + std::to_string(ref.rows.size()) +
                            " points +.*1 beyond the run +info"));
}
