// Small example: a tension curve (Almeida M15) and a shear curve (van der
// Pluijm, -0.5 MPa) of one interface point, printed as columns.
#include <cstdio>

#include "mortar/integrator.hpp"
#include "point_driver.hpp"

using namespace mortar;

int main() {
  Parameters m15{741.1, 308.8, 1.78, 2.67, 0.01209, 0.121, 40, 32, 511.9, 8, 0, 856.1, 10, 3};
  Model tension = make_model_checked(m15);
  State s;
  std::printf("# tension, Almeida M15: delta_n [mm]  sigma_n [MPa]  d_n\n");
  for (int i = 1; i <= 400; ++i) {
    IncrementResult r = integrate_increment(tension, s, Vec3(5e-5, 0, 0));
    if (i % 10 == 0) std::printf("%10.5f %10.5f %8.5f\n", s.separation[0], r.traction[0], s.dn);
  }

  Parameters vdp{209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};
  Model shear = make_model_checked(vdp);
  State q;
  harness::PointStepper step = harness::law_stepper(shear);
  harness::MixedIncrement pre;
  pre.c[0] = {true, -0.5};
  harness::solve_mixed(step, q, pre);
  std::printf("\n# shear at sigma_n = -0.5 MPa, van der Pluijm: slip [mm]  tau [MPa]  delta_n [mm]\n");
  for (int i = 1; i <= 500; ++i) {
    harness::MixedIncrement inc;
    inc.c[0] = {true, -0.5};
    inc.c[1] = {false, 2e-4};
    harness::MixedResult r = harness::solve_mixed(step, q, inc);
    if (i % 10 == 0)
      std::printf("%10.5f %10.5f %12.3e\n", q.separation[1], r.result.traction[1], q.separation[0]);
  }
  return 0;
}
