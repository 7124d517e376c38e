// The incremental rotation of the local tangent directions (VUINTERACTION
// dRot(2,2,nBlock), VUINTER drot(2,2,nSlvNod), UINTER DROT(2,2)): checked,
// then applied to the tangential components of the state's vectors before the
// law integrates, so that a joint whose tangent directions turn keeps its
// traction direction (docs/abaqus.md, "Rotating tangent directions").
// The rest: docs/adapters.md, section 5.
#pragma once

#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "adapter/report.hpp"
#include "mortar/state_layout.hpp"

namespace mj_adapter {

// |dRot^T dRot - I| (largest entry) allowed. Abaqus forms dRot from tangent
// directions it computes itself, in single precision in a single-precision
// job, so a legitimate dRot deviates by some 1e-7 to 1e-6; 1e-3 is far above
// that and any accumulated round-off, and far below what a matrix that is not
// a rotation (zeros, a scaled or sheared matrix, a reflection) shows.
constexpr double kRotationTolerance = 1e-3;

// The first rule a dRot breaks, or none (entry < 0 and deviation within).
struct RotationCheck {
  int bad_entry = -1;      // 0..3 column-major: the first entry that is not finite
  double deviation = 0;    // largest |dRot^T dRot - I|
  double determinant = 1;  // a rotation has +1, a reflection -1
  bool ok() const {
    return bad_entry < 0 && deviation <= kRotationTolerance && determinant > 0;
  }
};

template <class Real>
RotationCheck check_rotation(const Real* drot) {
  RotationCheck c;
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(double(drot[i]))) {
      c.bad_entry = i;
      return c;
    }
  const double a = double(drot[0]), b = double(drot[1]), p = double(drot[2]), q = double(drot[3]);
  // dRot^T dRot = [a^2+b^2, a p+b q; a p+b q, p^2+q^2] for dRot = [a p; b q].
  const double off = std::fabs(a * p + b * q);
  c.deviation = std::fmax(std::fmax(std::fabs(a * a + b * b - 1), std::fabs(p * p + q * q - 1)), off);
  c.determinant = a * q - p * b;
  return c;
}

// The sum of dRot's entries' distances from the unit matrix's: 0 exactly
// when each is (a NaN or an infinity makes it NaN or infinite), so that the
// test below is one comparison (it runs on every point-update in 3D), and
// the elastic lanes compare two points' sums at once.
template <class Real>
Real distance_from_identity(const Real* drot) {
  return std::fabs(drot[0] - Real(1)) + std::fabs(drot[1]) + std::fabs(drot[2]) + std::fabs(drot[3] - Real(1));
}
// Exactly the unit matrix: nothing turns, and nothing is touched, so that an
// unrotated analysis stays bit for bit what it was (1*x + 0*y would turn a
// -0 into +0).
template <class Real>
bool is_identity(const Real* drot) {
  return distance_from_identity(drot) == 0;
}

// Brings the tangential components of the state's in-plane vectors (plastic,
// crack and total separation, docs/model.md 3) into the turned tangent
// directions. The normal components and the scalars do not change.
template <class Real>
void rotate_tangential_state(const Real* drot, mortar::State& s) {
  if (is_identity(drot)) return;
  const double a = double(drot[0]), b = double(drot[1]), p = double(drot[2]), q = double(drot[3]);
  for (mortar::Vec3* v : {&s.plastic, &s.crack, &s.separation}) {
    const double s1 = (*v)[1], s2 = (*v)[2];
    (*v)[1] = a * s1 + p * s2;
    (*v)[2] = b * s1 + q * s2;
  }
}

// "argument dRot(1,2,3) = nan (point 3 of 4, slave node 1003) violates the
// rule: ..." : `argument` the routine's spelling, `index` what follows the
// two matrix indices (",3" for a block, "" for UINTER), `where` the point.
template <class Real>
void report_rotation(const Caller& who, const char* argument, const char* index, const char* where,
                     const Real* drot, const RotationCheck& c) {
  char what[480];
  if (c.bad_entry >= 0) {
    std::snprintf(what, sizeof what, "argument %s(%d,%d%s) = %g (%s) violates the rule: every entry finite", argument,
                  c.bad_entry % 2 + 1, c.bad_entry / 2 + 1, index, double(drot[c.bad_entry]), where);
  } else {
    std::snprintf(what, sizeof what,
                  "argument %s(:,:%s) = [%.9g %.9g; %.9g %.9g] (%s) violates the rule: a rotation, "
                  "|%s^T %s - I| <= %g and det > 0 (here %.3g and det %.9g)",
                  argument, index, double(drot[0]), double(drot[2]), double(drot[1]), double(drot[3]), where,
                  argument, argument, kRotationTolerance, c.deviation, c.determinant);
  }
  report(who, what);
}

}  // namespace mj_adapter
