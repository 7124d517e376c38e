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
#include <cstdio>
#include <sstream>
#include <string>

#include "mortar/state_layout.hpp"
#include "compare_support.hpp"

namespace {

using namespace mj_abi_compare;
namespace slot = mortar::slot;

// Abaqus/Explicit: props(15) = 0 is modified Euler, props(20) = 0 is -1.
constexpr ProductDefaults kExplicitDefaults = {mortar::Scheme::modified_euler, -1.0};

// One recorded call of one point (field order as abi_caller's `record`).
struct Record {
  std::string tag;
  int step = 0, point = 0, n_dir = 0;
  double penetration = 0, dd[3] = {}, start[kStates] = {};
  double stress[3] = {}, sed = 0, spd = 0, sfd = 0, scd = 0, svd = 0, flux_slv = 0, flux_mst = 0;
  double end[kStates] = {};
};

struct Expected {
  double stress[3] = {}, sed = 0, spd = 0, end[kStates] = {};
};

bool read_record(const std::string& line, Record& r) {
  std::istringstream in(line);
  in >> r.tag >> r.step >> r.point >> r.n_dir >> r.penetration;
  read_values(in, r.dd);
  read_values(in, r.start);
  read_values(in, r.stress);
  in >> r.sed >> r.spd >> r.sfd >> r.scd >> r.svd >> r.flux_slv >> r.flux_mst;
  read_values(in, r.end);
  return bool(in);
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
  explicit Comparison(bool single) : agreement_(single ? 2.0 * 0x1p-23 : 1e-12, single) {}

  void compare(const RunSetup& setup, const Record& r) {
    const Expected e = expected_call(setup, r);
    const mortar::Parameters& p = setup.model.p;
    agreement_.check_each(r, "stress(%d)", r.stress, e.stress, 3, [&](int) { return p.ft0; });
    agreement_.check(r, "sed", r.sed, e.sed, p.GIC);
    agreement_.check(r, "spd", r.spd, e.spd, p.GIC);
    for (double zero : {r.sfd, r.scd, r.svd, r.flux_slv, r.flux_mst})
      agreement_.check(r, "sfd/scd/svd/flux", zero, 0.0, 0.0);
    agreement_.check_each(r, "SDV %d", r.end, e.end, kStates, [&](int i) { return state_scale(i, p); });
    ++records_;
    if (r.spd > 0) ++dissipating_;
    if (r.end[slot::damage_n] > 0.99) ++separated_;
    if (r.stress[1] != 0 && r.end[slot::damage_s] > 0) ++sheared_;
  }

  int finish() const {
    std::printf("%d records, %ld values compared, %ld mismatches, worst deviation %.3g of the tolerance "
                "(rtol %.3g)\n", records_, agreement_.values(), agreement_.mismatches(), agreement_.worst(),
                agreement_.rtol());
    std::printf("%d records dissipated energy, %d had d_n > 0.99, %d carried shear with d_s > 0\n", dissipating_,
                separated_, sheared_);
    const bool exercised = records_ == 4 * 8 * 81 && dissipating_ > 0 && separated_ > 0 && sheared_ > 0;
    if (!exercised) std::printf("the records do not cover the expected runs and regimes\n");
    return (agreement_.mismatches() == 0 && exercised) ? 0 : 1;
  }

 private:
  Agreement agreement_;
  int records_ = 0, dissipating_ = 0, separated_ = 0, sheared_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: abi_compare <records-file> <single|double>\n");
    return 2;
  }
  Comparison cmp(std::string(argv[2]) == "single");
  const int rc = replay_records<Record>("abi_compare", argv[1], kExplicitDefaults, read_record,
                                        [&](const RunSetup& setup, const Record& r) { cmp.compare(setup, r); });
  return rc != 0 ? rc : cmp.finish();
}
