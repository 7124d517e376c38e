// Properties of vuinteraction_ with the compression cap on (docs/model.md 12),
// in both precisions (property_tests, property_tests_single): random valid
// parameter sets, each with a random valid cap (the rules of
// validate(cap, p)), DEPVAR 36 (double) / 37 (single), random paths that
// mix the path families of abi_block.hpp with steps scaled to the cap
// (pressing to and past fc/3, sliding under that pressure). After every call:
//   - no point rejected, everything finite;
//   - damage in [0, 1], damage, wI, wIII (SDV 7, 9) and kappa_c never
//     decreasing. wII (SDV 8) is counted, not asserted: Eq. 8's factor
//     |tau| - <-sigma_n> tan(phi) is zero on the fully softened cone and
//     takes either sign within FTOL of it, where crushed joints spend long
//     (docs/robustness.md, the capped property row);
//   - on or inside Eq. 2 within 10 x FTOL (the schemes with a drift
//     correction) and, for a traction in compression (a closed joint: the
//     cap holds closed joints only), on or inside the cap within 10 x FTOL;
//   - energy closure within the trapezoid's bound (modest increments).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "abi_block.hpp"
#include "formatted.hpp"

using namespace mj_property;

namespace {

// A random cap valid for p: Cs in [0.5, 20], fc 1.05-5 times the bound of
// fc/3 > sqrt(ft0^2 + Cs c0^2), Gfc 1.05-10 times its snap-back bound,
// kappa_p 0 or up to 3 fc/kn.
mortar::CompressionCap random_cap(std::mt19937& rng, const mortar::Parameters& p) {
  for (;;) {
    mortar::CompressionCap c;
    c.Cs = log_uniform(rng, 0.5, 20);
    c.fc = 3 * std::sqrt(p.ft0 * p.ft0 + c.Cs * p.c0 * p.c0) * log_uniform(rng, 1.05, 5);
    c.Gfc = 481 * c.fc * c.fc / (588 * std::min(p.kn, c.Cs * p.ks)) * log_uniform(rng, 1.05, 10);
    c.kappa_p = uniform(rng, 0, 1) < 0.2 ? 0.0 : log_uniform(rng, 0.01, 3) * c.fc / p.kn;
    if (mortar::validate(c, p).ok()) return c;
  }
}

// The cap's strength (docs/model.md 12), written out here from the doc.
double strength(const mortar::Model& M, double k) {
  const mortar::CompressionCap& c = M.cap;
  const double si = c.fc / 3, sm = c.fc / 2, sr = c.fc / 7, span = M.cap_softening_span, km = c.kappa_p + span;
  if (k < c.kappa_p) {
    const double x = k / c.kappa_p;
    return si + (c.fc - si) * (2 * x - x * x);
  }
  if (k < km) return c.fc + (sm - c.fc) * ((k - c.kappa_p) / span) * ((k - c.kappa_p) / span);
  return sr + (sm - sr) * std::exp(2 * (sm - c.fc) / span * (k - km) / (sm - sr));
}

inline double kappa_of(const double* a) { return mortar::load_kappa_c(a); }
inline double kappa_of(const float* a) {
  bool canonical = true;
  return mortar::load_kappa_c_pair(a, canonical);
}

std::vector<Real> capped_props(const mortar::Parameters& p, mortar::Scheme scheme, const mortar::CompressionCap& c) {
  std::vector<Real> props = props_of(p, scheme);
  props.resize(mortar::kCapFirstProp + mortar::kCapCount, Real(0));
  if (scheme != mortar::Scheme::modified_euler) props[14] = Real(static_cast<int>(scheme));
  for (int i = 0; i < mortar::kCapCount; ++i) props[size_t(mortar::kCapFirstProp + i)] = Real(cap_parameter_at(c, i));
  return props;
}

struct Tally {
  long paths = 0, crushed = 0, increments = 0, rejected = 0, non_finite = 0, damage = 0, works = 0, kappa = 0,
       off_surface = 0, off_cap = 0, beyond_bound = 0, wII_decreased = 0;
  double worst_yield = -1e300, worst_cap = -1e300, worst_vs_bound = 0;
};

// One block of 16 random paths of `increments` increments for set p and cap c.
void run_set(const mortar::Parameters& p, const mortar::CompressionCap& c, mortar::Scheme scheme, int n_dir,
             int increments, bool modest, std::mt19937& rng, Tally& t) {
  const int points = 16;
  const std::vector<Real> props = capped_props(p, scheme, c);
  std::vector<double> d(props.begin(), props.end());
  mortar::Parameters pr;
  mortar::Controls ct;
  mortar::CompressionCap cr;
  REQUIRE(mortar::read_props(d.data(), int(d.size()), pr, ct).ok());
  REQUIRE(mortar::read_cap(d.data(), int(d.size()), pr, cr).ok());
  const mortar::Model M = mortar::make_model(pr, ct, cr);
  Block b(points, n_dir, props, kCappedStates);
  std::vector<int> family(points);
  for (int k = 0; k < points; ++k) family[k] = int(rng() % 7);
  b.call();  // the reference
  EnergyBooks books(points);
  std::vector<double> kappa(points, 0.0);
  const double uc = c.fc / p.kn, usc = c.fc / (std::sqrt(c.Cs) * p.ks), f = modest ? 0.1 : 1.0;
  for (int i = 0; i < increments; ++i) {
    std::vector<mortar::Vec3> sigma_old(points), d_sep(points);
    std::vector<mortar::State> old(points);
    for (int k = 0; k < points; ++k) {
      sigma_old[k] = law_traction(b, k);
      old[k] = law_state(b, k);
      // Families 5, 6: pressing towards and past the cap (a bias to pressing),
      // sliding under that pressure.
      Step s = family[k] < 5 ? random_step(rng, p, family[k], modest)
                             : Step{f * uniform(rng, -0.1, family[k] == 5 ? 0.4 : 0.15) * uc,
                                    f * uniform(rng, -0.5, 0.6) * usc, f * uniform(rng, -0.3, 0.3) * usc};
      if (n_dir == 2) s.slip2 = 0;
      d_sep[k] = apply(b, k, s);
    }
    b.call();
    t.increments += points;
    for (int k = 0; k < points; ++k) {
      const Real* st = b.state_of(k);
      t.rejected += st[slot::status] != 0;
      t.non_finite += !(all_finite(st, kCappedStates) && all_finite(b.stress_of(k), size_t(n_dir)) &&
                        std::isfinite(b.sed[k]) && std::isfinite(b.spd[k]));
      const mortar::State s = law_state(b, k);
      const double kc = kappa_of(st);
      t.damage += !(s.dn >= old[k].dn && s.ds >= old[k].ds && s.dn <= 1 && s.ds <= 1);
      t.works += !(s.wI >= old[k].wI && s.wIII >= old[k].wIII);
      t.wII_decreased += !(s.wII >= old[k].wII);
      t.kappa += !(kc >= kappa[k] && kc >= 0);
      kappa[k] = kc;
      const mortar::Vec3 sigma = law_traction(b, k);
      if (scheme != mortar::Scheme::forward_euler) {
        mortar::State sc = s;
        sc.kappa_c = kc;
        const mortar::Vec3 start = kSingle ? mortar::traction_of(M, sc) : sigma;
        const double ry = mortar::yield_ratio(M, sc, start);
        t.worst_yield = std::max(t.worst_yield, ry);
        t.off_surface += ry > 10;
        if (!s.open && start[0] < 0) {  // closed and pressed: the cap holds
          const double q = std::sqrt(start[0] * start[0] + c.Cs * (start[1] * start[1] + start[2] * start[2]));
          const double rc = (q - strength(M, kc)) / (M.controls.ftol * std::max(start.norm(), p.ft0));
          t.worst_cap = std::max(t.worst_cap, rc);
          t.off_cap += rc > 10;
        }
      }
      books.add(k, sigma_old[k], sigma, d_sep[k]);
    }
  }
  for (int k = 0; k < points; ++k) {
    const double vs = books.vs_bound(b, k);
    t.worst_vs_bound = std::max(t.worst_vs_bound, vs);
    t.beyond_bound += vs > 1;
    t.crushed += kappa[k] > 0;
    ++t.paths;
  }
}

std::string summary(const Tally& t) {
  return mj_test::formatted(
      "%ld paths (%ld crushed), %ld point-increments; rejected %ld, non-finite %ld, damage %ld, wI/wIII %ld, wII "
      "decreased %ld, kappa_c "
      "%ld, off Eq. 2 %ld (worst F/FTOL %g), off the cap %ld (worst F_c/FTOL %g), closure beyond the trapezoid "
      "bound %ld (worst %g)",
      t.paths, t.crushed, t.increments, t.rejected, t.non_finite, t.damage, t.works, t.wII_decreased, t.kappa, t.off_surface,
      t.worst_yield, t.off_cap, t.worst_cap, t.beyond_bound, t.worst_vs_bound);
}

void check(const Tally& t, int sets, bool energy) {
  INFO(summary(t));
  CHECK(t.paths == 16 * sets);
  CHECK(t.crushed * 4 >= t.paths);  // the cap is reached on a quarter of the paths at least
  CHECK(t.rejected == 0);
  CHECK(t.non_finite == 0);
  CHECK(t.damage == 0);
  CHECK(t.works == 0);
  CHECK(t.kappa == 0);
  CHECK(t.off_surface == 0);
  CHECK(t.off_cap == 0);
  if (energy) CHECK(t.beyond_bound == 0);
}

void check_scheme(mortar::Scheme scheme, int sets, unsigned seed) {
  std::mt19937 rng(seed);
  Tally t;
  for (int set = 0; set < sets; ++set) {
    const mortar::Parameters p = random_parameters(rng);
    const mortar::CompressionCap c = random_cap(rng, p);
    CAPTURE(set, c.fc, c.Cs, c.Gfc, c.kappa_p);
    run_set(p, c, scheme, set % 4 == 3 ? 2 : 3, 60, false, rng, t);
  }
  check(t, sets, false);
}

}  // namespace

TEST_CASE("Property (cap): finite, damage, wI, wIII and kappa_c never decreasing, on or inside Eq. 2 and the cap "
          "(random sets and caps, 16 paths each, the three schemes)",
          "[property][cap]") {
  SECTION("modified Euler") { check_scheme(mortar::Scheme::modified_euler, scaled(40), 20261206); }
  SECTION("forward Euler") { check_scheme(mortar::Scheme::forward_euler, scaled(40), 20261207); }
  SECTION("backward Euler") { check_scheme(mortar::Scheme::implicit, implicit_sets(10), 20261208); }
}

TEST_CASE("Property (cap): energy closure within the trapezoid's bound, external work = sed + SDV 16 + 17 + 18 "
          "(random sets and caps, increments up to 0.1 elastic limit or 0.04 fc/kn)",
          "[property][cap]") {
  std::mt19937 rng(20261209);
  Tally t;
  const int sets = scaled(30);
  for (int set = 0; set < sets; ++set) {
    const mortar::Parameters p = random_parameters(rng);
    run_set(p, random_cap(rng, p), mortar::Scheme::modified_euler, 3, 150, true, rng, t);
  }
  check(t, sets, true);
}
