// docs/model.md 12: the compression cap, in every scheme. Closed-form checks
// of uniaxial crushing (peak fc at kappa_p, Gfc above the residual after the
// peak), the ellipse under shear beyond the corner, energy closure, and a
// deck without a cap unchanged.
#include <catch2/catch.hpp>

#include <cmath>

#include "formatted.hpp"
#include "paper_sets.hpp"
#include "paths.hpp"
#include "schemes.hpp"

#include "mortar/physics/compression_cap.hpp"

using namespace mortar;
using namespace mortar::testing;

namespace {

// A joint with a cap: van der Pluijm's set (sigma_n = -0.5 MPa) with fc = 12
// MPa, Cs = 9, Gfc = 5 N/mm, kappa_p = 0.05 mm (orders of Lourenco & Rots'
// masonry values; fc/3 = 4 > sqrt(ft0^2 + 9 c0^2) = 2.71).
CompressionCap test_cap() { return {12.0, 9.0, 5.0, 0.05}; }
Model capped_model(Scheme scheme, double stol = 1e-5) {
  Controls c;
  c.scheme = scheme;
  c.stol = stol;
  return make_model_checked(van_der_pluijm(-0.5), c, test_cap());
}

// The closed form of uniaxial crushing, independent of the law's code: the
// strength (docs/model.md 12: parabola to fc at kappa_p, parabola to fc/2 at
// kappa_m, exponential to fc/7, with slopes continuous) and its integral, the
// plastic work.
double span(const CompressionCap& c) { return 588 * c.Gfc / (481 * c.fc); }
double strength(const CompressionCap& c, double k) {
  const double si = c.fc / 3, sm = c.fc / 2, sr = c.fc / 7, km = c.kappa_p + span(c);
  if (k < c.kappa_p) {
    const double x = k / c.kappa_p;
    return si + (c.fc - si) * (2 * x - x * x);
  }
  if (k < km) {
    const double h = (k - c.kappa_p) / span(c);
    return c.fc + (sm - c.fc) * h * h;
  }
  return sr + (sm - sr) * std::exp(-c.fc / span(c) * (k - km) / (sm - sr));
}
double work(const CompressionCap& c, double k) {
  const double si = c.fc / 3, sm = c.fc / 2, sr = c.fc / 7, km = c.kappa_p + span(c);
  const double x = std::min(k, c.kappa_p) / c.kappa_p;
  double w = si * x * c.kappa_p + (c.fc - si) * c.kappa_p * (x * x - x * x * x / 3);
  if (k > c.kappa_p) {
    const double h = (std::min(k, km) - c.kappa_p) / span(c);
    w += span(c) * (c.fc * h + (sm - c.fc) * h * h * h / 3);
  }
  if (k > km) {
    const double tail = (sm - sr) * (sm - sr) / (c.fc / span(c));
    w += sr * (k - km) + tail * (1 - std::exp(-c.fc / span(c) * (k - km) / (sm - sr)));
  }
  return w;
}
// The area between the curve and the residual from the peak to k.
double above_residual(const CompressionCap& c, double k) {
  return work(c, k) - work(c, c.kappa_p) - c.fc / 7 * (k - c.kappa_p);
}

// kappa_c on the uniaxial path at total closure u > 0: u = kappa + strength/kn
// (bisection: the right side increases with kappa while kn > -strength').
double kappa_at(const CompressionCap& c, double kn, double u) {
  double lo = 0, hi = u;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid + strength(c, mid) / kn < u ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("Cap: uniaxial crushing peaks at fc and dissipates Gfc above the residual after the peak", "[cap]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Model M = capped_model(S.scheme, S.closure_stol);
  const CompressionCap c = M.cap;
  const double kn = M.p.kn;
  DisplacementDriver drive(M);
  // To 0.9 of the elastic limit, then 2e-4 mm increments (forward Euler,
  // first order without error control: 2e-6 mm) through the peak and 1 mm
  // of closure (kappa_c to ~2 Gfc/fc past kappa_p, 98.5 % of Gfc dissipated
  // above the residual).
  drive.ramp_to(Vec3(-0.9 * c.fc / 3 / kn, 0, 0), 10);
  const double end = 1.0, du = S.scheme == Scheme::forward_euler ? 2e-6 : 2e-4;
  drive.ramp_to(Vec3(-end, 0, 0), int(end / du));
  const Curve& curve = drive.curve();
  REQUIRE(curve.all_ok);
  double peak = 0, worst = 0;
  for (const Sample& s : curve.samples) {
    peak = std::max(peak, -s.traction[0]);
    const double u = -s.separation[0];
    const double expect = u < c.fc / 3 / kn ? kn * u : strength(c, kappa_at(c, kn, u));
    worst = std::max(worst, std::abs(-s.traction[0] - expect) / c.fc);
  }
  const State& y = drive.state();
  const double k_end = kappa_at(c, kn, end);
  const double booked_above = y.dissipation_plastic - work(c, c.kappa_p) - c.fc / 7 * (y.kappa_c - c.kappa_p);
  INFO(mj_test::formatted("[cap] %s: peak %.6f (fc %.1f), curve error %.2e fc, kappa_c %.6f vs %.6f, "
                          "dissipated above the residual after the peak %.6f (closed form %.6f, Gfc %.1f)",
                          S.name, peak, c.fc, worst, y.kappa_c, k_end, booked_above, above_residual(c, k_end), c.Gfc));
  CHECK(peak == Approx(c.fc).epsilon(1e-4));
  CHECK(worst < 1e-4);
  CHECK(y.kappa_c == Approx(k_end).epsilon(1e-4));
  CHECK(y.dissipation_plastic == Approx(work(c, k_end)).epsilon(1e-4));
  CHECK(booked_above == Approx(above_residual(c, k_end)).epsilon(1e-4));
  // The closed form itself: the whole area above the residual is Gfc.
  CHECK(above_residual(c, c.kappa_p + span(c) + 60 * c.Gfc / c.fc) == Approx(c.Gfc).epsilon(1e-12));
  // No shear flow: the cap's flow under tau = 0 is normal only; no work of Eqs. 7-9.
  CHECK(y.plastic[1] == 0);
  CHECK(y.wI == 0);
  CHECK(y.wII == 0);
  // Energy closure: external work = elastic energy + dissipation.
  CHECK(curve.external_work() == Approx(curve.stored_plus_dissipated(M)).epsilon(S.closure));
}

TEST_CASE("Cap: shear beyond the corner follows the ellipse", "[cap]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  const Model M = capped_model(S.scheme, S.closure_stol);
  const CompressionCap c = M.cap;
  // Pressed to sigma_n = -3.5 MPa (inside the initial cap, fc/3 = 4), then
  // slid at fixed normal separation: the cap is reached before the
  // hyperbola (tau on the cap at -3.5: 0.65 MPa; Coulomb about 3.9 MPa).
  // The cap's flow closes the joint plastically, so sigma_n falls at fixed
  // separation until the hyperbola is met (the corner), after which the
  // point slides on the softening hyperbola, inside the cap.
  DisplacementDriver drive(M);
  drive.ramp_to(Vec3(-3.5 / M.p.kn, 0, 0), 5);
  // 1e5 increments: the trapezoidal external work of this path (a sharp
  // softening after the corner) converges to 1.4e-7 there, 7e-6 at 5e3.
  const int n = 100000;
  drive.ramp(Vec3(0, 0.2, 0.05), n);
  const Curve& curve = drive.curve();
  REQUIRE(curve.all_ok);
  double worst = 0;
  int on_cap = 0;
  auto crushes = [&](size_t i) { return curve.samples[i].state.kappa_c > curve.samples[i - 1].state.kappa_c; };
  for (size_t i = 1; i + 1 < curve.samples.size(); ++i) {
    const Sample& s = curve.samples[i];
    // On the cap at the end of the increment: crushing in it and in the next
    // (the increment that reaches the corner ends on the hyperbola).
    if (!crushes(i) || !crushes(i + 1)) continue;
    ++on_cap;
    const Vec3& t = s.traction;
    const double q = std::sqrt(t[0] * t[0] + c.Cs * (t[1] * t[1] + t[2] * t[2]));
    worst = std::max(worst, std::abs(q - strength(c, s.state.kappa_c)) / c.fc);
  }
  INFO(mj_test::formatted("[cap] %s: %d samples on the cap, ellipse error %.2e fc, end tau %.4f sigma_n %.4f", S.name,
                          on_cap, worst, curve.samples.back().traction[1],
                          curve.samples.back().traction[0]));
  CHECK(on_cap > n / 4);
  CHECK(worst < 1e-4);
  CHECK(drive.state().wII > 0);  // the corner was passed: Eq. 2 flowed
  CHECK(curve.external_work() == Approx(curve.stored_plus_dissipated(M)).epsilon(S.closure));
}

TEST_CASE("Cap: a deck without a cap, or with fc = 0, is the paper's law to the bit", "[cap]") {
  const SchemeUnderTest S = GENERATE(from_range(all_schemes()));
  CAPTURE(S.name);
  Controls ctl;
  ctl.scheme = S.scheme;
  const Model plain = make_model_checked(van_der_pluijm(-0.5), ctl);
  const Model zero = make_model_checked(van_der_pluijm(-0.5), ctl, CompressionCap{0, 9, 5, 0.05});
  DisplacementDriver a(plain), b(zero);
  for (DisplacementDriver* d : {&a, &b}) {
    d->ramp_to(Vec3(-0.02, 0, 0), 4);
    d->ramp(Vec3(0.003, 0.3, -0.1), 60);
    d->ramp(Vec3(0.03, -0.2, 0.1), 60);
  }
  for (size_t i = 0; i < a.curve().samples.size(); ++i) {
    CHECK(a.curve().samples[i].traction == b.curve().samples[i].traction);
    CHECK(a.curve().samples[i].state.plastic == b.curve().samples[i].state.plastic);
  }
}
