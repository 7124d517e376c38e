// A mock solver as the scene's driver sees it (solvers/scene_run.hpp): the
// scene's points in groups that are solved together (the explicit solver's
// blocks, one call of vuinteraction_ for all of a block's points; the
// implicit solver's single point), each group advanced one increment at a
// time from its committed start and committed at the end.
#pragma once

#include "scenes/scene.hpp"
#include "solvers/mixed_control.hpp"

namespace mortar::harness {

class MockSolver {
 public:
  virtual ~MockSolver() = default;

  virtual int groups() const = 0;
  virtual int first_point(int group) const = 0;
  virtual int group_size(int group) const = 0;

  // What the solver does before the first increment (the explicit solver's
  // reference call); result() then holds row 0 of every point of the group.
  virtual void start(int group) = 0;
  // Solves increment i of `step` for the group's points, with the scene's
  // targets, and commits it. Throws RunFailure.
  virtual void advance(int group, const Scene& scene, int step, long i, const IncrementClock& clock) = 0;

  // The committed point (law signs) and its SDV array, by the scene's point index.
  virtual const PointResult& result(int point) const = 0;
  virtual const double* state(int point) const = 0;
  // The external work of the last increment [N/mm].
  virtual double work_increment(int point) const = 0;
  virtual long calls() const = 0;  // of the ABI entry point
};

}  // namespace mortar::harness
