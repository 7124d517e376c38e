// Small example: a tension curve (Almeida M15) and a shear curve (van der
// Pluijm, -0.5 MPa) of one interface point, printed as columns. Each curve is
// a loading program (input/protocol.hpp) driven through vuinteraction_ by the
// harness's explicit mock solver, as `masonry-joint run` drives a file.
#include <cstdio>

#include "input/protocol.hpp"
#include "solvers/explicit_run.hpp"

using namespace mortar;
using namespace mortar::harness;

namespace {

ProgramStep step_of(long increments, ComponentProgram n, ComponentProgram s1 = {}) {
  ProgramStep step;
  step.increments = increments;
  step.component = {n, s1, ComponentProgram{}};
  return step;
}

// Runs `program` on one point and prints every tenth increment's columns.
template <class Columns>
void print_curve(const Parameters& p, const std::vector<ProgramStep>& program, long first, Columns columns) {
  Protocol protocol;
  protocol.steps = program;
  run_protocol(p, protocol, RunSettings{}, [&](int, const Sample& s) {
    const long i = s.increment - first;
    if (i > 0 && i % 10 == 0) columns(s);
  });
}

}  // namespace

int main() {
  const Parameters m15{741.1, 308.8, 1.78, 2.67, 0.01209, 0.121, 40, 32, 511.9, 8, 0, 856.1, 10, 3};
  std::printf("# tension, Almeida M15: delta_n [mm]  sigma_n [MPa]  d_n\n");
  print_curve(m15, {step_of(400, {Control::displacement, 400 * 5e-5})}, 0, [](const Sample& s) {
    std::printf("%10.5f %10.5f %8.5f\n", s.separation[0], s.traction[0], s.state[slot::damage_n]);
  });

  const Parameters vdp{209.9, 87.4, 0.62, 0.88, 0.00458, 0.058, 40.97, 36.87, 1217.7, 27.7, 0, 1828.3, 10, 3};
  const ComponentProgram compression{Control::traction, -0.5};
  std::printf("\n# shear at sigma_n = -0.5 MPa, van der Pluijm: slip [mm]  tau [MPa]  delta_n [mm]\n");
  print_curve(vdp, {step_of(1, compression), step_of(500, compression, {Control::displacement, 500 * 2e-4})}, 1,
              [](const Sample& s) { std::printf("%10.5f %10.5f %12.3e\n", s.separation[1], s.traction[1], s.separation[0]); });
  return 0;
}
