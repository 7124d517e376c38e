// props of a call: what the routine reads back (mortar::read_props) is the
// parameter set, the scheme, and the controls given, the defaults elsewhere.
#include <catch2/catch.hpp>

#include "abi/props.hpp"
#include "abi/status.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {
const Parameters kVdp{209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};

struct ReadBack {
  Parameters p;
  Controls c;
  bool ok = false;
};
ReadBack read_back(const std::vector<double>& props) {
  ReadBack r;
  r.ok = read_props(props.data(), static_cast<int>(props.size()), r.p, r.c).ok();
  return r;
}
}  // namespace

TEST_CASE("props: STOL and the substep budget 0 keep the routine's defaults", "[abi]") {
  const ReadBack r = read_back(props_for(kVdp, Scheme::forward_euler, 0));
  REQUIRE(r.ok);
  for (int i = 0; i < kParameterCount; ++i) CHECK(parameter_at(r.p, i) == parameter_at(kVdp, i));
  CHECK(r.c.scheme == Scheme::forward_euler);
  CHECK(r.c.stol == Controls{}.stol);
  CHECK(r.c.max_substeps == Controls{}.max_substeps);
}

TEST_CASE("props: a given STOL and substep budget reach the routine", "[abi]") {
  const ReadBack r = read_back(props_for(kVdp, Scheme::implicit, 1e-7, 12));
  REQUIRE(r.ok);
  CHECK(r.c.scheme == Scheme::implicit);
  CHECK(r.c.stol == 1e-7);
  CHECK(r.c.max_substeps == 12);
  CHECK(r.c.ftol == Controls{}.ftol);
}

TEST_CASE("SDV 21: the law's codes by their names, the adapters' by their rule", "[abi]") {
  CHECK(status_meaning(1) == failure_name(static_cast<Failure>(1)));
  CHECK(status_meaning(-1) == "nDir is not 2 or 3");
  CHECK(status_meaning(-4).find("property") != std::string::npos);
  CHECK(status_meaning(-99) == "the routine's internal error");
}

TEST_CASE("props: a compression cap reaches the routine as props(21..24), with the state count that keeps it",
          "[abi][cap]") {
  const CompressionCap cap{10, 1, 2, 0.02};
  const std::vector<double> props = props_for(kVdp, Scheme::modified_euler, 0, 0, cap);
  REQUIRE(props.size() == 24);
  CHECK(props[19] == 0);  // the shear sign at its default
  const ReadBack r = read_back(props);
  REQUIRE(r.ok);
  CompressionCap back;
  REQUIRE(read_cap(props.data(), static_cast<int>(props.size()), r.p, back).ok());
  for (int i = 0; i < kCapCount; ++i) CHECK(cap_parameter_at(back, i) == cap_parameter_at(cap, i));
  CHECK(state_count_for(cap) == kCappedStateCountDouble);
  // Without a cap: props(1..19) and DEPVAR 35, as before.
  CHECK(props_for(kVdp, Scheme::modified_euler, 0).size() == 19);
  CHECK(state_count_for(CompressionCap{}) == kFlaggedStateCount);
}
