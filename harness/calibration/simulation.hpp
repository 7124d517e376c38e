// A test curve simulated by the law through the harness's mixed-control
// explicit solver (solvers/explicit_run.hpp, as `validate` runs its cases):
// the test's own loading program, built from its abscissae in test order, so
// that every data point is an increment end and nothing is interpolated.
//  - tension: the opening is imposed (displacement control), no slip;
//  - shear kinds: the normal stress is applied first with the slip held at
//    zero, then held while the slip goes through the data's slips;
//  - compression: the closure is imposed (normal separation -closure), no slip.
#pragma once

#include <vector>

#include "calibration/test_curve.hpp"
#include "input/protocol.hpp"
#include "mortar/parameters.hpp"

namespace mortar::harness {

struct SimulationSettings {
  // Increments per test: the largest |abscissa| is cut into about this many
  // (a monotonic test's travel; unloading and reversals add to them), and
  // every data interval gets at least one. The law's substepping keeps
  // each increment accurate (docs/model.md 7.1); this only bounds the
  // mixed-control steps between data points.
  int increments = 300;
  int normal_increments = 5;  // applying sigma_n (elastic: the joint is undamaged)
  Scheme scheme = Scheme::modified_euler;
  double stol = 0;  // 0: the routine's default
};

struct SimulatedCurve {
  std::vector<double> y;       // traction at each data abscissa [MPa]
  std::vector<double> uplift;  // shear kinds: normal opening since the start of shearing [mm]
};

Protocol protocol_for(const TestCurve& curve, const SimulationSettings& settings);

// Throws RunFailure when the run cannot be completed (e.g. a normal stress
// the joint cannot carry).
// `cap`: the compression cap (off by default, the paper's law).
SimulatedCurve simulate(const Parameters& p, const TestCurve& curve, const SimulationSettings& settings,
                        const CompressionCap& cap = CompressionCap{});

}  // namespace mortar::harness
