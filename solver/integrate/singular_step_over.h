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

#include <functional>
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

// A margin below kNearSingularRatio is a rank loss only when the rank is lost there or along
// the motion: σ below kRankLostRatio of its start value (the run's watch counts the rank lost
// there, run/singular_passage.h), or below kRankLossConfirmRatio of the departure's at the
// instant t* = t − σ/σ' where its linear model vanishes (ahead when σ falls, behind when it
// rises), on the departure's prediction projected there (or no projection there). Near a
// simple rank loss σ ≈ |σ'| |t − t*| and the model's error is second order: at 0.3 of the
// start the parallelogram's crank stands 0.3 rad from the instant, and σ(t*) is 0.03 of the
// departure's; a smooth minimum of σ stays above. And a rank loss of the rows held is a
// singular configuration only when no other choice of rows holds there: the system is asked to
// reselect its rows at t* (MechanicalSystem::reselect_constraints), and when the new rows'
// margin there is not below kNearSingularRatio of the start's the integrator restarts from its
// departure on them instead. The system is asked first without a change
// (MechanicalSystem::reselection_candidate) and switches only when those rows are taken: a
// probe that switches nothing leaves the system as it was. Bricard's linkage (tests/run/data) has such a point at t ≈ 0.214 s:
// its held rows' σ falls to 2e-3 of its start value while all 31 equations keep rank 30; at
// rtol 1e-10, atol 1e-12 IDA's corrector failed 2 ms before it (σ at 0.16 of the start), before
// the system's own trigger (a pivot below 0.1 of the chosen one) reselected, and the failure was
// stepped over as a singular configuration (10 ms; energy balance 1.2e-3 off, 5e-10 without).
inline constexpr double kRankLostRatio = 1e-2;
inline constexpr double kRankLossConfirmRatio = 0.1;

// Doublings of the stretch stepped over before giving up: a departure on the singular instant
// itself (σ at 1e-6 of its start: the 3-chain at rtol 1e-8) measures a distance of ~0.
inline constexpr int kMaxStepOverDoublings = 20;

// Step-overs without an accepted step between them after which the run stops: each lands where
// the rank margin is at least the departure's.
inline constexpr int kMaxStepOversInARow = 3;

// The smallest singular value of the held rows' G(t, q) with unit rows (1 with no rows).
double held_rows_margin(MechanicalSystem& system, double t, const Eigen::VectorXd& q);
// The same of given rows G (nc x nv; 1 with no rows).
double unit_rows_margin(Eigen::MatrixXd G);

// A consistent state past a singular configuration, and the jump's end points for the samples
// inside it (served by the same prediction, projected).
struct StepOver {
  bool near = true;     // a rank loss near (above); when false the rest is not set
  bool rows_reselected = false;  // the system chose other rows, which hold there: not stepped
  Status status;        // kConvergenceFailures (naming the configuration) when not possible
  double t = 0.0;       // where the integrator restarts
  Eigen::VectorXd q, v, vdot, lambda;
  // The departure, with the accelerations and multipliers the prediction starts from.
  Eigen::VectorXd q_from, v_from, vdot_from, lambda_from;
};

// From the state (t, q, v) where the corrector failed (v̇ solved there afresh): the state 2 d
// later (`landing_time` of it when given: generalized-α's next grid point), no later than
// `t_limit` (t_stop, a breakpoint). Precondition: σ(t, q) is below kNearSingularRatio of
// `margin_start` (σ at the start). `near` false when no rank loss is near, `rows_reselected`
// when it is the held rows' own, cured by other rows (above; the system holds them now). Fails
// (status, singular_failure_message) when the landing point's σ stays below the departure's
// after kMaxStepOverDoublings doublings of Δ, or when the accelerations fail.
StepOver step_over_singular(MechanicalSystem& system, double t, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& v, double margin_start, double t_limit,
                            const std::function<double(double)>& landing_time = {});


// The jump's prediction at t in [from.t, from.t + Δ]: q ⊕ (s v + s²/2 v̇), v + s v̇ (s = t − t0),
// projected onto the constraints; false (left unprojected) when the projection fails, as it may
// exactly at the singular instant.
bool predict_across(MechanicalSystem& system, double t0, const Eigen::VectorXd& q0,
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
  void serve(MechanicalSystem& system, double t, Sample& out) const;
};

// What a step-over did: nothing (not at a rank loss: the caller reports its own failure), a
// reselection of rows (the caller restarts from its state on them), a step over (the caller
// restarts from stretch()'s landing state), or a failure naming the singular configuration.
struct StepOverOutcome {
  enum Kind { kNotSingular, kRowsReselected, kSteppedOver, kFailed } kind = kNotSingular;
  Status status;
};

// The step-overs of one run: the held rows' rank margin at the start, the step-overs since the
// last accepted step and the last stretch.
class SingularStepOvers {
 public:
  // At the run's consistent start.
  void start(MechanicalSystem& system, double t, const Eigen::VectorXd& q);
  // After an accepted step: the count of step-overs in a row starts again.
  void accepted_step() { in_a_row_ = 0; }
  // After a failed (or struggling) step, from the state (t, q, v) with integrals z the
  // integrator stands at: not singular when the held rows' margin there is not below
  // `near_ratio` of the start's or no rank loss is near (step_over_singular); rows reselected;
  // stepped over, with stretch() the landing state to restart from (new rows reselected there, an
  // event switching inside the stretch refused); or failed (more than kMaxStepOversInARow
  // without an accepted step between them, or step_over_singular's failures). `t_limit`: the
  // next velocity breakpoint or t_stop; `what_failed`: the integrator's failure, for the
  // messages; `landing_time` as step_over_singular's.
  StepOverOutcome step_over(MechanicalSystem& system, const Quadrature& quadrature, double t,
                            const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& z,
                            double t_limit, const std::string& what_failed, double near_ratio,
                            const std::function<double(double)>& landing_time = {});
  // The last stretch stepped over, when t lies inside it (before its end); else null.
  const SteppedOverStretch* holding(double t) const;
  const SteppedOverStretch& stretch() const { return *stretch_; }
  double margin_start() const { return margin_start_; }

 private:
  double margin_start_ = 1.0;
  int in_a_row_ = 0;
  std::optional<SteppedOverStretch> stretch_;
};

}  // namespace limber::integrate
