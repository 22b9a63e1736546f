// Watches the redundant equations a run does not hold. A redundant row depends on the held
// rows, so while the mechanism stays where it is redundant its residual follows theirs (the
// seed slider-crank: 1e-14 throughout). A residual far above theirs means the row has come
// loose: the run has a freedom the model does not (deformation_redundancy.h) or has left the
// configurations where the row is redundant, and it would drift apart from there (the 10-mode
// slider-crank: the joints 1 m apart by t = 0.34 s). The run then stops with status
// kRedundantViolated, naming the equation, and keeps its samples.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "integrate/status.h"
#include "multibody/model.h"
#include "multibody/redundancy.h"
#include "run/deformation_redundancy.h"

namespace limber::run {

// A redundant row counts as loose above this residual, relative to the mechanism's size for
// translations and in radians for rotations (1e8 above rounding, 1e3 below the drift that
// makes a run inaccurate, accuracy_check.h) ...
inline constexpr double kLooseRedundantRow = 1e-6;
// ... and above this multiple of the held rows' largest residual (a redundant row combines
// them with weights of order one: IDA holds them only to its tolerance).
inline constexpr double kLooseOverHeld = 100.0;

class RedundantRowWatch {
 public:
  // `partition` is the run's current one (it may be reselected along the run); `known` the
  // start's deformation-dependent rows, whose diagnosis the message repeats. References must
  // outlive the watch.
  RedundantRowWatch(const multibody::Model& model, const multibody::ConstraintPartition& partition,
                    std::vector<DeformationRedundancy> known);

  // A failure status when a redundant row has come loose, from the residuals `g` of all rows
  // at time t (SampleRecorder::constraint_residuals); `size` is the mechanism's size [m]
  // (AccuracyMonitor).
  integrate::Status check(double t, const Eigen::VectorXd& g, double size) const;

 private:
  const multibody::Model& model_;
  const multibody::ConstraintPartition& partition_;
  std::vector<DeformationRedundancy> known_;

  std::string message(int row, double residual, double held, double t) const;
};

}  // namespace limber::run
