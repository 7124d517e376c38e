// Recomputes every converged UINTER call that uinter_caller (the Fortran
// caller) recorded, with the law library and the mapping of docs/abaqus.md
// ("Using it in Abaqus/Standard") written out independently here, and
// compares STRESS, DDSDDR, STATEV and the energies with what the adapter
// returned. Each call is checked on its own (the recorded start state is the
// input). Double precision throughout: agreement to 1e-12 relative, with an
// absolute floor of the same relative size times the scale of the quantity.
//
// Usage: uinter_compare <records-file>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "mortar/state_layout.hpp"
#include "compare_support.hpp"

namespace {

using namespace mj_abi_compare;
namespace slot = mortar::slot;

// UINTER's defaults: props(15) = 0 -> implicit, props(20) = 0 -> +1.
constexpr ProductDefaults kStandardDefaults = {mortar::Scheme::implicit, 1.0};

struct Record {
  std::string tag;
  int step = 0, point = 0, n_dir = 0;
  double rdisp[3] = {}, drdisp[3] = {}, start[kStates] = {};
  double stress[3] = {}, ddsddr[9] = {}, sed = 0, spd = 0, sfd = 0, svd = 0, scd = 0, pnewdt = 0;
  double end[kStates] = {};
};

bool read_record(const std::string& line, Record& r) {
  std::istringstream in(line);
  in >> r.tag >> r.step >> r.point >> r.n_dir;
  read_values(in, r.rdisp);
  read_values(in, r.drdisp);
  read_values(in, r.start);
  read_values(in, r.stress);
  read_values(in, r.ddsddr);
  in >> r.sed >> r.spd >> r.sfd >> r.svd >> r.scd >> r.pnewdt;
  read_values(in, r.end);
  return bool(in);
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
  void compare(const RunSetup& setup, const Record& r) {
    const Expected e = expected_call(setup, r);
    const mortar::Parameters& p = setup.model.p;
    agreement_.check_each(r, "STRESS(%d)", r.stress, e.stress, 3, [&](int) { return p.ft0; });
    char name[40];
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        std::snprintf(name, sizeof name, "DDSDDR(%d,%d)", i + 1, j + 1);
        agreement_.check(r, name, r.ddsddr[i + 3 * j], e.ddsddr[i + 3 * j], p.kn);
      }
    agreement_.check(r, "SED", r.sed, e.sed, p.GIC);
    agreement_.check(r, "SPD", r.spd, e.spd, p.GIC);
    for (double zero : {r.sfd, r.svd, r.scd}) agreement_.check(r, "SFD/SVD/SCD", zero, 0.0, 0.0);
    agreement_.check_each(r, "SDV %d", r.end, e.end, kStates, [](int) { return 1e-3; });
    ++records_;
    if (r.spd > 0) ++dissipating_;
    if (r.end[slot::damage_n] > 0.9) ++damaged_;
    if (r.end[slot::damage_s] > 0 && r.stress[1] != 0) ++sheared_;
    // Plastic increments carry a tangent that is not the secant (off-diagonal terms).
    if (std::abs(r.ddsddr[3]) > 0 || std::abs(r.ddsddr[1]) > 0) ++coupled_;
  }

  int finish() const {
    std::printf("%d records, %ld values compared, %ld mismatches, worst deviation %.3g of the tolerance\n", records_,
                agreement_.values(), agreement_.mismatches(), agreement_.worst());
    std::printf("%d records dissipated energy, %d had d_n > 0.9, %d carried shear with d_s > 0, %d had a coupled "
                "tangent\n",
                dissipating_, damaged_, sheared_, coupled_);
    const bool exercised = records_ == 3 * 6 * 40 && dissipating_ > 0 && damaged_ > 0 && sheared_ > 0 && coupled_ > 0;
    if (!exercised) std::printf("the records do not cover the expected runs and regimes\n");
    return (agreement_.mismatches() == 0 && exercised) ? 0 : 1;
  }

 private:
  Agreement agreement_{1e-12, false};
  int records_ = 0, dissipating_ = 0, damaged_ = 0, sheared_ = 0, coupled_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: uinter_compare <records-file>\n");
    return 2;
  }
  Comparison cmp;
  const int rc = replay_records<Record>("uinter_compare", argv[1], kStandardDefaults, read_record,
                                        [&](const RunSetup& setup, const Record& r) { cmp.compare(setup, r); });
  return rc != 0 ? rc : cmp.finish();
}
