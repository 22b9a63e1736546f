// Stepping over a singular configuration (issue 31): where the held constraint rows lose rank
// along the motion (a chain of parallelograms with every link collinear), the corrector's
// matrix turns singular near the instant, and IDA cut its step to 1e-23 s there and stopped.
// The motion itself is regular: a motion whose velocity stays continuous leaves a bifurcation
// on the branch it arrived on (run/singular_passage.h). So the integrator leaves the
// ill-conditioned stretch by a Taylor step of second order, Δ = 2 d past the state where its
// corrector failed (d: the distance in time to the rank loss, from the smallest singular value
// σ of the held rows, with unit rows, and its rate along the motion, σ ≈ |σ'| |t − t*|), lands
// as far past the singular instant as it stood before it, projects that state onto the
// constraints (project_initial_state) and restarts there. Local error O(Δ³) in the free
// coordinates (a BDF1 step's order); on a driven chain with no free coordinate the projection
// is exact. The two branches are O(Δ) apart there, the prediction O(Δ³) off its own: the
// projection lands on the branch the motion arrived on.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/mechanical_system.h"
#include "integrate/integrator.h"
#include "integrate/status.h"

namespace limber::integrate {

// Below this fraction of its start value σ counts as near a singular configuration: IDA's
// corrector failed at 1.3e-3 - 1.2e-2 of it on the parallelogram chains at rtol 1e-9 (before
// and after the instant, tests/run/parallelogram_chain_test.cpp), on the 3-chain at rtol 1e-10
// 8 ms before the instant, above 0.1 of it; a failure elsewhere is reported as IDA's own.
inline constexpr double kNearSingularRatio = 0.3;

// Doublings of the stretch stepped over before giving up: a departure on the singular instant
// itself (σ at 1e-6 of its start: the 3-chain at rtol 1e-8) measures a distance of ~0.
inline constexpr int kMaxStepOverDoublings = 20;

// Step-overs without an accepted step between them after which the run stops: each lands where
// the rank margin is at least the departure's.
inline constexpr int kMaxStepOversInARow = 3;

// The smallest singular value of the held rows' G(t, q) with unit rows (1 with no rows).
double held_rows_margin(const MechanicalSystem& system, double t, const Eigen::VectorXd& q);

// A consistent state past a singular configuration, and the jump's end points for the samples
// inside it (served by the same prediction, projected).
struct StepOver {
  Status status;        // kConvergenceFailures (naming the configuration) when not possible
  double t = 0.0;       // where the integrator restarts
  Eigen::VectorXd q, v, vdot, lambda;
  // The departure, with the accelerations and multipliers the prediction starts from.
  Eigen::VectorXd q_from, v_from, vdot_from, lambda_from;
};

// From the state (t, q, v) where the corrector failed (v̇ solved there afresh): the state 2 d
// later, no later than `t_limit` (t_stop, a breakpoint). Precondition: σ(t, q) is below
// kNearSingularRatio of `margin_start` (σ at the start). Fails (status,
// singular_failure_message) when the landing point's σ stays below the departure's after
// kMaxStepOverDoublings doublings of Δ, or when the accelerations fail.
StepOver step_over_singular(const MechanicalSystem& system, double t, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, double margin_start, double t_limit);

// The jump's prediction at t in [from.t, from.t + Δ]: q ⊕ (s v + s²/2 v̇), v + s v̇ (s = t − t0),
// projected onto the constraints; false (left unprojected) when the projection fails, as it may
// exactly at the singular instant.
bool predict_across(const MechanicalSystem& system, double t0, const Eigen::VectorXd& q0,
                    const Eigen::VectorXd& v0, const Eigen::VectorXd& vdot0, double t,
                    Eigen::VectorXd& q, Eigen::VectorXd& v);

// The message of a failure near a singular configuration: where, how close, what to change.
std::string singular_failure_message(double t, double ratio, const std::string& what_failed);

// A stretch stepped over, from the departure (t0) to the landing point (t1, where the
// integrator restarts), with the integrals z at both ends (trapezoidal rule across it).
struct SteppedOverStretch {
  double t0 = 0.0, t1 = 0.0;
  Eigen::VectorXd q0, v0, vdot0, lambda0, z0;  // at t0
  Eigen::VectorXd q1, v1, vdot1, lambda1, z1;  // at t1
  // A sample at t0 ≤ t ≤ t1: the departure's prediction, projected; v̇, λ and z linear.
  void serve(const MechanicalSystem& system, double t, Sample& out) const;
};

// The step-overs of one run: the held rows' rank margin at the start, the step-overs since the
// last accepted step and the last stretch.
class SingularStepOvers {
 public:
  // At the run's consistent start.
  void start(const MechanicalSystem& system, double t, const Eigen::VectorXd& q);
  // After an accepted step: the count of step-overs in a row starts again.
  void accepted_step() { in_a_row_ = 0; }
  // After a failed (or struggling) step, from the state (t, q, v) with integrals z the
  // integrator stands at: nullopt when the held rows' margin there is not below `near_ratio` of
  // the start's (the caller reports its own failure); else success, with stretch() the landing
  // state to restart from (new rows reselected there, an event switching inside the stretch
  // refused), or the failure naming the singular configuration. `t_limit`: the next velocity
  // breakpoint or t_stop; `what_failed`: the integrator's failure, for the messages.
  std::optional<Status> step_over(const MechanicalSystem& system, const Quadrature& quadrature, double t,
                                  const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& z,
                                  double t_limit, const std::string& what_failed, double near_ratio);
  // The last stretch stepped over, when t lies inside it (before its end); else null.
  const SteppedOverStretch* holding(double t) const;
  const SteppedOverStretch& stretch() const { return *stretch_; }

 private:
  double margin_start_ = 1.0;
  int in_a_row_ = 0;
  std::optional<SteppedOverStretch> stretch_;
};

}  // namespace limber::integrate
