// Driving a scheme along a discretised separation history through the
// Abaqus/Explicit entry point vuinteraction_, displacement-controlled: once
// for one point to record what it returns (tractions, dissipation, status,
// distance from the yield surface), and repeatedly over a block of points to
// time it.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mortar/parameters.hpp"
#include "mortar/state_layout.hpp"

namespace mortar::harness {

using Vec3 = Eigen::Vector3d;

// What props(15..19) say: the scheme and its controls (0 = the routine's
// default, as in Abaqus).
struct SchemeControls {
  Scheme scheme = Scheme::modified_euler;
  double stol = 0;          // props(16)
  double ftol = 0;          // props(17)
  double max_substeps = 0;  // props(18)
  double min_substep = 0;   // props(19)
};

// props(1..19), and with cap.on() props(20) = 0 and the cap in props(21..24).
std::vector<double> bench_props(const Parameters& p, const SchemeControls& c,
                                const CompressionCap& cap = CompressionCap{});

// What the solver holds for a point between increments: its state, stress
// and sed arrays (Abaqus layout and signs). DEPVAR is kStateCount, or with a
// cap kCappedStateCountDouble (SDV 36 holds kappa_c); the slots past it stay 0.
struct Snapshot {
  std::array<double, kCappedStateCountDouble> state{};
  std::array<double, 3> stress{};
  double sed = 0;
};

// One point's record along the history.
struct Trajectory {
  std::vector<Vec3> traction;  // law signs, at history[0..completed]
  double dissipation = 0;      // sum of spd to the end [N/mm]
  long completed = 0;          // increments done before a failure or the budget ran out
  int failure = 0;             // SDV 21 of the failed increment (0: none)
  long failure_increment = 0;  // 1-based history increment that failed
  bool non_finite = false;     // a traction, sed or spd that is NaN or infinite
  bool budget_exceeded = false;
  // Largest F / yield_tolerance over the increment ends (mortar::yield_function
  // on the returned traction and the returned state): > 1 is a drift off the
  // yield surface, beyond FTOL.
  double drift = 0;
  long drifted_increments = 0;
  double seconds = 0;
  // The point after increment checkpoint[j], for drive_point's `checkpoints`.
  std::vector<Snapshot> snapshots;
  bool complete(long increments) const { return completed == increments && failure == 0 && !non_finite; }
};

// Drives one point along `history` (history[0] is the origin, the reference
// call). Each history increment is split into `split` equal calls (a finer
// run along the same path; records are kept at the history's points only).
// `check_surface` computes the drift (costly; the references skip it): Eq. 2
// only, not the cap's surface, whose strength the law's headers do not expose. Stops
// at the first failed increment, at a non-finite output, or when
// `budget_seconds` of wall time are spent. The snapshots after the
// increments listed in `checkpoints` (ascending; 0 = after the reference
// call) are kept in Trajectory::snapshots.
Trajectory drive_point(const Parameters& p, const CompressionCap& cap, int n_dir, const SchemeControls& c, const std::vector<Vec3>& history,
                       int split, double budget_seconds, bool check_surface,
                       const std::vector<long>& checkpoints = {});

// The timed block: the history cut into `points` consecutive windows, point k
// of the block starting window k from the recorded state at its start, so
// that one sweep of the block does every increment of the path exactly once,
// with points in different states side by side as in an Abaqus block.
struct TimingWindows {
  std::vector<long> start;  // window k covers increments start[k]+1 .. start[k+1]
  int points() const { return static_cast<int>(start.size()) - 1; }
  long length() const;      // the longest window: calls per sweep
};
// At most `max_points` windows, of lengths differing by at most one.
TimingWindows timing_windows(long increments, int max_points);

struct Timing {
  double median_ns = 0, min_ns = 0, max_ns = 0;  // per point-update, over the repeats
  int points = 0, repeats = 0;
  long calls = 0;  // calls of vuinteraction_ per sweep
  // After the first (untimed, warm-up) sweep every point ended in the state
  // the one-point run recorded at the end of its window, bit for bit.
  bool reproduced = false;
};

// Nanoseconds per point-update over `repeats` sweeps of the windows (the
// one-point run's snapshots at the window starts, checkpoints =
// windows.start). A point whose window is done gets the "no opposite
// surface" penetration (the routine returns at once; not counted as an
// update). The timed loop only writes the call's penetration and slip
// increments and calls the routine; nothing is allocated in it.
Timing time_history(const Parameters& p, const CompressionCap& cap, int n_dir, const SchemeControls& c, const std::vector<Vec3>& history,
                    const TimingWindows& windows, const std::vector<Snapshot>& snapshots, int repeats);

}  // namespace mortar::harness
