#include "mortar/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mortar {

const std::array<ParameterInfo, kParameterCount> kParameterInfo = {{
    {"kn", "N/mm^3", "normal stiffness of the undamaged joint"},
    {"ks", "N/mm^3", "shear stiffness (both tangents)"},
    {"ft0", "MPa", "initial tensile strength"},
    {"c0", "MPa", "initial cohesion"},
    {"GIC", "N/mm", "mode I fracture energy"},
    {"GIIC", "N/mm", "mode II fracture energy"},
    {"phi0", "deg", "initial friction angle"},
    {"phir", "deg", "residual friction angle"},
    {"m", "mm/N", "decay constant of the friction angle"},
    {"psi0", "deg", "initial dilatancy angle"},
    {"psir", "deg", "residual dilatancy angle"},
    {"n", "mm/N", "decay constant of the dilatancy angle"},
    {"bn", "-", "crack-to-plastic ratio, normal"},
    {"bs", "-", "crack-to-plastic ratio, shear"},
}};

const std::array<ParameterRange, kParameterCount> kParameterRange = {{
    {0.01, 1e6, false, false, "0.01 <= kn <= 1e6 N/mm^3"},
    {0.01, 1e6, false, false, "0.01 <= ks <= 1e6 N/mm^3"},
    {1e-6, 100, false, false, "1e-6 <= ft0 <= 100 MPa"},
    {1e-6, 100, false, false, "1e-6 <= c0 <= 100 MPa"},
    {1e-9, 100, false, false, "1e-9 <= GIC <= 100 N/mm"},
    {1e-9, 100, false, false, "1e-9 <= GIIC <= 100 N/mm"},
    {0, 90, true, true, "0 < phi0 < 90 degrees"},
    {0, 90, true, true, "0 < phir < 90 degrees"},
    {0, 1e7, false, false, "0 <= m <= 1e7 mm/N"},
    {0, 90, false, true, "0 <= psi0 < 90 degrees"},
    {0, 90, false, true, "0 <= psir < 90 degrees"},
    {0, 1e7, false, false, "0 <= n <= 1e7 mm/N"},
    {0, 1000, false, false, "0 <= bn <= 1000"},
    {0, 1000, false, false, "0 <= bs <= 1000"},
}};

namespace {
double* slot(Parameters& p, int i) {
  double* table[kParameterCount] = {&p.kn,   &p.ks,   &p.ft0, &p.c0,   &p.GIC,
                                    &p.GIIC, &p.phi0, &p.phir, &p.m,   &p.psi0,
                                    &p.psir, &p.n,    &p.bn,  &p.bs};
  return (i >= 0 && i < kParameterCount) ? table[i] : nullptr;
}

constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr const char* kSchemeRule =
    "scheme is 1 (modified Euler), 2 (forward Euler) or 3 (implicit, backward Euler)";

ValidationError fail(int index, const char* name, double value, const char* rule) {
  return ValidationError{index, name, value, rule};
}
ValidationError fail(int index, double value, const char* rule) {
  return fail(index, kParameterInfo[index].name, value, rule);
}
}  // namespace

double& parameter_at(Parameters& p, int index) {
  double* s = slot(p, index);
  if (!s) throw std::out_of_range("parameter index out of range");
  return *s;
}
double parameter_at(const Parameters& p, int index) {
  return parameter_at(const_cast<Parameters&>(p), index);
}
int parameter_index(const std::string& name) {
  for (int i = 0; i < kParameterCount; ++i)
    if (name == kParameterInfo[i].name) return i;
  return -1;
}

const char* scheme_name(Scheme s) {
  switch (s) {
    case Scheme::modified_euler: return "modified-euler";
    case Scheme::forward_euler: return "forward-euler";
    case Scheme::implicit: return "backward-euler";
  }
  return "unknown";
}

std::string ValidationError::message() const {
  if (ok()) return "valid";
  char buf[320];
  if (argument) {
    std::snprintf(buf, sizeof buf, "argument '%s' = %.9g violates the rule: %s", name, value, rule);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "'%s' (props(%d)) = %.9g violates the rule: %s", name,
                index + 1, value, rule);
  return buf;
}

ValidationError validate(const Parameters& p) {
  // Every value must be a finite number before any rule can be read.
  for (int i = 0; i < kParameterCount; ++i) {
    double v = parameter_at(p, i);
    if (!std::isfinite(v)) return fail(i, v, "must be a finite number");
  }
  for (int i = 0; i < kParameterCount; ++i) {
    const double v = parameter_at(p, i);
    const ParameterRange& r = kParameterRange[i];
    if (!r.holds(v)) return fail(i, v, r.rule);
  }
  if (!(p.phir <= p.phi0)) return fail(7, p.phir, "phir <= phi0");
  if (!(p.psir <= p.psi0)) return fail(10, p.psir, "psir <= psi0");
  // Eq. 3 needs beta > alpha >= 0, i.e. c0^2 >= (ft0 tan phi)^2 for every
  // tan phi in [tan phir, tan phi0]; strictness keeps the hyperbola proper.
  if (!(p.c0 > p.ft0 * std::tan(p.phi0 * kDegree)))
    return fail(3, p.c0, "c0 > ft0*tan(phi0), without which the hyperbola of Eq. 2-3 does not exist");
  return {};
}

ValidationError validate(const Controls& c) {
  int s = static_cast<int>(c.scheme);
  if (s != 1 && s != 2 && s != 3) return fail(14, "scheme", s, kSchemeRule);
  if (!(c.stol > 0 && c.stol < 1)) return fail(15, "stol", c.stol, "0 < STOL < 1");
  if (!(c.ftol > 0 && c.ftol < 1)) return fail(16, "ftol", c.ftol, "0 < FTOL < 1");
  if (!(c.max_substeps >= 1)) return fail(17, "max_substeps", c.max_substeps, "max substeps >= 1");
  if (!(c.min_substep > 0 && c.min_substep <= 1))
    return fail(18, "min_substep", c.min_substep, "0 < minimum substep <= 1");
  return {};
}

ValidationError read_props(const double* props, int n_props, Parameters& p, Controls& c) {
  if (n_props < kParameterCount || props == nullptr) {
    ValidationError e = fail(0, "nProps", n_props, "nProps >= 14 (the 14 parameters of Table 1)");
    e.argument = true;
    return e;
  }
  for (int i = 0; i < kParameterCount; ++i) parameter_at(p, i) = props[i];
  ValidationError e = validate(p);
  if (!e.ok()) return e;
  c = Controls{};
  // Optional controls: props(15) scheme, (16) STOL, (17) FTOL, (18) max
  // substeps, (19) minimum substep. A zero keeps the default.
  auto opt = [&](int i) { return i < n_props ? props[i] : 0.0; };
  for (int i = kParameterCount; i < n_props && i < 19; ++i)
    if (!std::isfinite(props[i])) return fail(i, "control", props[i], "must be a finite number");
  if (double v = opt(14); v != 0) {
    if (v != 1 && v != 2 && v != 3) return fail(14, "scheme", v, kSchemeRule);
    c.scheme = static_cast<Scheme>(static_cast<int>(v));
  }
  if (double v = opt(15); v != 0) c.stol = v;
  if (double v = opt(16); v != 0) c.ftol = v;
  if (double v = opt(17); v != 0) {
    if (v != std::floor(v) || !(v >= 1 && v <= 1e9))
      return fail(17, "max_substeps", v, "a whole number in [1, 1e9]");
    c.max_substeps = static_cast<int>(v);
  }
  if (double v = opt(18); v != 0) c.min_substep = v;
  return validate(c);
}

std::array<double, kPropsWithControls> to_props(const Parameters& p, const Controls& c) {
  std::array<double, kPropsWithControls> props{};
  for (int i = 0; i < kParameterCount; ++i) props[i] = parameter_at(p, i);
  props[14] = static_cast<double>(static_cast<int>(c.scheme));
  props[15] = c.stol;
  props[16] = c.ftol;
  props[17] = c.max_substeps;
  props[18] = c.min_substep;
  return props;
}

Model make_model(const Parameters& p, const Controls& c, const CompressionCap& cap) {
  Model m;
  m.cap = cap;
  m.cap_initial = cap.fc / 3;
  m.cap_residual = cap.fc / 7;
  m.cap_softening_span = cap.on() ? 588 * cap.Gfc / (481 * cap.fc) : 0.0;
  m.p = p;
  m.controls = c;
  m.tan_phi0 = std::tan(p.phi0 * kDegree);
  m.tan_phir = std::tan(p.phir * kDegree);
  m.tan_psi0 = std::tan(p.psi0 * kDegree);
  m.tan_psir = std::tan(p.psir * kDegree);
  m.cohesion_term = p.c0 * p.c0 / p.ft0;
  m.alpha0 = 0.5 * (m.cohesion_term / m.tan_phi0 - p.ft0 * m.tan_phi0);
  m.beta0 = 0.5 * (m.cohesion_term / m.tan_phi0 + p.ft0 * m.tan_phi0);
  m.stress_scale = p.ft0;
  m.separation_floor = p.ft0 / p.kn;
  // The shorter of the elastic separation at ft0 and the mode-I softening
  // length: what a substep at the floor must resolve (docs/model.md 7.4).
  m.substep_length = std::min(m.separation_floor, p.GIC / p.ft0);
  m.cohesion_over_tan_phi0 = m.cohesion_term / m.tan_phi0;
  return m;
}

Model make_model_checked(const Parameters& p, const Controls& c, const CompressionCap& cap) {
  ValidationError e = validate(p);
  if (e.ok()) e = validate(c);
  if (e.ok()) e = validate(cap, p);
  if (!e.ok()) throw std::invalid_argument(e.message());
  return make_model(p, c, cap);
}

const std::array<CapParameterInfo, kCapCount> kCapParameterInfo = {{
    {"fc", "MPa", "compressive strength of the joint (0: no cap)", "fc = 0 (no cap) or 1e-3 <= fc <= 1000 MPa"},
    {"Cs", "-", "shear share of the cap, sigma_n^2 + Cs tau^2", "0 <= Cs <= 1000"},
    {"Gfc", "N/mm", "compressive fracture energy above the residual fc/7", "1e-6 <= Gfc <= 1e4 N/mm"},
    {"kappa_p", "mm", "plastic closure at the peak fc", "0 <= kappa_p <= 100 mm"},
}};

double& cap_parameter_at(CompressionCap& cap, int index) {
  double* table[kCapCount] = {&cap.fc, &cap.Cs, &cap.Gfc, &cap.kappa_p};
  if (index < 0 || index >= kCapCount) throw std::out_of_range("cap parameter index out of range");
  return *table[index];
}
double cap_parameter_at(const CompressionCap& cap, int index) {
  return cap_parameter_at(const_cast<CompressionCap&>(cap), index);
}
int cap_parameter_index(const std::string& name) {
  for (int i = 0; i < kCapCount; ++i)
    if (name == kCapParameterInfo[i].name) return i;
  return -1;
}

ValidationError validate(const CompressionCap& cap, const Parameters& p) {
  auto bad = [](int i, double v, const char* rule) { return fail(kCapFirstProp + i, kCapParameterInfo[i].name, v, rule); };
  for (int i = 0; i < kCapCount; ++i)
    if (!std::isfinite(cap_parameter_at(cap, i))) return bad(i, cap_parameter_at(cap, i), "must be a finite number");
  if (cap.fc == 0) return {};
  if (!(cap.fc >= 1e-3 && cap.fc <= 1000)) return bad(0, cap.fc, kCapParameterInfo[0].rule);
  if (!(cap.Cs >= 0 && cap.Cs <= 1000)) return bad(1, cap.Cs, kCapParameterInfo[1].rule);
  if (!(cap.Gfc >= 1e-6 && cap.Gfc <= 1e4)) return bad(2, cap.Gfc, kCapParameterInfo[2].rule);
  if (!(cap.kappa_p >= 0 && cap.kappa_p <= 100)) return bad(3, cap.kappa_p, kCapParameterInfo[3].rule);
  // The initial cap (fc/3) contains every traction of the shear-tension
  // surface at sigma_n >= 0 (|sigma_n| <= ft0, |tau| <= c0): it meets the
  // hyperbola under compression (docs/model.md 12).
  const double reach = std::sqrt(p.ft0 * p.ft0 + cap.Cs * p.c0 * p.c0);
  if (!(cap.fc / 3 > reach))
    return bad(0, cap.fc,
               "fc/3 > sqrt(ft0^2 + Cs c0^2): the initial cap must lie beyond the shear-tension surface at "
               "sigma_n >= 0, so that the two meet under compression");
  // No snap-back on the cap: its steepest softening, fc / (kappa_m -
  // kappa_p) = 481 fc^2 / (588 Gfc) at kappa_m, below the smallest stiffness
  // along its flow, min(kn, Cs ks).
  const double slope = 481 * cap.fc * cap.fc / (588 * cap.Gfc);
  const double stiff = cap.Cs > 0 ? std::min(p.kn, cap.Cs * p.ks) : p.kn;
  if (!(slope < stiff))
    return bad(2, cap.Gfc,
               "Gfc > 481 fc^2 / (588 min(kn, Cs ks)): crushing must soften more slowly than the joint unloads "
               "(no snap-back of the point)");
  return {};
}

ValidationError read_cap(const double* props, int n_props, const Parameters& p, CompressionCap& cap) {
  cap = CompressionCap{};
  if (n_props <= kCapFirstProp || props == nullptr) return {};
  for (int i = 0; i < kCapCount; ++i)
    cap_parameter_at(cap, i) = kCapFirstProp + i < n_props ? props[kCapFirstProp + i] : 0.0;
  return validate(cap, p);
}

}  // namespace mortar
