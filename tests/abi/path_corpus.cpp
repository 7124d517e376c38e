// The random-path corpus (path_corpus.hpp). Only the routine's argument list
// and the parameters' props order are used, so that the same source drives
// any build of vuinteraction_.
#include "path_corpus.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>

#include "mortar/state_pairs.hpp"
#include "random_parameters.hpp"
#include "vuinteraction.h"

namespace mj_corpus {
namespace {

using Real = mj_real;
using mj_test::log_uniform;
using mj_test::uniform;

constexpr int kPoints = 9;  // odd: pairs of lanes and a tail point
constexpr int kSteps = 64;
constexpr int kSets = 2;     // parameter sets per case

struct Hash {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  template <class T>
  void add(const std::vector<T>& v) {
    const unsigned char* p = reinterpret_cast<const unsigned char*>(v.data());
    for (size_t i = 0; i < v.size() * sizeof(T); ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
};

// One increment of a point: mostly small (elastic) steps, some large ones
// (plastic, softening, opening and closing), in both directions.
void random_step(std::mt19937& rng, const mortar::Parameters& p, double& d_pen, double& s1, double& s2) {
  const double un = p.ft0 / p.kn, us = p.c0 / p.ks;
  auto sign = [&] { return uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0; };
  const double r = uniform(rng, 0, 1);
  if (r < 0.7) {  // small
    d_pen = sign() * log_uniform(rng, 1e-6, 0.05) * un;
    s1 = sign() * log_uniform(rng, 1e-6, 0.05) * us;
    s2 = sign() * log_uniform(rng, 1e-6, 0.05) * us;
  } else if (r < 0.97) {  // towards and over the surface
    d_pen = uniform(rng, -0.6, 0.4) * un;
    s1 = uniform(rng, -0.8, 0.8) * us;
    s2 = uniform(rng, -0.5, 0.5) * us;
  } else {  // large
    d_pen = sign() * log_uniform(rng, 0.1, 20) * un;
    s1 = sign() * log_uniform(rng, 0.1, 20) * us;
    s2 = sign() * log_uniform(rng, 0.01, 5) * us;
  }
}

// Slots holding what the layout never writes (the "-corrupt" cases): before
// every fifth call one point's slot is corrupted, in turn each kind below;
// where the routine then rejects the point (keeping the slot), the slot is
// given back after the call, so that the point goes on.
struct Corruption {
  int point = -1, slot = 0;
  Real value = 0, saved = 0;
};
Corruption corrupt(std::vector<Real>& state, int n_states, int step) {
  namespace slot = mortar::slot;
  Corruption c;
  c.point = (step / 5) % kPoints;
  Real* st = state.data() + size_t(n_states) * c.point;
  const bool flags = n_states >= mortar::kFlaggedStateCount;
  const int flag_slot = mortar::flag_slot::integration_flags;
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  switch ((step / 5) % 8) {
    case 0: c.slot = flags ? flag_slot : int(slot::open), c.value = Real(flags ? 2.5 : 0.5); break;
    case 1: c.slot = flags ? flag_slot : int(slot::initialised), c.value = Real(16); break;
    case 2: c.slot = flags ? flag_slot : int(slot::open), c.value = nan; break;
    case 3: c.slot = flags ? flag_slot : int(slot::status), c.value = Real(5); break;
    case 4: c.slot = slot::open, c.value = Real(0.5); break;
    case 5: c.slot = slot::substeps_accepted, c.value = Real(2.5); break;  // a count's garbage: read as 2
    case 6:
      if (sizeof(Real) == sizeof(float) && n_states >= mortar::kPairedStateCount) {
        // A pair consistent but not canonical (docs/model.md 3): a low part
        // below the double sum's reach, or a -0 high part for a value 0.
        const mortar::SlotPair p = mortar::kPairedSlots[(step / 5) % 11];
        const float high = float(st[p.high]);
        const float spacing = std::nextafter(std::abs(high), HUGE_VALF) - std::abs(high);
        if (high == 0.0f) {
          c.slot = p.high, c.value = Real(-0.0f);
        } else {
          c.slot = p.low, c.value = Real(spacing * std::ldexp(1.0f + std::ldexp(1.0f, -23), -20));
        }
      } else {
        c.slot = slot::status, c.value = Real(1e30);  // the status's garbage: read as 0
      }
      break;
    default: c.slot = slot::reference_penetration, c.value = inf; break;
  }
  c.saved = st[c.slot];
  st[c.slot] = c.value;
  return c;
}
void give_back(std::vector<Real>& state, int n_states, const Corruption& c) {
  Real& x = state[size_t(n_states) * c.point + c.slot];
  if (std::memcmp(&x, &c.value, sizeof x) == 0) x = c.saved;
}

std::uint64_t run_case(int n_dir, int scheme, bool turning, int n_states, unsigned seed, bool corrupted = false) {
  std::mt19937 rng(seed);
  const mortar::Parameters p = mj_test::random_parameters(rng);
  std::vector<Real> props(15);
  for (int i = 0; i < 14; ++i) props[i] = Real(mortar::parameter_at(p, i));
  props[14] = Real(scheme);
  const int n = kPoints, n_props = 15, n_node_states = 1, n_nod_slv = 1, n_nod_mst = 4, n_temp = 0, n_fields = 1;
  const int flags[3] = {1, 1, 0};
  const Real r_data[4] = {0, 0, Real(1e-6), 0};
  const size_t nd = size_t(n_dir);
  std::vector<Real> stress(nd * n), flux_slv(n), flux_mst(n), state(size_t(n_states) * n), sed(n), sfd(n), scd(n),
      spd(n), svd(n), penetration(n), dr_disp(nd * n), d_rot(4 * n), dircos(nd * nd * n), per_point(n),
      dircos_sl(nd * n), shape_slv(n), shape_mst(4 * n), coord_slv(nd * n), coord_mst(4 * nd * n), field(n);
  std::vector<int> slave_nodes(n), master_nodes(4 * n);
  for (int k = 0; k < n; ++k) slave_nodes[k] = 101 + k;
  char name[80];
  std::memset(name, ' ', sizeof name);
  std::memcpy(name, "CORPUS", 6);
  Hash hash;
  for (int step = 0; step < kSteps; ++step) {
    for (int k = 0; k < n; ++k) {
      double d_pen = 0, s1 = 0, s2 = 0;
      if (step > 0) random_step(rng, p, d_pen, s1, s2);
      // Point 8 leaves the opposite surface now and then (not integrated).
      const bool unpaired = k == 8 && step % 13 == 7;
      if (k == 8 && step % 13 == 8) penetration[k] = Real(0);
      if (!unpaired && penetration[k] < Real(-1e29)) penetration[k] = Real(0);
      penetration[k] = unpaired ? Real(-2e30) : Real(double(penetration[k]) + d_pen);
      dr_disp[nd * k] = Real(-d_pen);
      dr_disp[nd * k + 1] = Real(s1);
      if (n_dir == 3) dr_disp[nd * k + 2] = Real(s2);
      const double angle = turning && uniform(rng, 0, 1) < 0.5 ? uniform(rng, -0.05, 0.05) : 0.0;
      d_rot[4 * k] = d_rot[4 * k + 3] = Real(std::cos(angle));
      d_rot[4 * k + 1] = Real(std::sin(angle));
      d_rot[4 * k + 2] = Real(-std::sin(angle));
    }
    Corruption c;
    if (corrupted && step % 5 == 3) c = corrupt(state, n_states, step);
    vuinteraction_(stress.data(), flux_slv.data(), flux_mst.data(), state.data(), sed.data(), sfd.data(), scd.data(),
                   spd.data(), svd.data(), &n, &n, &n, &n_node_states, &n_nod_slv, &n_nod_mst, &n_dir, &n_states,
                   &n_props, &n_temp, &n_fields, flags, r_data, name, name, name, slave_nodes.data(),
                   master_nodes.data(), props.data(), penetration.data(), dr_disp.data(), d_rot.data(),
                   dircos.data(), per_point.data(), per_point.data(), per_point.data(), dircos_sl.data(),
                   shape_slv.data(), shape_mst.data(), coord_slv.data(), coord_mst.data(), coord_slv.data(),
                   coord_mst.data(), per_point.data(), per_point.data(), field.data(), field.data(), 80, 80, 80);
    if (c.point >= 0) give_back(state, n_states, c);
    hash.add(stress);
    hash.add(state);
    hash.add(sed);
    hash.add(spd);
    hash.add(sfd);
    hash.add(scd);
    hash.add(svd);
    hash.add(flux_slv);
    hash.add(flux_mst);
  }
  return hash.h;
}

}  // namespace

std::vector<CaseHash> run_corpus() {
  const bool single = sizeof(Real) == sizeof(float);
  const std::vector<int> layouts = single ? std::vector<int>{34, 35, 23} : std::vector<int>{23, 35};
  std::vector<CaseHash> out;
  unsigned seed = 1;
  for (int n_dir : {2, 3})
    for (int scheme : {1, 2, 3})
      for (bool turning : {false, true}) {
        if (turning && n_dir == 2) continue;  // a 2D joint has nothing to turn
        for (int n_states : layouts)
          for (int set = 0; set < kSets; ++set) {
            std::ostringstream name;
            name << "dir" << n_dir << "-scheme" << scheme << "-turn" << turning << "-depvar" << n_states << "-set"
                 << set;
            out.push_back({name.str(), run_case(n_dir, scheme, turning, n_states, 7919u * seed++)});
          }
      }
  for (int n_dir : {2, 3})
    for (int n_states : layouts) {
      std::ostringstream name;
      name << "dir" << n_dir << "-corrupt-depvar" << n_states;
      out.push_back({name.str(), run_case(n_dir, 1, n_dir == 3, n_states, 7919u * seed++, true)});
    }
  return out;
}

bool write_hashes(const std::vector<CaseHash>& hashes, const std::string& path) {
  std::ofstream f(path);
  for (const CaseHash& c : hashes) f << c.name << ' ' << std::hex << c.hash << std::dec << '\n';
  return bool(f);
}

std::vector<std::string> compare_hashes(const std::vector<CaseHash>& hashes, const std::string& path) {
  std::ifstream f(path);
  if (!f) return {"cannot read " + path};
  std::map<std::string, std::uint64_t> expected;
  std::string name;
  std::uint64_t h;
  while (f >> name >> std::hex >> h >> std::dec) expected[name] = h;
  std::vector<std::string> differ;
  for (const CaseHash& c : hashes) {
    const auto it = expected.find(c.name);
    if (it == expected.end() || it->second != c.hash) differ.push_back(c.name);
    if (it != expected.end()) expected.erase(it);
  }
  for (const auto& e : expected) differ.push_back(e.first + " (missing)");
  return differ;
}

}  // namespace mj_corpus
