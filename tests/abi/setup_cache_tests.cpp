// The props read once per thread (adapter/arguments.hpp, cached_setup): every
// call integrates with its own props whatever the thread read before, and a
// props array that breaks a rule is reported at every call.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "abi_support.hpp"
#include "explicit_calls.hpp"
#include "paper_sets.hpp"
#include "stderr_capture.hpp"
#include "vuinteraction.h"

namespace {

using mj_abi_test::GeneralContact;
using Real = mj_real;

// Almeida M15 with props(1..20), as one interaction's props.
std::vector<Real> m15_props() { return mj_abi_test::props_of<Real>(mortar::testing::almeida_m15(), 20); }

// Another interaction's: every value that the setup reads changed (kn,
// tan(phi0) through phi0, the scheme, the shear sign).
std::vector<Real> other_props() {
  std::vector<Real> p = m15_props();
  p[0] *= Real(2);    // kn
  p[6] += Real(2);    // phi0 [deg]
  p[14] = Real(2);    // forward Euler
  p[19] = Real(1);    // shear sign +1
  return p;
}

// A pressed joint slipping, with some opening on odd points: plastic and
// elastic increments.
void step(GeneralContact& gc, int i) {
  for (int k = 0; k < gc.n_block; ++k) {
    gc.penetration[k] = Real(i == 0 ? 0.0 : (k % 2 ? -2e-4 * i : 1e-3));
    gc.dr_disp[k * 3 + 1] = Real(i == 0 ? 0.0 : 2e-3);
    gc.dr_disp[k * 3 + 2] = Real(i == 0 ? 0.0 : -1e-3 * (k % 3));
  }
  gc.call();
}

bool same_outputs(const GeneralContact& a, const GeneralContact& b) {
  return a.state == b.state && a.stress == b.stress && a.sed == b.sed && a.spd == b.spd;
}

}  // namespace

TEST_CASE("Setup cache: two interactions' props alternating on one thread give each its own results",
          "[abi][props]") {
  const int n = 40;
  GeneralContact alone_a(8, 3, m15_props()), alone_b(8, 3, other_props());
  for (int i = 0; i <= n; ++i) step(alone_a, i);
  for (int i = 0; i <= n; ++i) step(alone_b, i);
  // The two differ, so that the comparison below can see a stale setup.
  REQUIRE(alone_a.stress != alone_b.stress);
  GeneralContact a(8, 3, m15_props()), b(8, 3, other_props());
  for (int i = 0; i <= n; ++i) {
    step(a, i);
    step(b, i);
  }
  CHECK(same_outputs(a, alone_a));
  CHECK(same_outputs(b, alone_b));
}

TEST_CASE("Setup cache: props changed in place between calls take effect at the next call", "[abi][props]") {
  GeneralContact changed(4, 3, m15_props());
  for (int i = 0; i <= 10; ++i) step(changed, i);
  GeneralContact unchanged = changed;
  // The same array, one value changed, and no other call between: a key of
  // the array's address would miss it.
  changed.props[1] *= Real(0.5);  // ks
  // The same start and props, from an array this thread has not read (the
  // default shear sign spelt out).
  GeneralContact fresh = changed;
  fresh.props[19] = Real(-1);
  step(changed, 11);
  step(unchanged, 11);
  step(fresh, 11);
  CHECK(changed.stress != unchanged.stress);  // ks halved changes the traction
  CHECK(same_outputs(changed, fresh));
}

TEST_CASE("Setup cache: a bad props array after good ones is reported at every call, and the good ones still run",
          "[abi][props]") {
  GeneralContact good(4, 3, m15_props());
  std::vector<Real> bad_props = m15_props();
  bad_props[3] = Real(0.5);  // c0 below ft0 tan(phi0)
  GeneralContact bad(4, 3, bad_props);
  step(good, 0);
  for (int call = 0; call < 2; ++call) {
    mj_test::StderrCapture err;
    step(bad, 0);
    INFO("call " << call << ": " << err.text());
    CHECK(err.text().find("'c0' (props(4))") != std::string::npos);
    CHECK(double(bad.state_of(0)[mortar::slot::status]) == -4.0);
  }
  step(good, 1);
  CHECK(double(good.state_of(0)[mortar::slot::status]) == 0.0);
}
