#include "mortar/integration/drift_correction.hpp"

#include <cmath>

#include "mortar/integration/rate_statement.hpp"

namespace mortar {

void correct_drift(const Model& M, Point& P, Branches grow) {
  for (int it = 0; it < 8; ++it) {
    const Surface S = surface_of(M, P.y);
    const double F = yield_function(P.sigma, S);
    if (F <= yield_tolerance(M, P.sigma)) return;
    const RateStiffness k = rate_stiffness(M, P.y, grow.normal, grow.shear);
    const Flow f = flow_of(M, P.sigma, S, k.on_flow);
    const Vec3 e0 = P.y.elastic_separation();
    if (f.denominator > 0) {
      Point C = P;
      add(C, along_flow(M, P.sigma, f, F / f.denominator), 1.0);
      settle(M, C, e0, grow);
      if (std::abs(yield_of(M, C)) < F) {
        P = C;
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
    if (!(std::abs(yield_of(M, C)) < F)) return;
    P = C;
  }
}

}  // namespace mortar
