// Measurement, not a test: what the law's small values (s_sep = kSeparated,
// the normal completion threshold kNormalComplete, the normal-flow blend
// width s ft0) set at engineering scale (docs/model.md 6, Decision - no
// tolerance as a material parameter). For three representative paths it
// prints the reclosing contact point delta_p_n, the contact pressure at
// delta_n = 0, the shear after sliding closed and the energies booked, each
// with the path's peak traction, so that two builds (or two values of a
// constant) can be compared relative to that peak. The tolerance table of
// docs/model.md 6 is this program's output at the values x10 and /10.
//
// Paths (modified Euler, default controls, increments of 1e-4 mm):
//   m15_open   Almeida M15 opened in mode I to 0.2 mm and 0.5 mm (normal
//              completion near 0.109 mm), closed to delta_n = 0 and pressed
//              on to -1e-3 mm;
//   rocking    the bench's rocking toe on van der Pluijm -0.5 MPa: opened to
//              40, 15, 30 softening lengths, closed to delta_n = 0, slid
//              under the contact pressure, three times;
//   worn_open  van der Pluijm -0.5 MPa slid 0.3 mm under 0.5 MPa (worn),
//              opened to 0.05 mm while sliding on, closed to delta_n = 0,
//              slid again;
//   cap        the bench's cap_reversal on van der Pluijm -0.5 MPa (opening
//              to 6 softening lengths, the slip zig-zagging), closed to
//              delta_n = 0 and slid;
//   slide_open van der Pluijm -0.5 MPa opened to 0.05 mm, then opened and
//              slid together to (0.3, 0.1) mm, past complete separation,
//              closed to delta_n = 0, slid back by 0.05 mm.
//
// Usage: tolerance_table   (one line per quantity: path, name, value)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "mortar/integrator.hpp"
#include "mortar/state_layout.hpp"
#include "paper_sets.hpp"

using mortar::Model;
using mortar::Parameters;
using mortar::State;
using mortar::Vec3;

namespace {

struct Drive {
  const Model& M;
  State s;
  double peak = 0;
  long failures = 0;
  int worst_substeps = 0;
  explicit Drive(const Model& m) : M(m) {}
  // Straight to `to` in increments of at most h; the traction at the end.
  Vec3 to(const Vec3& target, double h = 1e-4) {
    const Vec3 d = target - s.separation;
    const int n = std::max(1, int(std::ceil(d.norm() / h - 1e-9)));
    Vec3 t = Vec3::Zero();
    for (int i = 0; i < n; ++i) {
      const mortar::IncrementResult r = mortar::integrate_increment(M, s, d / n);
      failures += !r.status.ok();
      worst_substeps = std::max(worst_substeps, s.substeps_accepted + s.substeps_rejected);
      t = r.traction;
      peak = std::max(peak, t.norm());
    }
    return t;
  }
  double dissipated() const { return s.dissipation_plastic + s.dissipation_damage; }
};

void line(const std::string& path, const std::string& name, double v) {
  std::printf("%-10s %-22s %.12e\n", path.c_str(), name.c_str(), v);
}

void footer(const std::string& path, const Drive& d) {
  line(path, "dissipated", d.dissipated());
  line(path, "D_plastic", d.s.dissipation_plastic);
  line(path, "E_unilateral", d.s.energy_unilateral);
  line(path, "wI", d.s.wI);
  line(path, "wII", d.s.wII);
  line(path, "peak", d.peak);
  line(path, "failures", double(d.failures));
  line(path, "worst_substeps", d.worst_substeps);
}

void m15_open(double reach) {
  const Model M = mortar::testing::model_with(mortar::testing::almeida_m15(), mortar::Scheme::modified_euler);
  const std::string path = "m15_" + std::to_string(int(std::lround(reach * 10))) + "dmm";
  Drive d(M);
  d.to(Vec3(reach, 0, 0));
  const double D_open = d.dissipated(), peak_open = d.peak;
  const Vec3 at_zero = d.to(Vec3(0, 0, 0));
  line(path, "contact_dp_n", d.s.plastic[0]);
  line(path, "sigma_n_at_0", at_zero[0]);
  line(path, "D_at_max_opening", D_open);
  d.to(Vec3(-1e-3, 0, 0));
  footer(path, d);
  line(path, "peak_opening", peak_open);
}

// bench/paths.cpp, rocking_legs.
void rocking() {
  const Parameters p = mortar::testing::van_der_pluijm(-0.5);
  const Model M = mortar::testing::model_with(p, mortar::Scheme::modified_euler);
  const double u = p.GIC / p.ft0;
  Drive d(M);
  double slip = 0;
  int k = 0;
  for (const auto& [opening, next_slip] : {std::pair{40.0, 0.04}, {15.0, -0.02}, {30.0, 0.03}}) {
    d.to(Vec3(opening * u, slip, 0));
    const Vec3 closed = d.to(Vec3(0, slip, 0));
    const std::string c = std::to_string(++k);
    line("rocking", "contact_dp_n_" + c, d.s.plastic[0]);
    line("rocking", "sigma_n_at_0_" + c, closed[0]);
    const Vec3 slid = d.to(Vec3(0, next_slip, 0));
    line("rocking", "tau_slid_" + c, slid[1]);
    line("rocking", "sigma_n_slid_" + c, slid[0]);
    slip = next_slip;
  }
  footer("rocking", d);
}

void worn_open() {
  const Parameters p = mortar::testing::van_der_pluijm(-0.5);
  const Model M = mortar::testing::model_with(p, mortar::Scheme::modified_euler);
  const double dc = -0.5 / p.kn;
  Drive d(M);
  d.to(Vec3(dc, 0, 0));
  d.to(Vec3(dc, 0.3, 0));
  const Vec3 open = d.to(Vec3(0.05, 0.35, 0));
  line("worn_open", "sigma_n_open", open[0]);
  line("worn_open", "tau_open", open[1]);
  line("worn_open", "dn_open", d.s.dn);
  const Vec3 closed = d.to(Vec3(0, 0.35, 0));
  line("worn_open", "contact_dp_n", d.s.plastic[0]);
  line("worn_open", "sigma_n_at_0", closed[0]);
  line("worn_open", "tau_at_0", closed[1]);
  const Vec3 slid = d.to(Vec3(0, 0.4, 0));
  line("worn_open", "tau_slid", slid[1]);
  line("worn_open", "sigma_n_slid", slid[0]);
  footer("worn_open", d);
}

// bench/paths.cpp, cap_reversal_legs, then closed to delta_n = 0 and slid:
// opening and softening on the tension cap with the slip reversing, where
// the normal flow runs through its blend (0 < sigma_n < s ft0).
void cap() {
  const Parameters p = mortar::testing::van_der_pluijm(-0.5);
  const Model M = mortar::testing::model_with(p, mortar::Scheme::modified_euler);
  const double u = p.GIC / p.ft0;
  Drive d(M);
  for (int k = 1; k <= 8; ++k) {
    const double opening = 6.0 * u * k / 8;
    const Vec3 t = d.to(Vec3(opening, (k % 2 ? 0.1 : -0.1) * opening, 0));
    line("cap", "tau_corner_" + std::to_string(k), t[1]);
    line("cap", "sigma_n_corner_" + std::to_string(k), t[0]);
  }
  line("cap", "dp_n_open", d.s.plastic[0]);
  const double slip = d.s.separation[1];
  const Vec3 closed = d.to(Vec3(0, slip, 0));
  line("cap", "contact_dp_n", d.s.plastic[0]);
  line("cap", "sigma_n_at_0", closed[0]);
  const Vec3 slid = d.to(Vec3(0, slip + 0.02, 0));
  line("cap", "tau_slid", slid[1]);
  footer("cap", d);
}

// Opening, then opening and sliding together past complete separation, on
// van der Pluijm -0.5 MPa, closed to delta_n = 0 and slid back: where the
// joint separates sets the plastic slip frozen with it (docs/model.md 6).
void slide_open() {
  const Parameters p = mortar::testing::van_der_pluijm(-0.5);
  const Model M = mortar::testing::model_with(p, mortar::Scheme::modified_euler);
  Drive d(M);
  d.to(Vec3(0.05, 0, 0));
  d.to(Vec3(0.3, 0.1, 0));
  line("slide_open", "dp_s_open", d.s.plastic[1]);
  line("slide_open", "ds_open", d.s.ds);
  line("slide_open", "dn_open", d.s.dn);
  line("slide_open", "wII_open", d.s.wII);
  line("slide_open", "D_open", d.dissipated());
  const Vec3 closed = d.to(Vec3(0, 0.1, 0));
  line("slide_open", "contact_dp_n", d.s.plastic[0]);
  line("slide_open", "sigma_n_at_0", closed[0]);
  line("slide_open", "tau_at_0", closed[1]);
  line("slide_open", "dp_s_closed", d.s.plastic[1]);
  const Vec3 slid = d.to(Vec3(0, 0.05, 0));
  line("slide_open", "tau_back", slid[1]);
  footer("slide_open", d);
}

}  // namespace

int main() {
  m15_open(0.2);
  m15_open(0.5);
  rocking();
  worn_open();
  cap();
  slide_open();
  return 0;
}
