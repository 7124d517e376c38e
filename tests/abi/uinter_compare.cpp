// Recomputes every converged UINTER call that uinter_caller (the Fortran
// caller) recorded, with the law library and the mapping of docs/abaqus.md
// ("Using it in Abaqus/Standard") written out independently here, and
// compares STRESS, DDSDDR, STATEV and the energies with what the adapter
// returned. Each call is checked on its own (the recorded start state is the
// input). Double precision throughout: agreement to 1e-12 relative, with an
// absolute floor of the same relative size times the scale of the quantity.
//
// Usage: uinter_compare <records-file>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mortar/integrator.hpp"

namespace {

constexpr int kStates = mortar::kStateCount;
namespace slot = mortar::slot;

struct Record {
  std::string tag;
  int step = 0, point = 0, n_dir = 0;
  double rdisp[3] = {}, drdisp[3] = {}, start[kStates] = {};
  double stress[3] = {}, ddsddr[9] = {}, sed = 0, spd = 0, sfd = 0, svd = 0, scd = 0, pnewdt = 0;
  double end[kStates] = {};
};

struct RunSetup {
  mortar::Model model;
  double shear_sign = 1;
};

bool read_record(const std::string& line, Record& r) {
  std::istringstream in(line);
  in >> r.tag >> r.step >> r.point >> r.n_dir;
  for (double& v : r.rdisp) in >> v;
  for (double& v : r.drdisp) in >> v;
  for (double& v : r.start) in >> v;
  for (double& v : r.stress) in >> v;
  for (double& v : r.ddsddr) in >> v;
  in >> r.sed >> r.spd >> r.sfd >> r.svd >> r.scd >> r.pnewdt;
  for (double& v : r.end) in >> v;
  return bool(in);
}

// UINTER's defaults: props(15) = 0 -> implicit, props(20) = 0 -> +1.
bool read_setup(const std::string& line, std::string& tag, RunSetup& setup) {
  std::istringstream in(line);
  std::string word;
  int n = 0;
  in >> word >> tag >> n;
  std::vector<double> props(n);
  for (double& v : props) in >> v;
  if (!in) return false;
  mortar::Parameters p;
  mortar::Controls c;
  if (!mortar::read_props(props.data(), std::min(n, 19), p, c).ok()) return false;
  if (n < 15 || props[14] == 0) c.scheme = mortar::Scheme::implicit;
  setup.model = mortar::make_model(p, c);
  setup.shear_sign = (n >= 20 && props[19] != 0) ? props[19] : 1.0;
  return true;
}

struct Expected {
  double stress[3] = {}, ddsddr[9] = {}, sed = 0, spd = 0, end[kStates] = {};
};

// The documented mapping from scratch: reference = RDISP(1) - DRDISP(1) at
// the first call; delta_n = reference - RDISP(1); slips = RDISP(2..);
// STRESS = (-sigma_n, s tau); DDSDDR(i,j) = C_i T_ij D_j with C = (-1, s, s),
// D = (-1, 1, 1).
Expected expected_call(const RunSetup& setup, const Record& r) {
  mortar::State s;
  mortar::load_state(r.start, s);
  const bool first = r.start[slot::initialised] == 0;
  const double reference = first ? r.rdisp[0] - r.drdisp[0] : r.start[slot::reference_penetration];
  const mortar::Vec3 d((reference - r.rdisp[0]) - s.separation[0], r.rdisp[1] - s.separation[1],
                       r.n_dir == 3 ? r.rdisp[2] - s.separation[2] : 0.0);
  mortar::Mat3 T;
  const mortar::IncrementResult res = mortar::integrate_increment(setup.model, s, d, &T);
  Expected e;
  std::copy(r.start, r.start + kStates, e.end);
  mortar::store_state(s, e.end);
  if (first && res.status.ok()) {
    e.end[slot::reference_penetration] = reference;
    e.end[slot::initialised] = 1;
  }
  const double C[3] = {-1, setup.shear_sign, setup.shear_sign}, D[3] = {-1, 1, 1};
  for (int i = 0; i < r.n_dir; ++i) {
    e.stress[i] = C[i] * res.traction[i];
    for (int j = 0; j < r.n_dir; ++j) e.ddsddr[i + 3 * j] = C[i] * T(i, j) * D[j];
  }
  e.sed = res.elastic_energy;
  e.spd = res.d_dissipation_plastic + res.d_dissipation_damage + res.d_energy_unilateral;
  return e;
}

class Comparison {
 public:
  void check(const Record& r, const char* what, double got, double expected, double scale) {
    const double tol = 1e-12 * (std::abs(expected) + scale);
    const double dev = std::abs(got - expected);
    worst_ = std::max(worst_, dev / tol);
    ++values_;
    if (dev <= tol) return;
    if (++mismatches_ <= 20)
      std::printf("MISMATCH %s step %d point %d %s: got %.17g expected %.17g\n", r.tag.c_str(), r.step, r.point,
                  what, got, expected);
  }

  void compare(const RunSetup& setup, const Record& r) {
    const Expected e = expected_call(setup, r);
    const mortar::Parameters& p = setup.model.p;
    char name[40];
    for (int i = 0; i < 3; ++i) {
      std::snprintf(name, sizeof name, "STRESS(%d)", i + 1);
      check(r, name, r.stress[i], e.stress[i], p.ft0);
    }
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        std::snprintf(name, sizeof name, "DDSDDR(%d,%d)", i + 1, j + 1);
        check(r, name, r.ddsddr[i + 3 * j], e.ddsddr[i + 3 * j], p.kn);
      }
    check(r, "SED", r.sed, e.sed, p.GIC);
    check(r, "SPD", r.spd, e.spd, p.GIC);
    for (double zero : {r.sfd, r.svd, r.scd}) check(r, "SFD/SVD/SCD", zero, 0.0, 0.0);
    for (int i = 0; i < kStates; ++i) {
      std::snprintf(name, sizeof name, "SDV %d", i + 1);
      check(r, name, r.end[i], e.end[i], 1e-3);
    }
    ++records_;
    if (r.spd > 0) ++dissipating_;
    if (r.end[slot::damage_n] > 0.9) ++damaged_;
    if (r.end[slot::damage_s] > 0 && r.stress[1] != 0) ++sheared_;
    // Plastic increments carry a tangent that is not the secant (off-diagonal terms).
    if (std::abs(r.ddsddr[3]) > 0 || std::abs(r.ddsddr[1]) > 0) ++coupled_;
  }

  int finish() const {
    std::printf("%d records, %ld values compared, %ld mismatches, worst deviation %.3g of the tolerance\n", records_,
                values_, mismatches_, worst_);
    std::printf("%d records dissipated energy, %d had d_n > 0.9, %d carried shear with d_s > 0, %d had a coupled "
                "tangent\n",
                dissipating_, damaged_, sheared_, coupled_);
    const bool exercised = records_ == 3 * 6 * 40 && dissipating_ > 0 && damaged_ > 0 && sheared_ > 0 && coupled_ > 0;
    if (!exercised) std::printf("the records do not cover the expected runs and regimes\n");
    return (mismatches_ == 0 && exercised) ? 0 : 1;
  }

 private:
  double worst_ = 0;
  long values_ = 0, mismatches_ = 0;
  int records_ = 0, dissipating_ = 0, damaged_ = 0, sheared_ = 0, coupled_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: uinter_compare <records-file>\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "uinter_compare: cannot read %s\n", argv[1]);
    return 2;
  }
  Comparison cmp;
  std::map<std::string, RunSetup> setups;
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, 5, "PROPS") == 0) {
      std::string tag;
      RunSetup s;
      if (!read_setup(line, tag, s)) {
        std::fprintf(stderr, "uinter_compare: bad props line: %s\n", line.c_str());
        return 1;
      }
      setups[tag] = s;
      continue;
    }
    Record r;
    if (!read_record(line, r) || !setups.count(r.tag)) {
      std::fprintf(stderr, "uinter_compare: bad record: %s\n", line.c_str());
      return 1;
    }
    cmp.compare(setups[r.tag], r);
  }
  return cmp.finish();
}
