// Parameter files: what is read is what was written, in the documented
// units, and a value that is no finite number is refused with its place.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {
// Every parameter of the van der Pluijm set but kn, one per line.
const std::string kAllButKn =
    "ks = 87.4\nft0 = 0.62\nc0 = 0.88\nGIC = 0.00458\nGIIC = 0.058\n"
    "phi0 = 40.97\nphir = 36.87\nm = 1217.7\npsi0 = 27.7\npsir = 0\nn = 1828.3\n"
    "bn = 10\nbs = 3\n";
}  // namespace

TEST_CASE("A parameter file gives the 14 values of Table 1 and where each was written", "[inputs]") {
  // Act
  const ParameterSet set = read_parameter_file(std::string(MJ_CALIBRATION_DATA_DIR) + "/almeida_tension/params_M34.toml");
  // Assert
  const double table1[kParameterCount] = {750.5, 312.7, 0.91, 1.37, 0.00293, 0.02925, 40,
                                          32,    2944.5, 8,   0,    4923.8,  10,      3};
  for (int i = 0; i < kParameterCount; ++i) {
    CAPTURE(kParameterInfo[i].name);
    CHECK(parameter_at(set.values, i) == table1[i]);
    CHECK(set.line[i] == i + 4);  // three comment lines, then one parameter per line
  }
}

TEST_CASE("Bare numbers are read in the documented units and integers count as numbers", "[inputs]") {
  // Arrange
  const auto dir = fresh_directory("bare_numbers");
  const std::string file = write_file(dir / "p.toml", "kn = 209.9\n" + kAllButKn);
  // Act
  const ParameterSet set = read_parameter_file(file);
  // Assert
  CHECK(set.values.psir == 0.0);
  CHECK(set.values.bn == 10.0);
  CHECK(set.values.m == 1217.7);
}

TEST_CASE("A non-finite parameter is an error, not a clamp", "[inputs]") {
  const auto dir = fresh_directory("nan_param");
  const std::string file = write_file(dir / "p.toml", "kn = nan\n" + kAllButKn);
  CHECK_THROWS_WITH(read_parameter_file(file), Catch::Contains("p.toml:1: parameter 'kn' must be a finite number"));
}
