// The 14 material parameters of the mortar-joint law (paper Table 1) and the
// integration controls that may follow them in the Abaqus props array.
#pragma once

#include <array>
#include <string>

namespace mortar {

// Table 1 of the paper, in its order (= Abaqus props(1..14)). Units N, mm, MPa.
struct Parameters {
  double kn = 0;    // normal stiffness of the undamaged joint      [N/mm^3]  [0.01, 1e6]
  double ks = 0;    // shear stiffness (both tangents)               [N/mm^3]  [0.01, 1e6]
  double ft0 = 0;   // initial tensile strength                      [MPa]     [1e-6, 100]
  double c0 = 0;    // initial cohesion                              [MPa]     [1e-6, 100], > ft0*tan(phi0)
  double GIC = 0;   // mode I fracture energy                        [N/mm]    [1e-9, 100]
  double GIIC = 0;  // mode II fracture energy                       [N/mm]    [1e-9, 100]
  double phi0 = 0;  // initial friction angle                        [deg]     phir <= phi0 < 90
  double phir = 0;  // residual friction angle                       [deg]     0 < phir
  double m = 0;     // decay constant of the friction angle          [mm/N]    [0, 1e7]
  double psi0 = 0;  // initial dilatancy angle                       [deg]     psir <= psi0 < 90
  double psir = 0;  // residual dilatancy angle                      [deg]     >= 0
  double n = 0;     // decay constant of the dilatancy angle         [mm/N]    [0, 1e7]
  double bn = 0;    // crack-to-plastic ratio, normal                [-]       [0, 1000]
  double bs = 0;    // crack-to-plastic ratio, shear                 [-]       [0, 1000]
};

inline constexpr int kParameterCount = 14;

struct ParameterInfo {
  const char* name;
  const char* unit;
  const char* meaning;
};
// Name, unit and meaning of each parameter, in Table 1 order.
extern const std::array<ParameterInfo, kParameterCount> kParameterInfo;

// The range of each parameter on its own, in Table 1 order (docs/model.md 2):
// lo <= x <= hi, with lo excluded when lo_open and hi when hi_open. The
// bounds are physical with room to spare (a mortar joint's stiffness is
// 1-10^4 N/mm^3, its strengths 0.01-10 MPa, its fracture energies
// 1e-4-1 N/mm); beyond them the input is a typo or a unit slip, and the
// law's arithmetic (ft0/kn, c0^2/ft0, exp(-m w)) leaves its tested range.
// The rules between parameters (phir <= phi0, psir <= psi0,
// c0 > ft0*tan(phi0)) come after these in validate().
struct ParameterRange {
  double lo, hi;
  bool lo_open, hi_open;
  const char* rule;  // "0.01 <= kn <= 1e6 N/mm^3"

  // Whether v lies in the range (false for NaN).
  bool holds(double v) const { return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi); }
};
extern const std::array<ParameterRange, kParameterCount> kParameterRange;

// Access by Table 1 position (0-based) so that props arrays and named files
// share one mapping.
double& parameter_at(Parameters& p, int index);
double parameter_at(const Parameters& p, int index);
// Index of a parameter by its name ("kn", "GIC", ...), or -1.
int parameter_index(const std::string& name);

// Stress-integration scheme (docs/model.md 7).
enum class Scheme : int {
  modified_euler = 1,  // Sloan, Abbo & Sheng (2001): Heun pair, error control (default)
  forward_euler = 2,   // one explicit step, no error control (baseline)
  implicit = 3,        // backward Euler return mapping, Newton, consistent tangent (docs/model.md 7.5)
};
const char* scheme_name(Scheme s);

// The default substep budget per increment (props(18) = 0 or absent,
// docs/model.md 9). The libFuzzer build (MJ_FUZZ, tools/fuzz.sh: there
// cmake/sanitizers.cmake defines libFuzzer's conventional
// FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION) runs the same code
// with 10^3, the fuzz target's cap of an explicit props(18): an input with
// nProps < 18 could otherwise spend 10^5 substeps, 2 x 10^5 Newton iterations ...
// The rest: docs/numerics.md, section 3.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
inline constexpr int kDefaultMaxSubsteps = 1000;
#else
inline constexpr int kDefaultMaxSubsteps = 100000;
#endif

// Integration controls; props(15..19) in the Abaqus adapters, 0 there = default.
struct Controls {
  Scheme scheme = Scheme::modified_euler;
  double stol = 1e-5;        // relative local error tolerance of a substep
  double ftol = 1e-8;        // yield-surface tolerance, relative to max(|sigma|, ft0)
  double min_substep = 1e-4; // smallest substep, as a fraction of the increment
                             // (implicit: the smallest plastic substep after halvings)
  int max_substeps = kDefaultMaxSubsteps; // substeps (accepted + rejected) and relaxation steps allowed per increment
};

// The first rule a parameter or control breaks; ok() when none.
struct ValidationError {
  int index = -1;            // 0-based position in the props array, -1 when ok
  const char* name = "";     // parameter or control name
  double value = 0;          // offending value
  const char* rule = "";     // the rule it breaks
  bool argument = false;     // an argument (nProps) rather than a props entry
  bool ok() const { return index < 0; }
  std::string message() const;  // "parameter 'c0' (props(4)) = 0.1 violates ..."
};

// Validates per docs/model.md 2 (parameters) and 7.4 (controls).
// Non-throwing; cheap enough for every call.
ValidationError validate(const Parameters& p);
ValidationError validate(const Controls& c);

// Reads props(1..14) and optional controls from props(15..19). Returns the
// first violation (including too few props); does not throw.
ValidationError read_props(const double* props, int n_props, Parameters& p, Controls& c);

// props(1..19) of a parameter set and its controls, every control written
// out (read_props of them gives p and c back). props(20), the adapters'
// shear-stress sign, is not the law's and is left to the caller.
inline constexpr int kPropsWithControls = kParameterCount + 5;
std::array<double, kPropsWithControls> to_props(const Parameters& p, const Controls& c = Controls{});

// The compression cap (docs/model.md 12; beyond the paper, after Lourenco &
// Rots 1997): props(21..24). fc = 0 (or fewer than 21 props) is no cap, and
// the law is the paper's to the bit. The cap acts on closed joints only; the
// rule fc/3 > sqrt(ft0^2 + Cs c0^2) keeps the initial cap beyond every
// traction the shear-tension surface allows at sigma_n >= 0.
struct CompressionCap {
  double fc = 0;       // compressive strength of the joint          [MPa]   0 (no cap), or [1e-3, 1000]
  double Cs = 0;       // shear share of the cap, sigma_n^2 + Cs tau^2 [-]    [0, 1000]
  double Gfc = 0;      // compressive fracture energy above fc/7     [N/mm]  [1e-6, 1e4], > 481 fc^2/(588 min(kn, Cs ks))
  double kappa_p = 0;  // plastic closure at the peak fc             [mm]    [0, 100]
  bool on() const { return fc > 0; }
};
inline constexpr int kCapFirstProp = 20;  // 0-based position of fc: props(21)
inline constexpr int kCapCount = 4;
struct CapParameterInfo {
  const char* name;
  const char* unit;
  const char* meaning;
  const char* rule;
};
extern const std::array<CapParameterInfo, kCapCount> kCapParameterInfo;
double& cap_parameter_at(CompressionCap& cap, int index);
double cap_parameter_at(const CompressionCap& cap, int index);
// Index of a cap parameter by its name ("fc", "Cs", "Gfc", "kappa_p"), or -1.
int cap_parameter_index(const std::string& name);

// The cap's own ranges and its rules against the joint's parameters p
// (docs/model.md 12); indices are props positions (20..23).
ValidationError validate(const CompressionCap& cap, const Parameters& p);
// Reads props(21..24) when n_props > 20 (else no cap) and validates them
// against p (already validated).
ValidationError read_cap(const double* props, int n_props, const Parameters& p, CompressionCap& cap);

// Parameters plus the values derived from them once (tangents of the angles,
// alpha and beta of the undamaged surface), and the integration controls.
struct Model {
  Parameters p;
  Controls controls;
  double tan_phi0 = 0, tan_phir = 0, tan_psi0 = 0, tan_psir = 0;
  double cohesion_term = 0;  // c0^2 / ft0, so that alpha, beta = s*(C/tanphi -/+ ft0*tanphi)/2
  double alpha0 = 0, beta0 = 0;  // Eq. 3 at s = 1, tanphi = tanphi0
  double stress_scale = 0;       // ft0: reference for tolerances and floors [MPa]
  // Once per model rather than per point-update (the same expressions, so the
  // same values): the floor of boundary_eps, the elastic separation at ft0
  // [mm]; cohesion_term / tan_phi0, the elastic shortcut's C / tan(phi) on an
  // unworn joint (w_III = 0) [MPa].
  double separation_floor = 0;
  double cohesion_over_tan_phi0 = 0;
  // The material length that bounds the smallest substep (min_substep_floor,
  // docs/model.md 7.4) [mm].
  double substep_length = 0;
  // The compression cap (off unless cap.fc > 0) and its initial and residual
  // strengths fc/3, fc/7 (docs/model.md 12) [MPa].
  CompressionCap cap;
  double cap_initial = 0, cap_residual = 0;
  double cap_softening_span = 0;  // kappa_m - kappa_p = 588 Gfc / (481 fc) [mm]
};

// Builds a Model from validated inputs (call validate first). Non-throwing.
Model make_model(const Parameters& p, const Controls& c = Controls{}, const CompressionCap& cap = CompressionCap{});
// Throwing convenience for C++ callers (harness, tests): std::invalid_argument
// with ValidationError::message().
Model make_model_checked(const Parameters& p, const Controls& c = Controls{},
                         const CompressionCap& cap = CompressionCap{});

}  // namespace mortar
