// Singular configurations along a run: samples where the constraint equations lose rank, e.g.
// a parallelogram four-bar with all links collinear, where it may fold into the
// anti-parallelogram (issue 14). The measure is the rank-th singular value of the full
// constraint Jacobian G with unit rows (redundancy.h scaling), `rank` the number of independent
// rows chosen at the start, relative to its value at the start. A passage is a run of samples
// where it is below kSingularRatio; it is reported once, at its smallest sample, naming the
// joints (and drivers) whose rows carry the lost direction (|u_k| ≥ 0.1 max |u| of the left
// singular vector). The integrators run on through.
//
// Branch: at a bifurcation the branches cross with different tangents, so a motion that keeps
// its velocity continuous (no impulse: finite forces act for no time at the instant) leaves on
// the branch it arrived on. A change of branch shows as a jump of the bodies' frame velocities
// across the passage. The check extrapolates the last two samples before the passage linearly
// to the first sample after it and compares, per body, the linear and the angular frame
// velocity with the prediction, relative to the largest linear / angular frame speed before it.
// The prediction's own error is O((ω Δt)²) for a passage Δt long at frame rates ω: 5e-4 for the
// parallelograms of tests/run/data (2 rev/s, 3 ms); a jump above kBranchJump is reported as a
// change of branch, which is a numerical impulse unless the model holds an impact there.
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

// Velocity jump across a passage (relative, see above) above which the run changed branch.
inline constexpr double kBranchJump = 0.1;

struct SingularPassage {
  double t = 0.0;        // sample of the smallest value [s]
  double ratio = 0.0;    // its value relative to the start
  std::vector<std::string> names;  // joints and drivers whose rows carry the lost direction
  // Frame velocity jump across the passage relative to the frame speeds before it, and the
  // body where it is largest; −1 when not checked (the run started or ended inside it).
  double velocity_jump = -1.0;
  std::string jump_body;
  bool changed_branch() const { return velocity_jump > kBranchJump; }
  std::string message() const;
};

class SingularPassageMonitor {
 public:
  // `rank`: the independent rows at the start; rows flagged in `released` (released joints,
  // multibody/redundancy.h) are left out.
  SingularPassageMonitor(const multibody::Model& model, int rank, std::vector<bool> released = {});
  // Adds a sample (t, q, v) with the velocity Jacobian G of all the model's rows at state.q
  // (a sample's pass: SampleRecorder::constraint_jacobian); returns true when a passage has
  // just ended (`last()` holds it).
  bool add(const multibody::State& state, const Eigen::MatrixXd& G);
  // Ends an open passage (end of run, branch not checked); true when one was open.
  bool finish();
  const SingularPassage& last() const { return last_; }

 private:
  const multibody::Model& model_;
  int rank_;
  std::vector<int> rows_;  // the equations still in force (released joints' rows left out)
  Eigen::MatrixXd unit_rows_, gram_;  // scratch: their unit rows S and S Sᵀ
  double start_ = -1.0;
  bool open_ = false;
  SingularPassage current_, last_;
  // The last two samples before the open passage (or the latest two while none is open).
  struct Moment { double t = 0.0; Eigen::VectorXd v; };
  Moment before_[2];
  int moments_ = 0;
  bool close(const multibody::State* after);
  double branch_jump(const multibody::State& after, std::string& body) const;
};

}  // namespace limber::run
