// The ABI as the mock solvers see it: one call of the routine for a set of
// points (a block of VUINTERACTION, abi/vuinteraction_caller.hpp; UINTER's
// single point, abi/uinter_caller.hpp) in the law's variables and signs
// (docs/model.md 1): point-increment in, traction, state and tangent out.
//
// Every call starts from the committed start of the increment (the routine
// must not commit: a solver calls it many times per increment); the solver
// accepts, point by point, the call it keeps, and commit() makes the accepted
// calls the start of the next increment.
#pragma once

#include <Eigen/Core>

#include "abi/call_time.hpp"

namespace mortar::harness {

class Caller {
 public:
  virtual ~Caller() = default;

  virtual int size() const = 0;   // points per call
  virtual int n_dir() const = 0;  // 2 (one slip) or 3

  // Point k's trial: its separation at the end of the call and the increment
  // from the committed start, the same trial twice; each routine reads the
  // one its arguments need (VUINTERACTION: the opening and the increment,
  // UINTER: the end).
  virtual void set_trial(int k, const Eigen::Vector3d& end, const Eigen::Vector3d& increment) = 0;
  virtual void call(const CallTime& time) = 0;

  // The last call's outputs.
  virtual Eigen::Vector3d traction(int k) const = 0;  // zero beyond nDir
  virtual double status(int k) const = 0;             // SDV 21
  // d traction / d separation, when the routine returns one (UINTER's
  // DDSDDR); false otherwise.
  virtual bool tangent(int, Eigen::Matrix3d&) const { return false; }
  // The routine's request for a smaller increment (UINTER's PNEWDT; < 1 is a request).
  virtual double size_request(int) const { return kNoSizeRequest; }

  virtual void accept(int k) = 0;  // the last call of point k is the one kept
  virtual void commit() = 0;       // the kept calls become the start

  // The committed point.
  virtual const double* state(int k) const = 0;  // SDV 1..nStates
  virtual double elastic_energy(int k) const = 0;         // sed [N/mm]
  virtual double dissipation_increment(int k) const = 0;  // spd of the kept call [N/mm]

  // Abaqus sets PNEWDT large before every call; only a value below 1 asks.
  static constexpr double kNoSizeRequest = 1e36;
};

}  // namespace mortar::harness
