// docs/model.md 2: parameters, their order, validation rules and the
// values derived from them once.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "mortar/parameters.hpp"
#include "paper_sets.hpp"

using namespace mortar;
using namespace mortar::testing;

TEST_CASE("Parameters: props follow Table 1 order and names", "[parameters]") {
  const double props[14] = {209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};
  Parameters p;
  Controls c;
  REQUIRE(read_props(props, 14, p, c).ok());
  const Parameters expected = van_der_pluijm(-0.5);
  for (int i = 0; i < kParameterCount; ++i) {
    CAPTURE(i, kParameterInfo[i].name);
    CHECK(parameter_at(p, i) == parameter_at(expected, i));
    CHECK(parameter_index(kParameterInfo[i].name) == i);
  }
  CHECK(std::string(kParameterInfo[4].name) == "GIC");
  CHECK(parameter_index("nonsense") == -1);
  CHECK(c.scheme == Scheme::modified_euler);
}

TEST_CASE("Parameters: each rule of docs/model.md 2 is enforced with name, value and rule", "[parameters]") {
  struct Case {
    int index;
    double value;
    const char* rule_fragment;
  };
  const Case cases[] = {
      {0, 0.0, "0.01 <= kn <= 1e6 N/mm^3"}, {1, -1.0, "ks <= 1e6"},  {2, 0.0, "1e-6 <= ft0"},
      {3, -0.5, "1e-6 <= c0"},     {4, 0.0, "1e-9 <= GIC"},  {5, -1e-3, "GIIC <= 100 N/mm"},
      {6, 90.0, "phi0 < 90"},      {7, 0.0, "0 < phir"},     {7, 45.0, "phir <= phi0"},
      {8, -1.0, "0 <= m"},         {9, 95.0, "psi0 < 90"},   {10, -1.0, "0 <= psir"},
      {10, 30.0, "psir <= psi0"},  {11, -2.0, "0 <= n"},     {12, -0.1, "0 <= bn"},
      {13, -0.1, "0 <= bs"},       {3, 0.5, "c0 > ft0*tan(phi0)"}, {2, NAN, "finite"},
      // Beyond the physical ranges (issue 39: kn = 1e300 was accepted).
      {0, 1e300, "kn <= 1e6 N/mm^3"}, {1, 2e6, "ks <= 1e6"},   {2, 101.0, "ft0 <= 100 MPa"},
      {3, 1e3, "c0 <= 100 MPa"},    {4, 1e-12, "1e-9 <= GIC"}, {5, 1e5, "GIIC <= 100"},
      {8, 1e8, "m <= 1e7 mm/N"},    {11, 1e30, "n <= 1e7"},    {12, 1e4, "bn <= 1000"},
      {13, 1001.0, "bs <= 1000"},
      {0, INFINITY, "finite"},
  };
  for (const Case& k : cases) {
    Parameters p = van_der_pluijm(-0.5);
    parameter_at(p, k.index) = k.value;
    const ValidationError e = validate(p);
    CAPTURE(k.index, k.value, e.message());
    REQUIRE_FALSE(e.ok());
    CHECK(e.index == k.index);
    CHECK(std::string(e.rule).find(k.rule_fragment) != std::string::npos);
    CHECK(e.message().find(kParameterInfo[k.index].name) != std::string::npos);
    CHECK_THROWS_AS(make_model_checked(p), std::invalid_argument);
  }
  // Boundaries that are allowed.
  Parameters p = van_der_pluijm(-0.5);
  p.phir = p.phi0;
  p.psir = p.psi0;
  p.m = p.n = p.bn = p.bs = 0;
  CHECK(validate(p).ok());
  p.kn = p.ks = 1e6;
  p.GIC = 1e-9;
  p.GIIC = 100;
  p.m = p.n = 1e7;
  p.bn = p.bs = 1000;
  CHECK(validate(p).ok());
}

TEST_CASE("Parameters: optional controls from props 15-19, zero keeps the default", "[parameters]") {
  double props[19] = {209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3,
                      2, 1e-4, 0, 500, 1e-3};
  Parameters p;
  Controls c;
  REQUIRE(read_props(props, 19, p, c).ok());
  CHECK(c.scheme == Scheme::forward_euler);
  CHECK(c.stol == 1e-4);
  CHECK(c.ftol == Controls{}.ftol);
  CHECK(c.max_substeps == 500);
  CHECK(c.min_substep == 1e-3);
  props[14] = 7;
  ValidationError e = read_props(props, 19, p, c);
  CHECK(e.index == 14);
  props[14] = 1;
  props[15] = 2;  // STOL must be < 1
  CHECK(read_props(props, 19, p, c).index == 15);
  props[15] = 0;
  props[17] = 2.5;  // not a whole number
  CHECK(read_props(props, 19, p, c).index == 17);
  props[17] = 1e9;  // the largest budget (the fuzz target never passes it: fuzz_input.hpp)
  REQUIRE(read_props(props, 19, p, c).ok());
  CHECK(c.max_substeps == 1000000000);
  props[17] = 1e9 + 1;
  CHECK(read_props(props, 19, p, c).index == 17);
  props[17] = 500;
  CHECK(read_props(props, 13, p, c).message().find("nProps >= 14") != std::string::npos);
  for (int bad : {-5, 0, 13}) {
    const ValidationError e = read_props(props, bad, p, c);
    CHECK_FALSE(e.ok());
    CHECK(e.argument);
    CHECK(e.message().find("argument 'nProps'") != std::string::npos);
  }
}

TEST_CASE("Parameters: alpha and beta at s = 1 satisfy Eq. 3", "[parameters]") {
  const Model M = make_model_checked(van_der_pluijm(-0.5));
  // c^2 = beta^2 - alpha^2 and ft = (beta - alpha)/tan(phi).
  CHECK(M.beta0 * M.beta0 - M.alpha0 * M.alpha0 == Approx(0.88 * 0.88).epsilon(1e-14));
  CHECK((M.beta0 - M.alpha0) / std::tan(40.97 * M_PI / 180) == Approx(0.62).epsilon(1e-14));
  CHECK(M.alpha0 > 0);
}

TEST_CASE("Parameters: to_props writes props 1-19 that read_props reads back", "[parameters]") {
  const Parameters p = almeida_m34();
  Controls c;
  c.scheme = Scheme::implicit;
  c.stol = 3e-6;
  c.ftol = 2e-9;
  c.max_substeps = 777;
  c.min_substep = 5e-5;
  const auto props = to_props(p, c);
  Parameters q;
  Controls d;
  REQUIRE(read_props(props.data(), kPropsWithControls, q, d).ok());
  for (int i = 0; i < kParameterCount; ++i) CHECK(parameter_at(q, i) == parameter_at(p, i));
  CHECK(d.scheme == c.scheme);
  CHECK(d.stol == c.stol);
  CHECK(d.ftol == c.ftol);
  CHECK(d.max_substeps == c.max_substeps);
  CHECK(d.min_substep == c.min_substep);
}

TEST_CASE("Parameters: scheme 3 (backward Euler) is read from props(15) and named", "[parameters][implicit]") {
  Controls implicit;
  implicit.scheme = Scheme::implicit;
  auto props = to_props(almeida_m15(), implicit);
  REQUIRE(props[14] == 3);
  Parameters q;
  Controls c;
  REQUIRE(read_props(props.data(), 15, q, c).ok());
  CHECK(c.scheme == Scheme::implicit);
  CHECK(std::string(scheme_name(Scheme::implicit)) == "backward-euler");
  props[14] = 4;
  const ValidationError e = read_props(props.data(), 15, q, c);
  CHECK_FALSE(e.ok());
  CHECK(e.index == 14);
}
