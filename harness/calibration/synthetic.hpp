// Synthetic test curves: made by the law from a known parameter set, through
// the same simulation as the fit (calibration/simulation.hpp), then resampled
// the way a person digitises a figure and perturbed by noise. They exist to
// test the calibration against known true values; they are never experimental
// data, and every file written from them says so.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "calibration/simulation.hpp"
#include "calibration/test_curve.hpp"
#include "mortar/parameters.hpp"

namespace mortar::harness {

// One test of a synthetic programme.
struct SyntheticTest {
  TestKind kind = TestKind::shear;
  double sigma_n = 0;               // shear kinds [MPa], < 0
  double travel = 0;                // tension: final opening; shear: final slip [mm]
  std::vector<double> amplitudes;   // cyclic_shear: slip amplitudes [mm], one cycle each, about 0
  std::vector<double> path;         // unloading-reloading: the abscissa's corners after 0 [mm] (then no amplitudes)
  int points = 30;                  // digitised points
  bool uplift = true;               // shear kinds: dilatancy measured
};

// The programme used by the tests and the shipped example: tension to about
// 3 % of ft0, and monotonic shear at sigma_n = -0.1, -0.5, -1.0 MPa to a slip
// that wears the joint out (the elastic slip to the peak, then 4 GIIC/c0),
// with dilatancy.
std::vector<SyntheticTest> standard_programme(const Parameters& p, int points);

// Tests with unloading branches, for bn and bs (calibration/unloading_rules.hpp):
// tension unloaded three times on its softening branch (at 70, 40 and 15 %
// of ft0) to a tenth of the way above its plastic opening and reloaded; and
// shear at a constant tension of ft0/10 unloaded three times after the peak
// (where about 15, 30 and 45 % of the strength is gone) to 0.4 of the slip
// and reloaded, ending at the last unloading's slip, before it separates.
std::vector<SyntheticTest> unloading_programme(const Parameters& p, int points);

// The law's curve, dense (about 600 increments), resampled at `points` points
// equally spaced in arc length on the chart's scaled axes (each axis divided
// by its range, as a figure is drawn), the peak always among them, as a
// digitiser clicks it. Then Gaussian noise of standard deviation
// `noise` x the curve's largest |value| on the ordinate and the uplift
// (noise = 0.02: 2 %). Deterministic for a given seed.
// Compression tests (kind compression, travel a closure) need `cap` on.
TestCurve synthetic_curve(const Parameters& p, const SyntheticTest& test, double noise, std::uint32_t seed,
                          const std::string& name, const CompressionCap& cap = CompressionCap{});

// The curves without the sample at each shear curve's largest tau: a peak
// the test's sampling missed (the coverage study and the fit's tests).
std::vector<TestCurve> without_shear_peaks(std::vector<TestCurve> curves);

}  // namespace mortar::harness
