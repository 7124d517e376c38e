#include "mortar/integration/substepper.hpp"

#include <algorithm>
#include <cmath>

#include "mortar/integration/cone.hpp"
#include "mortar/integration/relaxation.hpp"

namespace mortar {

namespace {
constexpr int kMaxCrossingCuts = 40;  // docs/model.md 6, regime switches inside an increment
}  // namespace

double Substepper::run(const Vec3& d, const SurfaceAt& at) {
  const Controls& c = M_.controls;
  surface_at_start_ = at;
  // The floor follows the strength left (min_substep_floor); an increment no
  // longer than the material length keeps min_substep throughout.
  const double length = d.norm();
  const bool bounded = length > M_.substep_length;
  scheme_.set_floor(c.min_substep);
  apex_.set_floor(c.min_substep);
  at_boundary_ = false;
  // Every bracket starts closed: one left open by the run before (stopped
  // inside it) would cut this run's substeps towards another point's sizes.
  cut_ = CrossingBracket{};
  cuts_ = 0;
  sep_cut_ = CrossingBracket{};
  sep_cuts_ = 0;
  dn_cut_ = CrossingBracket{};
  dn_cuts_ = 0;
  reach_cut_ = CrossingBracket{};
  reach_cuts_ = 0;
  double T = 0, dT = 1;
  bool unloaded = false;
  // Every pass of the loop counts against the budget, so no path through
  // it (cuts, relaxations) can spin forever.
  for (long pass = 0; T < 1; ++pass) {
    if (st_.work() >= c.max_substeps || pass >= 4L * c.max_substeps) {
      st_.failure = Failure::too_many_substeps;
      return T;
    }
    if (const Failure f = scheme_.budget_spent(st_); f != Failure::none) {
      st_.failure = f;
      return T;
    }
    // An elastic substep (unloading) left the point inside the surface: where
    // it yields again is the segment's to find (the elastic-plastic
    // intersection, increment.cpp), as for a call that starts there; the
    // rate statement from inside would flow at once and keep the gap.
    if (unloaded && yield_of_surfaces(M_, P_, surface_at_start_) < -yield_tolerance(M_, P_.sigma)) return T;
    if (bounded) {
      scheme_.set_floor(min_substep_floor(M_, length, surface_at_start_.S.s_raw));
      apex_.set_floor(min_substep_floor(M_, length, surface_at_start_.S.s_raw));
    }
    dT = std::min(dT, 1 - T);
    const Vec3 dd = dT * d;
    with_psi(M_, surface_at_start_.S, P_.y.wIII);  // the last end surface may be a shape (scheme.hpp, Attempt)
    const Rates r1 = stage(M_, P_, surface_at_start_, dd);
    if (r1.snapback) {  // no strain-driven solution from here
      if (!relax(M_, P_, st_, true)) {
        st_.failure = Failure::relaxation_failed;
        return T;
      }
      surface_at_start_ = surface_at(M_, P_);
      tangent_.forget(st_);
      continue;
    }
    // On the fully softened normal the rest of the run is one scalar solve
    // (cone.hpp; docs/model.md 6, Decision - sliding on the cone), for every
    // scheme; not while a bracket is being closed.
    if (r1.plastic && !cut_.active && !sep_cut_.active) {
      const ConeStep cone = cone_step(M_, P_, surface_at_start_, (1 - T) * d, r1.grow);
      if (cone.done > 0) {
        surface_at_start_ = surface_at(M_, P_);
        tangent_.forget(st_);
        ++st_.substeps_accepted;
        T += cone.done * (1 - T);
        if (cone.separates) return std::min(T, 1.0);
        return 1;
      }
    }
    // The apex zone of a worn open joint (in_apex_zone): backward-Euler
    // substeps, whatever the scheme (docs/model.md 6, Decision - the apex zone).
    SubstepScheme& sch = in_apex_zone(M_, P_, surface_at_start_) ? static_cast<SubstepScheme&>(apex_) : scheme_;
    const Attempt a = sch.attempt(P_, dd, dT, r1);
    if (a.kind == Attempt::retry) {
      dT = a.size;
      ++st_.substeps_rejected;
      continue;
    }
    if (a.kind == Attempt::fail) {
      st_.failure = a.failure;
      return T;
    }
    if (a.kind == Attempt::on_boundary) return end_on_boundary(*a.end, T + a.theta * dT);
    // settle() and the landings change no work: SN is the surface of the
    // substep's end before and after them.
    SurfaceAt surface_at_end;
    const Surface& SN = surface_at_end.S = a.surface ? *a.surface : surface_of(M_, a.end->y);
    const Landing sep = separation(SN, dT);
    if (sep == Landing::cut) continue;
    const Landing normal = normal_completion(*a.end, SN, dT);
    if (normal == Landing::cut) continue;
    const Landing reached = surface_reached(*a.end, SN, dT);
    if (reached == Landing::cut) continue;
    // A substep cut to land on the other surface: its size depends on the
    // increment, and the tangent holds it fixed (docs/model.md 12).
    if (reached == Landing::lands) tangent_.lost = tangent_.lost || bool(tangent_);
    const bool separates = sep == Landing::lands;
    const Crossing crossing_kind = crossing(*a.end, dd, dT);
    if (crossing_kind == Crossing::from_boundary) {
      at_boundary_ = true;
      return T;
    }
    if (crossing_kind == Crossing::cut) continue;
    const bool switch_here = crossing_kind == Crossing::ends_on_boundary;
    Point& Q = *a.end;  // the scheme's own, which its next attempt overwrites
    if (switch_here) Q.y.plastic[0] = Q.y.separation[0];  // on the boundary: delta_e_n = 0
    sch.before_settle(Q);
    settle(M_, Q, P_.y.elastic_separation(), sch.traits.branches_from_first_stage ? r1.grow : Branches{});
    if (normal == Landing::lands) {
      complete_normal_damage(M_, Q.y);
      Q.sigma = traction_of(M_, Q.y);
    }
    // A substep that lands on a boundary (regime or complete separation) is
    // exact there: neither rejected for drift nor drift-corrected off it.
    const bool lands = switch_here || separates;
    surface_at_end.radius = shear_radius(Q.sigma, SN);
    if (const double retry = sch.recheck(Q, surface_at_end, dT, lands); retry > 0) {
      dT = retry;
      ++st_.substeps_rejected;
      continue;
    }
    sch.commit(P_, Q, surface_at_end, dd, T, dT, lands);
    surface_at_start_ = surface_at_end;
    ++st_.substeps_accepted;
    unloaded = !r1.plastic;
    T += dT;
    if (switch_here) {
      at_boundary_ = true;
      return std::min(T, 1.0);
    }
    // The normal traction given up on completing the normal damage (by up to
    // tan(phi) times the threshold), or all of it on separating, leaves the
    // point inside the surface: what follows is decided afresh, elastic up to
    // the surface first, as a call that starts there would (increment.cpp).
    // Where the landing substep ends depends on the increment; its tangent
    // is held fixed there (docs/model.md 7.5).
    if (normal == Landing::lands || separates) {
      tangent_.lost = tangent_.lost || bool(tangent_);
      return std::min(T, 1.0);
    }
    // The next substep's size, when there is one: a run that reaches T = 1
    // has done its segment, and no later substep of the increment reads what
    // next_size() keeps (its square root and division are then not waited on).
    if (T < 1) dT = sch.next_size(dT);
  }
  return 1;
}

// A switch of regime inside the substep: the substep is shortened to end on
// the boundary delta_e_n = 0 (regula falsi on the substep size, with
// bisection as a safeguard, bracketed between a size that stays in the
// regime and one that crosses), then the regime switches there.
Substepper::Crossing Substepper::crossing(const Point& N, const Vec3& dd, double& dT) {
  const double e0 = P_.y.elastic_separation()[0], e1 = N.y.elastic_separation()[0];
  const double near = 1e-9 * std::abs(dd[0]) + boundary_eps(M_, N.y);
  const bool crossed = crosses(P_.y.open, e1);
  if (crossed && std::abs(e0) <= boundary_eps(M_, P_.y)) return Crossing::from_boundary;
  bool on_boundary = false;
  if (crossed || cut_.active) {
    cut_.record(dT, e1, crossed, e0);
    if (std::abs(e1) > near && cuts_ < kMaxCrossingCuts) {
      dT = cut_.next(cuts_);
      ++cuts_;
      return Crossing::cut;
    }
    on_boundary = crossed || std::abs(e1) <= near;
  }
  cuts_ = 0;
  cut_ = CrossingBracket{};
  return on_boundary ? Crossing::ends_on_boundary : Crossing::none;
}

// Complete separation inside the substep (docs/model.md 6, Decision -
// complete separation): a substep of an open joint that takes s_raw below
// kSeparated is shortened to end on it (regula falsi on the substep size in
// log(s_raw / kSeparated), bisection as a safeguard), so that where the joint
// separates does not depend on the cuts; settle() then disintegrates it.
Substepper::Landing Substepper::separation(const Surface& SN, double& dT) {
  if (!P_.y.open) return Landing::none;
  const double s0 = surface_at_start_.S.s_raw, s1 = SN.s_raw;
  if (separated(s0)) return Landing::none;
  const double g1 = std::log(std::max(s1, 1e-300) / kSeparated);
  return one_sided(sep_cut_, sep_cuts_, dT, std::log(s0 / kSeparated), g1, g1 < -1e-9, std::abs(g1) <= 1e-9,
                   separated(s1));
}

// Complete normal damage inside the substep (docs/model.md 6, Decision -
// complete normal damage): on its growing branch an open joint's normal
// traction falls towards zero while the joint stays open, and only
// asymptotically on a worn joint that opens while sliding. What is left is
// taken as none once it is below kSeparated of a traction scale, as s is at
// complete separation: ft0, or, while the joint slides, the undamaged ...
// The rest: docs/numerics.md, section 10.
Substepper::Landing Substepper::normal_completion(const Point& N, const Surface& SN, double& dT) {
  if (!P_.y.open || !(P_.y.dn < 1) || !(N.y.elastic_separation()[0] > 0)) return Landing::none;
  auto g = [&](const Point& X, const ShearRadius& r) {
    const double tau = r.tau, R = r.R;
    const double sliding = R > 0 ? tau / R : 0.0;
    const double left = kNormalComplete * std::max(M_.stress_scale, sliding * M_.p.kn * X.y.elastic_separation()[0]);
    return (X.sigma[0] - left) / M_.stress_scale;
  };
  const double g0 = g(P_, surface_at_start_.radius);
  if (!(g0 > 0)) return Landing::none;
  const double g1 = g(N, shear_radius(N.sigma, SN));
  const bool landed = g1 < 0 && g1 >= -1e-9;
  return one_sided(dn_cut_, dn_cuts_, dT, g0, g1, g1 < 0, landed, landed);
}

// The second surface reached inside the substep (docs/model.md 12): a closed
// joint with a cap that flows on one of Eq. 2 and the cap, inside the other
// at the substep's start, and ends beyond it: the substep is shortened to end
// on it (regula falsi on the substep size in that surface's F), so that where
// the corner is reached does not depend on the cuts.
Substepper::Landing Substepper::surface_reached(const Point& N, const Surface& SN, double& dT) {
  if (!cap_applies(M_, P_.y) || !cap_applies(M_, N.y)) return Landing::none;
  const double tol = on_surface_band(M_, P_.sigma);
  const double F1 = yield_of(P_, surface_at_start_), Fc = cap_function(M_, P_.sigma, P_.y.kappa_c);
  const bool on1 = F1 >= -tol, onc = Fc >= -tol;
  if (on1 == onc && !reach_cut_.active) return Landing::none;
  // The surface the start lies inside (the cap, while a bracket is open on it).
  const bool cap_is_other = reach_cut_.active ? reach_on_cap_ : on1;
  const double g0 = cap_is_other ? Fc : F1;
  const double g1 = cap_is_other ? cap_function(M_, N.sigma, N.y.kappa_c) : yield_function(N.sigma, SN);
  const double tol1 = yield_tolerance(M_, N.sigma);
  if (!reach_cut_.active) reach_on_cap_ = cap_is_other;
  const bool past = g1 > tol1, within = std::abs(g1) <= tol1;
  return one_sided(reach_cut_, reach_cuts_, dT, g0, g1, past, within, past || within);
}

// One trial substep of a one-sided bracket on the boundary function g (g0 at
// the substep's start, g1 at its end, `past` when g1 lies beyond the
// boundary): the first substep that goes past opens the bracket; until the
// end is `within` tolerance (or kMaxCrossingCuts tries are spent) the next
// size comes from the bracket; then the bracket closes and the substep
// `lands` on the boundary or not.
Substepper::Landing Substepper::one_sided(CrossingBracket& b, int& cuts, double& dT, double g0, double g1, bool past,
                                          bool within, bool lands) {
  if (!past && !b.active) return Landing::none;
  b.record(dT, g1, past, g0);
  if (!within && cuts < kMaxCrossingCuts) {
    dT = b.next(cuts);
    ++cuts;
    return Landing::cut;
  }
  cuts = 0;
  b = CrossingBracket{};
  return lands ? Landing::lands : Landing::none;
}

// The implicit scheme's step that ends on the regime boundary (BoundaryStep):
// accepted there, with delta_e_n = 0 exactly; `done` is the fraction of the
// plastic part it reaches.
double Substepper::end_on_boundary(const Point& N, double done) {
  const Vec3 e_start = P_.y.elastic_separation();
  P_ = N;
  P_.y.plastic[0] = P_.y.separation[0];
  settle(M_, P_, e_start);
  tangent_.forget(st_);
  ++st_.substeps_accepted;
  at_boundary_ = true;
  return std::min(done, 1.0);
}

}  // namespace mortar
