#include "mortar/integration/drift_correction.hpp"

#include <cmath>

#include "mortar/integration/rate_statement.hpp"

namespace mortar {

void correct_drift(const Model& M, Point& P, Branches grow) {
  SurfaceAt at = surface_at(M, P);
  correct_drift(M, P, at, grow);
}

// Each candidate's surface is evaluated once: it decides whether the
// candidate is taken, and a taken one is the next iterate.
void correct_drift(const Model& M, Point& P, SurfaceAt& at, Branches grow) {
  double F = yield_of(P, at);
  for (int it = 0; it < 8; ++it) {
    if (F <= yield_tolerance(M, P.sigma)) return;
    with_psi(M, at.S, P.y.wIII);
    const RateStiffness k = rate_stiffness(M, P.y, grow.normal, grow.shear);
    const Flow f = flow_of(M, P.sigma, at.S, k.on_flow, at.radius);
    const Vec3 e0 = P.y.elastic_separation();
    if (f.denominator > 0) {
      Point C = P;
      add(C, along_flow(M, P.sigma, f, F / f.denominator), 1.0);
      settle(M, C, e0, grow);
      const SurfaceAt at_C = surface_at(M, C);
      const double FC = yield_of(C, at_C);
      if (std::abs(FC) < F) {
        P = C;
        at = at_C;
        F = FC;
        continue;
      }
    }
    const double nn = f.dF.squaredNorm();
    if (!(nn > 0)) return;
    // The stiffness of each component's branch; a fully damaged one (0)
    // takes its growing-branch value, as its traction is 0 after settle().
    const double h = P.y.open ? 1.0 : 0.0;
    const Vec3 k_grow(M.p.kn * (1 + h * M.p.bn), M.p.ks * (1 + h * M.p.bs), M.p.ks * (1 + h * M.p.bs));
    const Vec3 kA = (k.on_flow.array() > 0).select(k.on_flow, k_grow);
    Point C = P;
    const Vec3 dp = (F / nn) * f.dF.cwiseQuotient(kA);
    C.y.plastic += dp;
    C.y.crack += crack_ratio(M).cwiseProduct(dp);
    C.y.dissipation_plastic += P.sigma.dot(dp);
    C.sigma -= (F / nn) * f.dF;
    settle(M, C, e0, grow);
    const SurfaceAt at_C = surface_at(M, C);
    const double FC = yield_of(C, at_C);
    if (!(std::abs(FC) < F)) return;
    P = C;
    at = at_C;
    F = FC;
  }
}

}  // namespace mortar
