#include "calibration/simulation.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/explicit_run.hpp"

namespace mortar::harness {

Protocol protocol_for(const TestCurve& c, const SimulationSettings& s) {
  Protocol p;
  p.file = c.file;
  p.title = c.name;
  p.directions = 2;
  const int along = c.shear() ? 1 : 0;  // the imposed component: s1 or n
  if (c.shear()) {
    ProgramStep normal;
    normal.name = "normal stress";
    normal.increments = s.normal_increments;
    normal.component[0] = {Control::traction, c.sigma_n};
    p.steps.push_back(normal);
  }
  // The increment from the largest |abscissa|, not the travel: unloading
  // and reversals add increments rather than coarsen the loading branches.
  double reach = 0, last = 0;
  for (double x : c.x) reach = std::max(reach, std::abs(x));
  const double h = reach > 0 ? reach / s.increments : 1;
  for (size_t i = 0; i < c.x.size(); ++i) {
    ProgramStep step;
    step.name = "to data point " + std::to_string(i + 1);
    step.increments = std::max(1L, static_cast<long>(std::ceil(std::abs(c.x[i] - last) / h)));
    // A component a step leaves out holds; both are written for clarity.
    step.component[0] = c.shear() ? ComponentProgram{Control::traction, c.sigma_n} : ComponentProgram{};
    step.component[along] = {Control::displacement, c.compression() ? -c.x[i] : c.x[i]};
    p.steps.push_back(step);
    last = c.x[i];
  }
  return p;
}

SimulatedCurve simulate(const Parameters& p, const TestCurve& c, const SimulationSettings& s, const CompressionCap& cap) {
  const Protocol protocol = protocol_for(c, s);
  const int first = c.shear() ? 1 : 0;  // program steps before the first data point
  std::vector<Sample> end_of_step(protocol.steps.size() + 1);
  RunSettings run;
  run.scheme = s.scheme;
  run.stol = s.stol;
  run.cap = cap;
  run_protocol(p, protocol, run, [&](int, const Sample& sample) { end_of_step[sample.step] = sample; });
  SimulatedCurve out;
  const int j = c.shear() ? 1 : 0;
  const double normal_start = end_of_step[first].separation[0];
  for (size_t i = 0; i < c.x.size(); ++i) {
    const Sample& at = end_of_step[first + 1 + i];
    out.y.push_back(at.traction[j]);
    if (c.shear()) out.uplift.push_back(at.separation[0] - normal_start);
  }
  return out;
}

}  // namespace mortar::harness
