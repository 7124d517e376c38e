#include "bench/drive.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "abi/vuinteraction_call.hpp"
#include "mortar/state_layout.hpp"
#include "mortar/integrator.hpp"

namespace mortar::harness {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

AbiSetup setup_for(const Parameters& p, const CompressionCap& cap, int n_dir, const SchemeControls& c) {
  AbiSetup s;
  s.n_dir = n_dir;
  s.n_states = cap.on() ? kCappedStateCountDouble : kStateCount;
  s.props = bench_props(p, c, cap);
  s.stiffness_default = p.kn;
  return s;
}

// The model the routine builds from the same props, for the surface check.
Model model_for(const std::vector<double>& props) {
  Parameters p;
  Controls c;
  CompressionCap cap;
  read_props(props.data(), static_cast<int>(props.size()), p, c);
  read_cap(props.data(), static_cast<int>(props.size()), p, cap);
  return make_model(p, c, cap);
}

// The call arguments of one increment from `from` to `to` (law signs): the
// opening at its end and the separation increment.
struct CallInput {
  double opening = 0;
  Vec3 increment = Vec3::Zero();
};
CallInput call_input(const Vec3& from, const Vec3& to) { return CallInput{to[0], to - from}; }

void set_inputs(AbiBlock& abi, int k, const CallInput& in) {
  abi.set_separation_increment(k, in.opening, in.increment);
}

// The routine's first sight of the points: zero penetration and slip.
void reference_call(AbiBlock& abi) {
  std::fill(abi.state_array().begin(), abi.state_array().end(), 0.0);
  std::fill(abi.stress_array().begin(), abi.stress_array().end(), 0.0);
  std::fill(abi.sed_array().begin(), abi.sed_array().end(), 0.0);
  for (int k = 0; k < abi.size(); ++k) {
    abi.penetration(k) = 0.0;  // +0, the reference the routine stores
    std::fill_n(abi.dr_disp(k), abi.n_dir(), 0.0);
  }
  abi.invoke(CallTime{});
}

CallTime call_info(long increment, long increments) {
  CallTime info;
  info.increment = static_cast<int>(std::min<long>(increment, 2000000000L));
  info.time_increment = 1.0 / double(increments);
  info.step_time = info.total_time = double(increment) / double(increments);
  return info;
}

// F / yield_tolerance of point 0 after a call, with the law's own functions.
double surface_ratio(const Model& M, const AbiBlock& abi, const Vec3& sigma) {
  State y;
  load_state(abi.state(0), y);
  return mortar::yield_ratio(M, y, sigma);
}

Snapshot snapshot_of(AbiBlock& abi, int k) {
  Snapshot s;
  std::copy_n(abi.state(k), abi.n_states(), s.state.begin());
  std::copy_n(abi.stress(k), abi.n_dir(), s.stress.begin());
  s.sed = abi.sed(k);
  return s;
}

void restore(AbiBlock& abi, int k, const Snapshot& s) {
  std::copy_n(s.state.begin(), abi.n_states(), abi.state(k));
  std::copy_n(s.stress.begin(), abi.n_dir(), abi.stress(k));
  abi.sed(k) = s.sed;
}

// The opening whose penetration (-1e36) Abaqus passes for a point with no
// opposite surface (the routine then returns zero traction at once).
constexpr double kNoContactOpening = 1e36;

}  // namespace

std::vector<double> bench_props(const Parameters& p, const SchemeControls& c, const CompressionCap& cap) {
  Controls controls;
  controls.scheme = c.scheme;
  if (c.stol != 0) controls.stol = c.stol;
  if (c.ftol != 0) controls.ftol = c.ftol;
  if (c.max_substeps != 0) controls.max_substeps = static_cast<int>(c.max_substeps);
  if (c.min_substep != 0) controls.min_substep = c.min_substep;
  const auto props = to_props(p, controls);
  std::vector<double> out(props.begin(), props.end());
  if (cap.on()) {
    out.resize(kCapFirstProp + kCapCount, 0.0);  // props(20) = 0: the adapters' default shear sign
    for (int i = 0; i < kCapCount; ++i) out[static_cast<size_t>(kCapFirstProp + i)] = cap_parameter_at(cap, i);
  }
  return out;
}

Trajectory drive_point(const Parameters& p, const CompressionCap& cap, int n_dir, const SchemeControls& c, const std::vector<Vec3>& history,
                       int split, double budget_seconds, bool check_surface,
                       const std::vector<long>& checkpoints) {
  const AbiSetup setup = setup_for(p, cap, n_dir, c);
  const Model M = model_for(setup.props);
  AbiBlock abi(setup, 1, 0);
  Trajectory t;
  t.traction.reserve(history.size());
  const auto t0 = Clock::now();
  reference_call(abi);
  t.traction.push_back(abi.traction(0));
  size_t next_checkpoint = 0;
  auto keep_snapshot = [&](long i) {
    while (next_checkpoint < checkpoints.size() && checkpoints[next_checkpoint] == i) {
      t.snapshots.push_back(snapshot_of(abi, 0));
      ++next_checkpoint;
    }
  };
  keep_snapshot(0);
  const long n = static_cast<long>(history.size()) - 1;
  const long calls = n * split;
  for (long i = 1; i <= n; ++i) {
    for (int j = 1; j <= split; ++j) {
      const Vec3 from = history[i - 1] + (history[i] - history[i - 1]) * (double(j - 1) / split);
      const Vec3 to = j == split ? history[i] : history[i - 1] + (history[i] - history[i - 1]) * (double(j) / split);
      set_inputs(abi, 0, call_input(from, to));
      abi.invoke(call_info((i - 1) * split + j, calls));
      const double status = abi.state(0)[slot::status];
      if (status != 0) {
        t.failure = static_cast<int>(status);
        t.failure_increment = i;
        t.seconds = seconds_since(t0);
        return t;
      }
      if (!std::isfinite(abi.stress(0)[0] + abi.stress(0)[1] + abi.stress(0)[n_dir - 1] + abi.sed(0) +
                         abi.spd(0))) {
        t.non_finite = true;
        t.failure_increment = i;
        t.seconds = seconds_since(t0);
        return t;
      }
      t.dissipation += abi.spd(0);
    }
    const Vec3 sigma = abi.traction(0);
    t.traction.push_back(sigma);
    t.completed = i;
    keep_snapshot(i);
    if (check_surface) {
      const double r = surface_ratio(M, abi, sigma);
      t.drift = std::max(t.drift, r);
      if (r > 1) ++t.drifted_increments;
    }
    if (seconds_since(t0) > budget_seconds) {
      t.budget_exceeded = true;
      break;
    }
  }
  t.seconds = seconds_since(t0);
  return t;
}

long TimingWindows::length() const {
  long w = 0;
  for (size_t k = 1; k < start.size(); ++k) w = std::max(w, start[k] - start[k - 1]);
  return w;
}

TimingWindows timing_windows(long increments, int max_points) {
  const long points = std::max(1L, std::min<long>(max_points, increments));
  TimingWindows w;
  for (long k = 0; k <= points; ++k) w.start.push_back(k * increments / points);
  return w;
}

Timing time_history(const Parameters& p, const CompressionCap& cap, int n_dir, const SchemeControls& c, const std::vector<Vec3>& history,
                    const TimingWindows& windows, const std::vector<Snapshot>& snapshots, int repeats) {
  const int P = windows.points();
  const long W = windows.length();
  // The inputs of call w for point k, and the call infos, made beforehand.
  std::vector<CallInput> inputs(static_cast<size_t>(W * P));
  for (long w = 0; w < W; ++w)
    for (int k = 0; k < P; ++k) {
      const long i = windows.start[k] + 1 + w;
      CallInput& in = inputs[w * P + k];
      if (i <= windows.start[k + 1]) in = call_input(history[i - 1], history[i]);
      else in.opening = kNoContactOpening;
    }
  std::vector<CallTime> infos(static_cast<size_t>(W));
  for (long w = 0; w < W; ++w) infos[w] = call_info(w + 1, W);
  AbiBlock abi(setup_for(p, cap, n_dir, c), P, 0);
  std::vector<double> ns(static_cast<size_t>(repeats));
  Timing t;
  t.points = P;
  t.repeats = repeats;
  t.calls = W;
  const long updates = windows.start.back();
  // Sweep 0 warms the caches and checks the reproduction; it is not timed.
  for (int r = 0; r <= repeats; ++r) {
    for (int k = 0; k < P; ++k) restore(abi, k, snapshots[k]);
    const auto t0 = Clock::now();
    for (long w = 0; w < W; ++w) {
      const CallInput* in = &inputs[w * P];
      for (int k = 0; k < P; ++k) set_inputs(abi, k, in[k]);
      abi.invoke(infos[w]);
    }
    const auto t1 = Clock::now();
    if (r > 0) ns[r - 1] = std::chrono::duration<double, std::nano>(t1 - t0).count() / double(updates);
    if (r == 0) {
      t.reproduced = true;
      for (int k = 0; k < P; ++k)
        t.reproduced = t.reproduced && std::equal(snapshots[k + 1].state.begin(),
                                                  snapshots[k + 1].state.begin() + abi.n_states(), abi.state(k));
    }
  }
  std::sort(ns.begin(), ns.end());
  t.min_ns = ns.front();
  t.max_ns = ns.back();
  t.median_ns = repeats % 2 ? ns[repeats / 2] : 0.5 * (ns[repeats / 2 - 1] + ns[repeats / 2]);
  return t;
}

}  // namespace mortar::harness
