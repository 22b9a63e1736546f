// Singular configurations along a run: samples where the constraint equations lose rank, e.g.
// a parallelogram four-bar with all links collinear, where it may fold into the
// anti-parallelogram (issue 14). The measure is the rank-th singular value of the full
// constraint Jacobian G with unit rows (redundancy.h scaling), `rank` the number of independent
// rows chosen at the start, relative to its value at the start. A passage is a run of samples
// where it is below kSingularRatio; it is reported once, at its smallest sample, naming the
// joints (and drivers) whose rows carry the lost direction (|u_k| ≥ 0.1 max |u| of the left
// singular vector). The integrators run on through; which branch they took is not decided
// here (the model does not say which motion is intended).
#pragma once

#include <string>
#include <vector>

#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::run {

// Below this fraction of its start value the rank-th singular value counts as lost: the
// parallelograms of tests/run/data fall to 2e-7 - 8e-7 (the floor of the Gram matrix S Sᵀ,
// √ε) at their singular samples; the shipped slider-cranks, four-bar and satellite deployment
// report none.
inline constexpr double kSingularRatio = 1e-2;

struct SingularPassage {
  double t = 0.0;        // sample of the smallest value [s]
  double ratio = 0.0;    // its value relative to the start
  std::vector<std::string> names;  // joints and drivers whose rows carry the lost direction
  std::string message() const;
};

class SingularPassageMonitor {
 public:
  SingularPassageMonitor(const multibody::Model& model, int rank);
  // Adds a sample; returns true when a passage has just ended (`last()` holds it).
  bool add(const multibody::State& state);
  // Ends an open passage (end of run); true when one was open.
  bool finish();
  const SingularPassage& last() const { return last_; }

 private:
  const multibody::Model& model_;
  int rank_;
  multibody::Workspace workspace_;
  double start_ = -1.0;
  bool open_ = false;
  SingularPassage current_, last_;
};

}  // namespace limber::run
