// The state of one IDA run (ida_integrator.h) behind IdaIntegrator's pointer: SUNDIALS' objects,
// the equations, the discrete bookkeeping of restarts, events and breakpoints, and the tuning
// constants with their reasons. Private to the integrate library: ida_integrator.cpp sets IDA
// up and steps it, ida_restarts.cpp restarts it (events, breakpoints, new constraint rows,
// singular configurations, loosened multiplier weights).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "integrate/ggl_equations.h"
#include "integrate/ida_integrator.h"
#include "integrate/singular_step_over.h"
#include "integrate/wall_clock_budget.h"

namespace limber::integrate {

// The layout of y = [q, v, λ, μ, z] is the equations' (ggl_equations.h).
struct IdaIntegrator::Impl : GglLayout {
  // Times closer than this are one time.
  static double time_tolerance(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }

  // Fraction of rtol × the largest starting multiplier below which λ's Newton weight does not go.
  // λ follows v̇ (M v̇ + Gᵀλ = Q), which Newton resolves only to v's weight divided by the step:
  // at 0.01 (1 % of rtol) the satellite deployment's multipliers, a few newtons, were asked for
  // 1e-5 N at h ~ 1e-4 s and Newton failed 1 671 times in 0–2.95 s with an exact matrix; at 1,
  // 126 times (docs/benchmarks.md, "IDA within 2× of generalized-α").
  static constexpr double kLambdaWeight = 1.0;

  // After IDA's corrector fails away from any singular configuration, λ's Newton weight is
  // loosened by kLambdaRelaxation and IDA restarts from the last state reached, at most
  // kMaxLambdaRelaxations times in a run. λ carries the round-off of v̇ (ε/h), so the weight
  // above asks for digits that small steps cannot give at rtol 1e-10: Bricard's linkage
  // (tests/run/data) failed at t = 0 with atol 1e-12 and at t = 0.8 s with atol 1e-10, each
  // with h ~ 1e-13; the parallelogram failed at t = 8e-6 s. Runs that did not fail are unchanged.
  static constexpr double kLambdaRelaxation = 100.0;
  static constexpr int kMaxLambdaRelaxations = 3;

  // Largest growth of the step from one step to the next (IDA's default 2). On a lightly damped
  // elastic mode a doubled step fails its error test, IDA halves it back and doubles it again,
  // so BDF1 never gets the run of equal steps it needs to raise its order: the flexible
  // slider-crank at rtol 1e-6 crawled at h ≈ 5 µs for 14 ms (2 519 rejected steps); with 1.5,
  // 246 rejected steps over the whole 0.3 s.
  static constexpr double kMaxStepGrowth = 1.5;

  // Non-finite residuals IDA may recover from (by cutting the step) within one advance_to.
  static constexpr int kMaxNonFiniteRetries = 10;

  // Rejected attempts within one accepted step within kStruggleRatio of a singular
  // configuration after which IDA steps over it at once instead of crawling on to its
  // corrector's failure (at rtol 1e-8 the simple parallelogram took 200 rejected steps per
  // passage that way). At 0.1 the stretch stepped over, whose samples are predicted, was 10
  // times longer and its samples 2e-5 m off (docs/integrators.md).
  static constexpr int kStruggle = 3;
  static constexpr double kStruggleRatio = 1e-2;

  WallClockBudget budget;  // IntegratorOptions::max_wall_seconds
  std::optional<GglEquations> equations;  // F and its Newton matrix

  MechanicalSystem* system = nullptr;
  IntegratorOptions options;
  double t0 = 0.0;
  bool stepped = false;
  bool failed = false;
  Status failure;
  std::string last_message;  // IDA's own text of its last error
  int nonfinite_residuals = 0;  // in the current advance_to
  Statistics restart_statistics;  // totals at IDA's last restart (reselect_constraints)
  int ne = 0;                     // event functions
  double t_reached = 0.0;         // where the solution stands: IDA's last return or restart
  std::vector<int> pending_events;  // located at t_reached, applied before the next step
  std::vector<double> breakpoints;  // velocity breakpoints after t0, before t_stop, ascending
  std::size_t next_breakpoint = 0;  // the first not yet passed
  Eigen::VectorXd e_values;
  SingularStepOvers step_overs;  // singular configurations stepped over (singular_step_over.h)
  bool jumped = false;  // restarted past a singular configuration, not stepped since
  long rejected_before = 0;  // rejected attempts before the last accepted step
  int lambda_relaxations = 0;  // λ's Newton weight loosened (kLambdaRelaxation) so far
  double first_step = 0.0;     // IDA's first step at t0
  // The structured matrix's kept difference (ggl_equations.h) is taken afresh at its first
  // matrix after a (re)start and after each Newton failure.
  bool difference_due = true;
  long failures_at_difference = 0;     // IDA's Newton failures (since its restart) then
  long difference_evaluations_at_restart = 0;

  SUNContext context = nullptr;
  N_Vector y = nullptr, yp = nullptr, id = nullptr, atol_vec = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver solver = nullptr;
  void* ida = nullptr;

  // Scratch space: events, y' of a restart.
  Eigen::VectorXd q, v, f;
  Eigen::MatrixXd N;

  ~Impl() { release(); }

  // --- Set-up and stepping (ida_integrator.cpp) ---
  // The run's bookkeeping reset for a start at x0 (breakpoints between t0 and t_stop).
  void start_run(MechanicalSystem& system_in, const InitialState& x0, const IntegratorOptions& options_in);
  // y0, y0' and id (q, v, z differential) from the consistent initial state.
  void load_initial_state(double t, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                          const Eigen::VectorXd& vdot0, const Eigen::VectorXd& lambda0);
  // IDA created and configured: linear solver, Newton matrix, tolerances, step limits, events.
  // Returns IDA's first failing flag, or ≥ 0.
  int configure_ida(double t, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& vdot0, const Eigen::VectorXd& lambda0);
  // The weights of IDA's error and convergence tests (atol per component).
  int set_tolerances(const Eigen::VectorXd& lambda0);
  // rtol and atol_vec handed to IDA, per component or per group (IdaErrorWeights).
  int apply_error_weights();
  // IdaErrorWeights::kPerGroup: w_i = 1 / (rtol max(|y_i|, max over y_i's group) + atol_i), the
  // groups q and v; λ, μ and z as IDASVtolerances weighs them.
  void group_error_weights(const double* y_data, double* w_data) const;
  // One IDA step towards t_out and what follows it (events found, statistics, the step
  // reported, budget, singular configurations). False when the run stops with `failure`.
  bool take_step(double t_out, Statistics& stats);
  // At a root IDA returned: the events it did not return that rise through 0 within
  // options.event_tolerance after it switch with it (as generalized-α's twin events). The
  // satellite's mirror-image latches R3 and R4 engage at one instant; at rtol 3e-5 IDA
  // returned R3's root alone and never saw R4 rise from there (docs/benchmarks.md).
  void add_twin_events();
  // The sample at t_out from y, y' (after IDAGetDky); `restart_due`: the equations change there.
  Status serve_sample(double t_out, bool restart_due, const Statistics& stats, Sample& out);
  void release();
  // F(t, y, y') (ggl_equations.h); on non-finite values returns 1 (recoverable: IDA cuts the
  // step) at most kMaxNonFiniteRetries times per advance_to, then −1 (IDA_RES_FAIL).
  int residual(double t, const double* y_data, const double* yp_data, double* r_data);
  // IDA's counters since the last (re)start, added to `before` (the totals at that restart).
  void read_statistics(Statistics& stats, const Statistics& before) const;
  // The structured Newton matrix (ggl_equations.h), its kept difference refreshed when due.
  bool newton_matrix(double t, double c_j, const double* y_data, const double* yp_data, double* J);
  // MechanicalSystem::step_accepted, then IntegratorOptions::on_step when set, with the state
  // IDA returned at t (the end of its step, or a located event): y and y' as IDASolve left them.
  void report_step(double t) const;
  // Event functions of the system at IDA's (t, y), for its root finding.
  int events(double t, const double* y_data, double* e_data);

  // --- Restarts (ida_restarts.cpp) ---
  // New constraint rows at time t (the current step end, or a located event): the multipliers
  // change meaning, so IDA restarts there.
  void reselect_constraints(double t);
  // The events located at t_reached switch their modes; IDA restarts there.
  void apply_pending_events();
  // IDA stops just before the next velocity breakpoint (half the time tolerance), else at
  // t_stop. A step ending on the breakpoint itself would meet the rate after the jump (drivers'
  // derivatives are right-continuous) with the velocities before it, and Newton fails there
  // at any step size (a kinked table driver died at t = 0.05 s with h = 1e-18).
  void set_stop_time();
  // At a velocity breakpoint (IDA stopped there): restart with v after the jump and the
  // integrals' jump (mechanical_system.h, velocity_breakpoints).
  void apply_breakpoint();
  // Restart at t (inside the last step, or at a velocity breakpoint just after it) at order 1,
  // from the current step size, with λ, v̇ from the saddle-point system and μ = 0; q, v and
  // the integrals carry over (across a breakpoint, `jump`, with the integrals' jump added).
  void restart(double t, bool jump = false);
  // The same from the state in y (its y' recomputed), first step h0.
  void restart_from_y(double t, double h0, bool jump = false);
  // y = [q, v, λ, 0, z], y' = [N v, v̇, 0, 0, f] at t (z as it stands in y).
  void load_state(double t, const Eigen::VectorXd& q_now, const Eigen::VectorXd& v_now,
                  const Eigen::VectorXd& vdot_now, const Eigen::VectorXd& lambda_now);
  // IDA restarted at t from y, y' at order 1, first step h0 (IDA's choice when 0).
  void reinit(double t, double h0);
  // After a corrector failure: λ's Newton weight loosened (kLambdaRelaxation) and IDA
  // restarted from the state it reached with its last step (the first step at t0, where IDA
  // has taken none). False when the relaxations are spent or there is no λ.
  bool relax_multiplier_weight();
  // After a failed step (or a struggling one): at a singular configuration (the held rows' rank
  // margin below near_ratio of the start's), restart past it, or on other rows where they hold
  // (singular_step_over.h). Returns nullopt when not at one (the caller reports IDA's failure),
  // else success or the failure naming it.
  std::optional<Status> step_over_singular_configuration(double near_ratio = kNearSingularRatio);
  // After IDASolve failed with `flag`: true when IDA goes on (restarted past a singular
  // configuration, or on other rows, or with λ's weight loosened), else false with the failure.
  bool recover_from_failure(int flag);
};

}  // namespace limber::integrate
