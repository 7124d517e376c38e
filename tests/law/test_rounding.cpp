// Every multiply and add rounds on its own (CMakeLists.txt: -ffp-contract=off
// for the whole project), so that the law's results do not depend on the
// instruction set a build targets (README, the Abaqus build step). This file
// is compiled with the flags the law's sources are: on a target with fused
// multiply-add (-march=native on most x86-64 hosts, every aarch64) a build
// that fused a * b + c would give -2^-60 below, not 0.
#include <catch2/catch.hpp>

#include <cmath>

namespace {
// Read at run time, so that the compiler cannot fold the expression.
volatile double a_in = 1.0 + 0x1p-30, b_in = 1.0 - 0x1p-30, c_in = -1.0;

double multiply_add(double a, double b, double c) { return a * b + c; }
}  // namespace

TEST_CASE("a * b + c rounds the product before the sum: no fused multiply-add in the build", "[build]") {
  const double a = a_in, b = b_in, c = c_in;
  // a * b = 1 - 2^-60 exactly, which rounds to 1; fused, the sum keeps -2^-60.
  CHECK(std::fma(a, b, c) == -0x1p-60);
  REQUIRE(multiply_add(a, b, c) == 0.0);
}
