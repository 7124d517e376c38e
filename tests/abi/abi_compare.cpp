// Recomputes every call that abi_caller (the Fortran caller) recorded, with
// the law library and the mapping documented in docs/abaqus.md written out
// independently here, and compares with what the adapter returned.
//
// Usage: abi_compare <records-file> <single|double>
//
// Each call is checked on its own: the recorded start state is the input, so
// a deviation points at the call where it arises. The adapter runs the law in
// double precision in both builds, so the expected values, rounded to the
// build's precision, should be reproduced to round-off: 1e-12 relative in
// double, two float ulps in single, each with an absolute floor of the same
// relative size times the scale of the quantity (stress ft0, energy GIC,
// displacement ft0/kn).
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

// One recorded call of one point (field order as abi_caller's `record`).
struct Record {
  std::string tag;
  int step = 0, point = 0, n_dir = 0;
  double penetration = 0, dd[3] = {}, start[kStates] = {};
  double stress[3] = {}, sed = 0, spd = 0, sfd = 0, scd = 0, svd = 0, flux_slv = 0, flux_mst = 0;
  double end[kStates] = {};
};

struct RunSetup {
  mortar::Model model;
  double shear_sign = -1;
};

struct Expected {
  double stress[3] = {}, sed = 0, spd = 0, end[kStates] = {};
};

bool read_record(const std::string& line, Record& r) {
  std::istringstream in(line);
  in >> r.tag >> r.step >> r.point >> r.n_dir >> r.penetration;
  for (double& v : r.dd) in >> v;
  for (double& v : r.start) in >> v;
  for (double& v : r.stress) in >> v;
  in >> r.sed >> r.spd >> r.sfd >> r.scd >> r.svd >> r.flux_slv >> r.flux_mst;
  for (double& v : r.end) in >> v;
  return bool(in);
}

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
  setup.model = mortar::make_model(p, c);
  setup.shear_sign = (n >= 20 && props[19] != 0) ? props[19] : -1.0;
  return true;
}

// The documented mapping, from scratch: the first call (SDV 23 = 0) stores the
// penetration as reference and integrates nothing; later calls integrate
// delta_n = reference - penetration and the slips drDisp(2..nDir).
Expected expected_call(const RunSetup& setup, const Record& r) {
  mortar::State s;
  mortar::load_state(r.start, s);
  const bool first = r.start[slot::initialised] == 0;
  mortar::Vec3 d = mortar::Vec3::Zero();
  if (!first) {
    d[0] = (r.start[slot::reference_penetration] - r.penetration) - s.separation[0];
    d[1] = r.dd[1];
    d[2] = r.n_dir == 3 ? r.dd[2] : 0.0;
  }
  const mortar::IncrementResult res = mortar::integrate_increment(setup.model, s, d);
  Expected e;
  std::copy(r.start, r.start + kStates, e.end);
  mortar::store_state(s, e.end);
  if (first && res.status.ok()) {
    e.end[slot::reference_penetration] = r.penetration;
    e.end[slot::initialised] = 1;
  }
  e.stress[0] = -res.traction[0];
  for (int i = 1; i < r.n_dir; ++i) e.stress[i] = setup.shear_sign * res.traction[i];
  e.sed = res.elastic_energy;
  e.spd = res.d_dissipation_plastic + res.d_dissipation_damage + res.d_energy_unilateral;
  return e;
}

// Scale of each state variable, for the absolute part of the tolerance.
double state_scale(int i, const mortar::Parameters& p) {
  const double displacement = p.ft0 / p.kn;
  switch (i) {
    case slot::work_I: case slot::work_II: case slot::work_III:
    case slot::dissipation_plastic: case slot::dissipation_damage: case slot::energy_unilateral:
      return p.GIC;
    case slot::damage_n: case slot::damage_s: case slot::open: case slot::substeps_accepted:
    case slot::substeps_rejected: case slot::status: case slot::initialised:
      return 1;
    default:
      return displacement;
  }
}

class Comparison {
 public:
  explicit Comparison(bool single) : single_(single), rtol_(single ? 2.0 * 0x1p-23 : 1e-12) {}

  // Compares one value; `scale` sets the absolute floor.
  void check(const Record& r, const char* what, double got, double expected, double scale) {
    if (single_) expected = double(float(expected));
    const double tol = rtol_ * (std::abs(expected) + scale);
    const double dev = std::abs(got - expected);
    worst_ = std::max(worst_, dev / tol);
    ++values_;
    if (dev <= tol) return;
    if (++mismatches_ <= 20)
      std::printf("MISMATCH %s step %d point %d %s: got %.17g expected %.17g\n", r.tag.c_str(), r.step, r.point,
                  what, got, expected);
  }
  void check_exact(const Record& r, const char* what, double got, double expected) {
    check(r, what, got, expected, 0.0);
  }

  void compare(const RunSetup& setup, const Record& r) {
    const Expected e = expected_call(setup, r);
    const mortar::Parameters& p = setup.model.p;
    char name[32];
    for (int i = 0; i < 3; ++i) {
      std::snprintf(name, sizeof name, "stress(%d)", i + 1);
      check(r, name, r.stress[i], e.stress[i], p.ft0);
    }
    check(r, "sed", r.sed, e.sed, p.GIC);
    check(r, "spd", r.spd, e.spd, p.GIC);
    for (double zero : {r.sfd, r.scd, r.svd, r.flux_slv, r.flux_mst}) check_exact(r, "sfd/scd/svd/flux", zero, 0.0);
    for (int i = 0; i < kStates; ++i) {
      std::snprintf(name, sizeof name, "SDV %d", i + 1);
      check(r, name, r.end[i], e.end[i], state_scale(i, p));
    }
    ++records_;
    if (r.spd > 0) ++dissipating_;
    if (r.end[slot::damage_n] > 0.99) ++separated_;
    if (r.stress[1] != 0 && r.end[slot::damage_s] > 0) ++sheared_;
  }

  int finish() const {
    std::printf("%d records, %ld values compared, %ld mismatches, worst deviation %.3g of the tolerance "
                "(rtol %.3g)\n", records_, values_, mismatches_, worst_, rtol_);
    std::printf("%d records dissipated energy, %d had d_n > 0.99, %d carried shear with d_s > 0\n", dissipating_,
                separated_, sheared_);
    const bool exercised = records_ == 4 * 8 * 81 && dissipating_ > 0 && separated_ > 0 && sheared_ > 0;
    if (!exercised) std::printf("the records do not cover the expected runs and regimes\n");
    return (mismatches_ == 0 && exercised) ? 0 : 1;
  }

 private:
  bool single_;
  double rtol_;
  double worst_ = 0;
  long values_ = 0, mismatches_ = 0;
  int records_ = 0, dissipating_ = 0, separated_ = 0, sheared_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: abi_compare <records-file> <single|double>\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "abi_compare: cannot read %s\n", argv[1]);
    return 2;
  }
  Comparison cmp(std::string(argv[2]) == "single");
  std::map<std::string, RunSetup> setups;
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, 5, "PROPS") == 0) {
      std::string tag;
      RunSetup s;
      if (!read_setup(line, tag, s)) {
        std::fprintf(stderr, "abi_compare: bad props line: %s\n", line.c_str());
        return 1;
      }
      setups[tag] = s;
      continue;
    }
    Record r;
    if (!read_record(line, r) || !setups.count(r.tag)) {
      std::fprintf(stderr, "abi_compare: bad record: %s\n", line.c_str());
      return 1;
    }
    cmp.compare(setups[r.tag], r);
  }
  return cmp.finish();
}
