// The root finders of the integration (src/mortar/integration/root_finder.hpp):
// Pegasus and the crossing bracket on the substep size.
#include <catch2/catch.hpp>

#include <cmath>

#include "mortar/integration/root_finder.hpp"

using namespace mortar;

TEST_CASE("Root finder: Pegasus converges to the root within the tolerance", "[root_finder]") {
  // A convex and a concave function, roots inside and near an end of [0, 2].
  struct Case {
    double (*f)(double);
    double root;
  } cases[] = {{[](double x) { return x * x * x - 2; }, std::cbrt(2.0)},
               {[](double x) { return std::exp(x) - 1.01; }, std::log(1.01)},
               {[](double x) { return 1 - std::sqrt(x); }, 1.0}};
  for (const Case& c : cases) {
    int evaluations = 0;
    auto sample = [&](double x) {
      ++evaluations;
      return RootSample{c.f(x), 1e-13};
    };
    const double x = pegasus(sample, 0, c.f(0), 2, c.f(2), 100);
    CHECK(std::abs(c.f(x)) <= 1e-13);
    CHECK(x == Approx(c.root).margin(1e-10));
    CHECK(evaluations < 20);  // superlinear: far fewer than bisection's ~45
  }
}

TEST_CASE("Root finder: Pegasus returns the first point within the tolerance", "[root_finder]") {
  // f = x - 1 on [0, 4]: the first secant point is the root; a loose
  // tolerance accepts it at once.
  int evaluations = 0;
  auto sample = [&](double x) {
    ++evaluations;
    return RootSample{x - 1, 0.5};
  };
  CHECK(pegasus(sample, 0, -1, 4, 3, 100) == 1);
  CHECK(evaluations == 1);
}

TEST_CASE("Root finder: Pegasus stops at the iteration limit with the last point tried", "[root_finder]") {
  double last = -1;
  auto sample = [&](double x) {
    last = x;
    return RootSample{std::tanh(50 * (x - 0.3)), 0.0};  // steep: not converged in 3 iterations
  };
  const double x = pegasus(sample, 0, std::tanh(-15.0), 1, std::tanh(35.0), 3);
  CHECK(x == last);
  CHECK(x > 0);
  CHECK(x < 1);
}

TEST_CASE("Root finder: the crossing bracket takes the secant point, bisecting every third try", "[root_finder]") {
  // e_lo = 1 at size 0, e_hi = -3 at size 1: the secant zero is at 0.25.
  const CrossingBracket b{true, 0.0, 1.0, 1.0, -3.0};
  CHECK(b.next(0) == 0.25);
  CHECK(b.next(1) == 0.25);
  CHECK(b.next(2) == 0.5);  // every third try
  CHECK(b.next(5) == 0.5);
  // Round-off can put the secant point on an end: bisection instead.
  const CrossingBracket flat{true, 0.2, 0.0, 0.6, -1.0};
  CHECK(flat.next(0) == Approx(0.4));
}
