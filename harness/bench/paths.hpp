// The loading paths of the work-precision study (`masonry-joint bench`):
// each is a SEPARATION HISTORY, a piecewise-linear path of the total
// separation (delta_n, delta_s1, delta_s2) in legs between corners, that
// every scheme is then driven along, displacement-controlled. Driving every
// scheme along the same separations means the comparison measures the stress
// integration alone: no mixed-control iteration, whose tolerance and
// predictor would otherwise differ from scheme to scheme, enters the error.
//
// - The paper's test series (van der Pluijm, Atkinson, Almeida): the
//   separations a mixed-control run of the calibration case (its own
//   parameters, program, scheme and STOL) went through, one leg per program
//   step (cycle legs counted separately). For the constant-normal-stress
//   tests that history is the one that held sigma_n at its value. The
//   Atkinson program is cut after its first amplitude's cycles (+/-0.5 mm,
//   twice): its larger cycles repeat the same sliding for 24 more mm.
// - Mixed paths that stress the methods, given directly as corner points
//   (with the van der Pluijm -0.5 MPa parameters), and a cyclic shear with
//   reversals at three normal stresses, again from a mixed-control run.
// - crush: the one path with the compression cap on (docs/model.md 12), the
//   splitting tests' crush family on the same parameters.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "mortar/parameters.hpp"

namespace mortar::harness {

using Vec3 = Eigen::Vector3d;

struct BenchPath {
  std::string id;     // short name used in files and tables ("vdp_sn0.5")
  std::string title;  // one line for charts and the stability list
  Parameters parameters;
  int directions = 3;  // nDir of the calls (2: one slip)
  // Legs of the history; legs[i] is a polyline whose first point is the last
  // point of legs[i-1] (the origin for the first leg).
  std::vector<std::vector<Vec3>> legs;
  CompressionCap cap;  // off (fc = 0) but on the crush path
};

// The separations at the end of the increments of size at most h [mm]
// (Euclidean norm of the separation increment): every leg is divided by arc
// length into the fewest equal parts no longer than h, so corners are always
// hit. Element 0 is the origin (the reference call).
std::vector<Vec3> discretise(const BenchPath& path, double h);

// Total arc length of the history [mm].
double path_length(const BenchPath& path);

// Every bench path in a fixed order, or those named in `ids` in their order
// (each built only when named: most are the history of a mixed-control
// run). `data_dir` is calibration_data/. `quick` leaves out the Atkinson
// cyclic test, whose 28 mm of slip travel dominate the run time (the cyclic
// path at three normal stresses stays). InputError for unreadable data or
// an id that names no path (the message lists the ids); RunFailure if a
// mixed-control run fails.
// The cap of the crush path and of bench --throughput's cap rows for set p,
// the rule of the splitting tests' crush family: Cs = 9, fc = 4 sqrt(ft0^2 +
// Cs c0^2) (the rule: fc/3 above that root), Gfc twice its snap-back bound,
// kappa_p = fc/kn.
CompressionCap crush_cap(const Parameters& p);

std::vector<BenchPath> bench_paths(const std::string& data_dir, bool quick, const std::vector<std::string>& ids = {});

}  // namespace mortar::harness
