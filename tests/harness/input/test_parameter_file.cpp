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

TEST_CASE("The compression cap's keys are optional: none is no cap", "[inputs][cap]") {
  const ParameterSet set = read_parameter_file(std::string(MJ_TEST_DATA_DIR) + "/vdp_sn0.5.toml");
  CHECK_FALSE(set.cap.on());
  for (int i = 0; i < kCapCount; ++i) CHECK(set.cap_line[i] == 0);
}

TEST_CASE("A parameter file with fc, Cs, Gfc, kappa_p reads them with their lines and round-trips", "[inputs][cap]") {
  // Arrange
  const ParameterSet set = read_parameter_file(std::string(MJ_TEST_DATA_DIR) + "/vdp_sn0.5_cap.toml");
  REQUIRE(set.cap.on());
  const double cap[kCapCount] = {10, 1, 2, 0.02};
  for (int i = 0; i < kCapCount; ++i) {
    CAPTURE(kCapParameterInfo[i].name);
    CHECK(cap_parameter_at(set.cap, i) == cap[i]);
    CHECK(set.cap_line[i] == 18 + i);  // after the 14 parameters
  }
  // Act: written and read back, the cap with values that are no short decimals.
  mortar::CompressionCap odd = set.cap;
  odd.fc = 31.0 / 3.0;
  odd.kappa_p = 0.1 / 7.0;
  const auto dir = fresh_directory("cap_round_trip");
  write_parameter_file((dir / "p.toml").string(), set.values, {"written by the test"}, odd);
  const ParameterSet back = read_parameter_file((dir / "p.toml").string());
  // Assert
  for (int i = 0; i < kParameterCount; ++i) CHECK(parameter_at(back.values, i) == parameter_at(set.values, i));
  for (int i = 0; i < kCapCount; ++i) CHECK(cap_parameter_at(back.cap, i) == cap_parameter_at(odd, i));
  // Without a cap, none of its keys is written.
  write_parameter_file((dir / "q.toml").string(), set.values, {});
  CHECK_FALSE(read_parameter_file((dir / "q.toml").string()).cap.on());
}

TEST_CASE("A cap value that breaks its rule is an error naming the key, its line and the rule", "[inputs][cap]") {
  const auto dir = fresh_directory("bad_cap");
  struct Case {
    std::string lines, message;
  };
  const Case cases[] = {
      {"fc = 3\nCs = 1\nGfc = 2\n", "p.toml:15: parameter 'fc' = 3 violates the rule: fc/3 > sqrt(ft0^2 + Cs c0^2)"},
      {"fc = -1\n", "p.toml:15: parameter 'fc' = -1 violates the rule: fc = 0 (no cap) or 1e-3 <= fc <= 1000 MPa"},
      {"fc = 10\nCs = 1\nGfc = 0\n", "p.toml:17: parameter 'Gfc' = 0 violates the rule: 1e-6 <= Gfc <= 1e4 N/mm"},
      {"fc = 10\nCs = nan\nGfc = 2\n", "p.toml:16: parameter 'Cs' must be a finite number"},
      {"fc = 10\nCs = 1\nGfc = 2\nkappa_p = { value = 0.02, unit = \"m\" }\n",
       "unit \"m\" of 'kappa_p' is not accepted: 'kappa_p' (plastic closure at the peak fc) is given in \"mm\""},
      {"Fc = 10\n", "unknown key 'Fc'"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.lines);
    const std::string file = write_file(dir / "p.toml", "kn = 209.9\n" + kAllButKn + c.lines);
    CHECK_THROWS_WITH(read_parameter_file(file), Catch::Contains(c.message));
  }
}
