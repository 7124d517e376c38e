// The implicit mock solver (`run --solver implicit`): UINTER driven as
// Abaqus/Standard drives it, Newton on the returned DDSDDR.
//   - quadratic convergence on a plastic softening increment where the
//     consistent tangent is exact (and, as a control that the measure can
//     fail, linear convergence with an explicit scheme's continuum tangent);
//   - the same curve as the explicit solver with the same law scheme, to the
//     traction tolerance;
//   - the modified-Euler curve within the implicit scheme's error control,
//     at the program's increments and at half of them;
//   - PNEWDT honoured: cut-backs leave no trace, their number is bounded;
//   - traction control at a brittle peak with two free components, solved
//     with the secant once Newton's residual rises;
//   - Newton on DDSDDR's symmetric part (no UNSYMM) converging linearly.
// A failed check shows the residual sequences (INFO).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "abi/props.hpp"
#include "commands/run.hpp"
#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "solvers/implicit_run.hpp"
#include "support.hpp"

using namespace mortar;
using namespace mortar::harness;
using namespace mortar::harness::testing;

namespace {

const std::string kVdp = std::string(MJ_CALIBRATION_DATA_DIR) + "/vdp_monotonic_shear/";

struct ImplicitRecord {
  std::vector<Sample> curve;
  std::vector<ResidualSequence> attempts;
  ImplicitStatistics stats;
};

ImplicitRecord run_implicit(const Parameters& p, const Protocol& protocol, const ImplicitSettings& settings) {
  ImplicitRecord r;
  r.stats = run_protocol_implicit(
      p, protocol, settings, [&](int, const Sample& s) { r.curve.push_back(s); }, {},
      [&](const ResidualSequence& a) { r.attempts.push_back(a); });
  return r;
}

// Residuals above this are not round-off: tractions of order 1 MPa carry
// about 1e-16 MPa of it, the law's local solve converges to 1e-12 (relative).
constexpr double kNoiseFloor = 1e-13;

// Estimated order of convergence from the last three residuals above the
// noise floor, log(r_k+1 / r_k) / log(r_k / r_k-1); NaN when there are fewer.
double observed_order(const ResidualSequence& r) {
  std::vector<double> above;
  for (int k = 0; k < r.count; ++k)
    if (r.residual[k] > kNoiseFloor) above.push_back(r.residual[k]);
  const size_t n = above.size();
  if (n < 3) return NAN;
  return std::log(above[n - 1] / above[n - 2]) / std::log(above[n - 2] / above[n - 3]);
}

// Largest r_k+1 / r_k^2 over the iterations after the first with r_k below
// `near` [MPa] (the neighbourhood of the solution) [1/MPa].
double quadratic_constant(const ResidualSequence& r, double near) {
  double c = 0;
  for (int k = 0; k + 1 < r.count; ++k)
    if (r.residual[k] <= near && r.residual[k] > kNoiseFloor)
      c = std::max(c, r.residual[k + 1] / (r.residual[k] * r.residual[k]));
  return c;
}

// The law's own view of increment i of a curve: integrate it again from the
// committed start state with the props UINTER received.
IncrementResult replay(const Parameters& parameters, Scheme scheme, const std::vector<Sample>& curve, size_t i) {
  Parameters p;
  Controls c;
  const std::vector<double> props = props_for(parameters, scheme, 0);
  REQUIRE(read_props(props.data(), static_cast<int>(props.size()), p, c).ok());
  State s;
  load_state(curve[i - 1].state.data(), s);
  Mat3 T;
  return integrate_increment(make_model(p, c), s, curve[i].separation - s.separation, &T);
}

struct CurveDifference {
  double normal = 0, shear = 0;  // max |difference| of sigma_n and of tau_1 [MPa]
  size_t shear_at = 0;
};

// `fine` has `ratio` increments for every increment of `coarse`.
CurveDifference difference(const std::vector<Sample>& coarse, const std::vector<Sample>& fine, size_t ratio = 1) {
  REQUIRE(fine.size() == ratio * (coarse.size() - 1) + 1);
  CurveDifference d;
  for (size_t i = 1; i < coarse.size(); ++i) {
    d.normal = std::max(d.normal, std::abs(coarse[i].traction[0] - fine[ratio * i].traction[0]));
    const double shear = std::abs(coarse[i].traction[1] - fine[ratio * i].traction[1]);
    if (shear > d.shear) d.shear = shear, d.shear_at = i;
  }
  return d;
}

}  // namespace

TEST_CASE("Newton on UINTER's DDSDDR converges quadratically on a plastic softening increment", "[implicit]") {
  // Arrange: sigma_n = -0.5 MPa held by traction control (the free
  // component), slip imposed; the last increment is 1e-2 mm past the peak.
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("implicit_softening.toml"));
  // Act
  const ImplicitRecord implicit = run_implicit(params.values, protocol, ImplicitSettings{});
  // Assert: the increment is plastic, softening, and its tangent is exact.
  const size_t last = implicit.curve.size() - 1;
  const IncrementResult law = replay(params.values, Scheme::implicit, implicit.curve, last);
  REQUIRE(law.status.ok());
  CHECK(law.status.plastic);
  CHECK_FALSE(law.status.tangent_approximate);
  CHECK(implicit.curve[last].traction[1] < implicit.curve[last - 1].traction[1]);  // softening
  const ResidualSequence& r = implicit.attempts.back();
  REQUIRE(r.step == 3);
  INFO("residuals: " << format_residuals(r));
  REQUIRE(r.outcome == AttemptOutcome::converged);
  REQUIRE(r.count >= 3);
  CHECK(r.residual[r.count - 1] <= 1e-9);
  const double order = observed_order(r), c = quadratic_constant(r, 1e-1);
  INFO("observed order " << order << ", max r_k+1/r_k^2 = " << c << " /MPa");
  CHECK(order > 1.8);
  CHECK(c <= 1.0);

  // Control: the same increment with modified Euler, whose tangent is the
  // continuum one of Eq. 20 (not the derivative of its update): linear.
  ImplicitSettings explicit_scheme;
  explicit_scheme.scheme = Scheme::modified_euler;
  explicit_scheme.options.traction_tolerance = 1e-12;  // more iterations to see the rate,
  explicit_scheme.options.max_iterations = 60;         // which is slow at the peak
  const ImplicitRecord control = run_implicit(params.values, protocol, explicit_scheme);
  const ResidualSequence& rc = control.attempts.back();
  INFO("control, modified Euler (continuum tangent), residuals: " << format_residuals(rc));
  CHECK(replay(params.values, Scheme::modified_euler, control.curve, last).status.tangent_approximate);
  CHECK(observed_order(rc) < 1.5);
  CHECK(quadratic_constant(rc, 1e-1) > 1.0);
}

TEST_CASE("The implicit solver shows quadratic convergence in the worst increment of the vdP -0.5 MPa program",
          "[implicit]") {
  const ParameterSet params = read_parameter_file(kVdp + "params_sn0.5.toml");
  const Protocol protocol = read_protocol_file(kVdp + "protocol_sn0.5.toml");
  const ImplicitRecord implicit = run_implicit(params.values, protocol, ImplicitSettings{});
  REQUIRE(implicit.stats.has_worst);
  const ResidualSequence& w = implicit.stats.worst;
  INFO("most iterations: step " << w.step << ", increment " << w.increment << ", residuals: "
                                 << format_residuals(w));
  CHECK(implicit.stats.attempts == implicit.stats.increments);  // no cut-back
  CHECK(implicit.stats.max_traction_residual <= 1e-9);
  CHECK(w.count <= 4);
  CHECK(quadratic_constant(w, 1e-1) <= 100.0);
}

TEST_CASE("Implicit and explicit solvers agree on the vdP -0.5 MPa program with the same law scheme",
          "[implicit]") {
  // Arrange: both solvers run props(15) = 3; the explicit one through
  // vuinteraction_ with a finite-difference Jacobian, the implicit one
  // through uinter_ with DDSDDR. Only their traction solves differ.
  const double tolerance = GENERATE(1e-9, 1e-12);
  CAPTURE(tolerance);
  const ParameterSet params = read_parameter_file(kVdp + "params_sn0.5.toml");
  const Protocol protocol = read_protocol_file(kVdp + "protocol_sn0.5.toml");
  ImplicitSettings implicit_settings;
  implicit_settings.options.traction_tolerance = tolerance;
  RunSettings explicit_settings;
  explicit_settings.scheme = Scheme::implicit;
  explicit_settings.mixed.traction_tolerance = tolerance;
  // Act
  const ImplicitRecord implicit = run_implicit(params.values, protocol, implicit_settings);
  const std::vector<Sample> explicit_curve = run_one_point(params.values, protocol, explicit_settings);
  // Assert: sigma_n is within the tolerance of the same target in both, so
  // within twice it of each other; tau follows from the (slightly different)
  // normal separations, and the difference shrinks with the tolerance.
  const CurveDifference d = difference(implicit.curve, explicit_curve);
  INFO("max |d sigma_n| " << d.normal << ", max |d tau| " << d.shear << " MPa");
  CHECK(d.normal <= 2 * tolerance);
  CHECK(d.shear <= 10 * tolerance);
}

TEST_CASE("The implicit solver reproduces the modified-Euler curve within the implicit scheme's error control",
          "[implicit]") {
  // Arrange: the reference is the explicit solver with modified Euler at
  // STOL 1e-8 (the series' setting; its own error is below 1e-6 MPa: STOL
  // 1e-5 moves it by 7.5e-7 MPa). The implicit scheme's substeps hold its
  // local error to STOL / 10 (docs/model.md 7.5): its error follows STOL, not
  // the increment, and with STOL 1e-7 it falls by about sqrt(100).
  const ParameterSet params = read_parameter_file(kVdp + "params_sn0.5.toml");
  const Protocol protocol = read_protocol_file(kVdp + "protocol_sn0.5.toml");
  Protocol halved = protocol;
  for (ProgramStep& s : halved.steps) s.increments *= 2;
  RunSettings reference_settings;
  reference_settings.stol = 1e-8;
  ImplicitSettings tight;
  tight.stol = 1e-7;
  // Act
  const std::vector<Sample> reference = run_one_point(params.values, protocol, reference_settings);
  const std::vector<Sample> coarse = run_implicit(params.values, protocol, ImplicitSettings{}).curve;
  const std::vector<Sample> fine = run_implicit(params.values, halved, ImplicitSettings{}).curve;
  const std::vector<Sample> tighter = run_implicit(params.values, protocol, tight).curve;
  // Assert
  const CurveDifference e_h = difference(reference, coarse), e_h2 = difference(reference, fine, 2),
                        e_tight = difference(reference, tighter);
  double peak = 0;
  for (const Sample& r : reference) peak = std::max(peak, r.traction[1]);
  const double dissipation = coarse.back().dissipation / reference.back().dissipation - 1;
  INFO("max |d tau| " << e_h.shear << " MPa (" << e_h.shear / peak << " of the peak), halved increments "
                       << e_h2.shear << " MPa, STOL 1e-7 " << e_tight.shear << " MPa; dissipation " << dissipation
                       << " relative");
  CHECK(e_h.shear <= 2e-4 * peak);   // 8.2e-5 of the peak measured (1.1e-4 MPa)
  CHECK(e_h2.shear <= 2e-4 * peak);  // the error control's, not the increment's
  CHECK(e_h.normal <= 2e-9);         // held by traction control in both
  CHECK(e_tight.shear <= 0.2 * e_h.shear);  // sqrt(STOL): 0.1 expected
  CHECK(std::abs(dissipation) <= 5e-4);
}

TEST_CASE("PNEWDT < 1 cuts the increment back and abandoned attempts leave no trace", "[implicit]") {
  // Arrange: a substep budget of one makes the routine reject the large
  // increment (PNEWDT = 0.5) until the sub-increment is small enough.
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("implicit_cut_back.toml"));
  ImplicitSettings budget;
  budget.max_substeps = 1;
  // STOL 0.9: the error control's cuts (docs/model.md 7.5) would spend the
  // budget of one on every piece; this test is about the local solve's.
  budget.stol = 0.9;
  // Act
  const ImplicitRecord cut = run_implicit(params.values, protocol, budget);
  // Assert: cut-backs by the routine, each retried from the same start with
  // PNEWDT times the size; converged pieces follow each other up to the end.
  std::string attempts;
  for (const ResidualSequence& a : cut.attempts)
    attempts += " [" + std::to_string(a.start) + ", " + std::to_string(a.start + a.size) + ") " +
                (a.outcome == AttemptOutcome::converged ? "ok;" : "cut;");
  INFO("attempts (fractions of the increment):" << attempts);
  REQUIRE(cut.stats.cuts_by_routine >= 1);
  REQUIRE(cut.attempts.back().outcome == AttemptOutcome::converged);
  CHECK(cut.attempts.back().start + cut.attempts.back().size == 1.0);
  for (size_t i = 0; i + 1 < cut.attempts.size(); ++i) {
    const ResidualSequence &a = cut.attempts[i], &next = cut.attempts[i + 1];
    if (a.outcome == AttemptOutcome::converged) {
      CHECK(next.start == a.start + a.size);
    } else {
      CHECK(a.outcome == AttemptOutcome::cut_by_routine);
      CHECK(a.pnewdt == 0.5);
      CHECK(next.start == a.start);
      CHECK(next.size == a.size * a.pnewdt);
    }
  }
  // The converged pieces as a program of their own, run without the budget:
  // the same law on the same increments from the same states, so the same
  // end point to the last bit, if the abandoned attempts left nothing behind.
  Protocol pieces = protocol;
  pieces.steps.clear();
  for (const ResidualSequence& a : cut.attempts) {
    if (a.outcome != AttemptOutcome::converged) continue;
    ProgramStep piece = protocol.steps[0];
    const double end = a.start + a.size;
    for (ComponentProgram& c : piece.component) c.target = end >= 1.0 ? c.target : 0.0 + (c.target - 0.0) * end;
    pieces.steps.push_back(piece);
  }
  ImplicitSettings same_law;
  same_law.stol = budget.stol;
  const ImplicitRecord reference = run_implicit(params.values, pieces, same_law);
  CHECK(reference.stats.attempts == static_cast<long>(pieces.steps.size()));  // no cut-back without the budget
  const Sample& a = cut.curve.back();
  const Sample& b = reference.curve.back();
  CHECK(a.separation == b.separation);
  CHECK(a.traction == b.traction);
  CHECK(a.state == b.state);
  CHECK(a.dissipation == Approx(b.dissipation).epsilon(1e-14));

  // Too few cut-backs allowed: a clear failure naming the limit and PNEWDT.
  budget.options.max_cuts = 1;
  try {
    run_implicit(params.values, protocol, budget);
    FAIL("the run should have failed");
  } catch (const RunFailure& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find("after 1 cut-back(s) (at most 1, --max-cuts") != std::string::npos);
    CHECK(what.find("PNEWDT = 0.5") != std::string::npos);
  }
}

TEST_CASE("Traction control at a brittle peak with two free components: the secant across the kink solves it",
          "[implicit]") {
  // Shear along s1 at sigma_n = -0.8 MPa with tau_2 = 0.3 MPa held: at the
  // onset of yield (step 2, increment 183) the free block of DDSDDR (n, s2)
  // has a negative determinant, and Newton on the one-sided tangents cycled
  // between the elastic and the plastic branch in every cut-back piece. Once
  // the residual rises the solver iterates with Broyden's secant update.
  const ParameterSet params = read_parameter_file(data_file("vdp_sn0.5.toml"));
  const Protocol protocol = read_protocol_file(data_file("three_components.toml"));
  const ImplicitRecord implicit = run_implicit(params.values, protocol, ImplicitSettings{});
  RunSettings same_law;
  same_law.scheme = Scheme::implicit;
  const std::vector<Sample> reference = run_one_point(params.values, protocol, same_law);
  // The explicit solver (finite-difference Jacobian, bracketing) with the
  // same law scheme: the same curve to the traction tolerance.
  const CurveDifference d = difference(implicit.curve, reference);
  INFO("max |d sigma_n| " << d.normal << ", max |d tau| " << d.shear << " MPa; attempts "
                          << implicit.stats.attempts << ", most iterations " << implicit.stats.max_iterations);
  CHECK(implicit.stats.cycling == 0);
  CHECK(implicit.stats.max_iterations <= 16);  // 16 measured at the onset, 5 elsewhere
  CHECK(d.normal <= 1e-8);                     // 1.0e-9 measured
  CHECK(d.shear <= 1e-7);                      // 4.8e-9 measured (tau_1 follows the free separations)
}

TEST_CASE("Without UNSYMM (DDSDDR's symmetric part) Newton converges linearly where the full tangent is quadratic",
          "[implicit]") {
  // Two traction-controlled components (sigma_n, tau_2) while s1 slips, in
  // 1e-2 mm increments (docs/abaqus.md, what Standard does with the tangent).
  const ParameterSet params = read_parameter_file(kVdp + "params_sn0.5.toml");
  const Protocol protocol = read_protocol_file(data_file("two_free_components.toml"));
  ImplicitSettings symmetric;
  symmetric.options.symmetric_tangent = true;
  const ImplicitRecord full = run_implicit(params.values, protocol, ImplicitSettings{});
  const ImplicitRecord part = run_implicit(params.values, protocol, symmetric);
  INFO("calls " << full.stats.calls << " / " << part.stats.calls << ", most iterations "
                << full.stats.max_iterations << " / " << part.stats.max_iterations);
  CHECK(full.stats.max_iterations <= 5);  // 5 measured: 2.7e-1 1.4e-2 1.4e-4 3.2e-9 1.3e-14 MPa
  CHECK(part.stats.max_iterations >= 10);  // 15 measured, the residual falling by about 3 per iteration
  CHECK(part.stats.calls >= 2 * full.stats.calls);  // 313 against 119 measured
  // The same law converged to the same tolerance: the same curve.
  REQUIRE(full.curve.size() == part.curve.size());
  for (size_t i = 0; i < full.curve.size(); ++i)
    CHECK((full.curve[i].traction - part.curve[i].traction).norm() <= 1e-8);
}
