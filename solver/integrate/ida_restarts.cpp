// IDA's restarts (ida_integrator_impl.h): at located events, velocity breakpoints and new
// constraint rows, past singular configurations, and with the multipliers' Newton weight
// loosened after a corrector failure. Each reloads a consistent y, y' and calls IDAReInit.
#include <fmt/format.h>

#include "core/error.h"
#include "integrate/consistent_state.h"
#include "integrate/ida_integrator_impl.h"
#include "integrate/ida_status.h"

namespace limber::integrate {

// New constraint rows at time t (the current step end, or a located event): the multipliers
// change meaning, so IDA restarts there.
void IdaIntegrator::Impl::reselect_constraints(double t) {
  LIMBER_DEMAND(IDAGetDky(ida, t, 0, y) == IDA_SUCCESS);
  const Eigen::VectorXd q_now = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), nq);
  if (system->reselect_constraints(t, q_now)) restart(t);
}

// The events located at t_reached switch their modes; IDA restarts there.
void IdaIntegrator::Impl::apply_pending_events() {
  if (pending_events.empty()) return;
  LIMBER_DEMAND(IDAGetDky(ida, t_reached, 0, y) == IDA_SUCCESS);
  const Eigen::VectorXd q_now = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), nq);
  const Eigen::VectorXd v_now = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y) + iv, nv);
  for (const int k : pending_events) system->apply_event(k, t_reached, q_now, v_now);
  pending_events.clear();
  restart(t_reached);
}

// IDA stops just before the next velocity breakpoint (half the time tolerance), else at
// t_stop. A step ending on the breakpoint itself would meet the rate after the jump (drivers'
// derivatives are right-continuous) with the velocities before it, and Newton fails there
// at any step size (a kinked table driver died at t = 0.05 s with h = 1e-18).
void IdaIntegrator::Impl::set_stop_time() {
  const double stop =
      next_breakpoint < breakpoints.size()
          ? breakpoints[next_breakpoint] - 0.5 * time_tolerance(breakpoints[next_breakpoint])
          : options.t_stop;
  if (std::isfinite(stop)) LIMBER_DEMAND(IDASetStopTime(ida, stop) == IDA_SUCCESS);
}

// At a velocity breakpoint (IDA stopped there): restart with v after the jump and the
// integrals' jump (mechanical_system.h, velocity_breakpoints).
void IdaIntegrator::Impl::apply_breakpoint() {
  if (next_breakpoint >= breakpoints.size() ||
      t_reached < breakpoints[next_breakpoint] - time_tolerance(t_reached)) {
    return;
  }
  restart(breakpoints[next_breakpoint++], true);
}

// Restart at t (inside the last step, or at a velocity breakpoint just after it) at order 1,
// from the current step size, with λ, v̇ from the saddle-point system and μ = 0; q, v and
// the integrals carry over (across a breakpoint, `jump`, with the integrals' jump added).
void IdaIntegrator::Impl::restart(double t, bool jump) {
  // IDA interpolates only within its last step: the state at a breakpoint is the one IDA
  // reached, half a time tolerance before it.
  const double t_state = std::min(t, t_reached);
  LIMBER_DEMAND(IDAGetDky(ida, t_state, 0, y) == IDA_SUCCESS);
  LIMBER_DEMAND(IDAGetDky(ida, t_state, 1, yp) == IDA_SUCCESS);
  double h_last = 0.0;
  IDAGetLastStep(ida, &h_last);
  restart_from_y(t, h_last, jump);
}

// The same from the state in y (its y' recomputed), first step h0.
void IdaIntegrator::Impl::restart_from_y(double t, double h0, bool jump) {
  Eigen::Map<Eigen::VectorXd> y_now(N_VGetArrayPointer(y), n);
  Eigen::VectorXd q_now = y_now.head(nq);
  // Rows that come in after a reselection were held only through ill-conditioned
  // combinations of the old ones: project q and v onto them, or IDA restarts from a state
  // off its algebraic equations and fails its error test down to h ~ 1e-10.
  Eigen::VectorXd v_now = y_now.segment(iv, nv);
  Eigen::VectorXd vdot_now, lambda_now;
  // A failed projection or solve keeps IDA's values; its next step then reports the trouble.
  const Eigen::VectorXd v_before = v_now;
  if (project_initial_state(*system, t, q_now, v_now).ok() &&
      solve_accelerations(*system, t, q_now, v_now, vdot_now, lambda_now).ok()) {
    if (jump && nz > 0 && options.quadrature.jump) {
      options.quadrature.jump(t, q_now, v_before, v_now, f);
      y_now.segment(iz, nz) += f;
    }
    load_state(t, q_now, v_now, vdot_now, lambda_now);
  }
  reinit(t, h0);
}

// y = [q, v, λ, 0, z], y' = [N v, v̇, 0, 0, f] at t (z as it stands in y).
void IdaIntegrator::Impl::load_state(double t, const Eigen::VectorXd& q_now, const Eigen::VectorXd& v_now,
                                     const Eigen::VectorXd& vdot_now, const Eigen::VectorXd& lambda_now) {
  Eigen::Map<Eigen::VectorXd> y_now(N_VGetArrayPointer(y), n);
  Eigen::Map<Eigen::VectorXd> yp_now(N_VGetArrayPointer(yp), n);
  y_now.head(nq) = q_now;
  y_now.segment(iv, nv) = v_now;
  y_now.segment(ilambda, nc) = lambda_now;
  y_now.segment(imu, nc + nh).setZero();
  system->kinematic_matrix(q_now, N);
  yp_now.head(nq) = N * v_now;
  yp_now.segment(iv, nv) = vdot_now;
  yp_now.segment(ilambda, 2 * nc + nh).setZero();
  if (nz > 0) {
    options.quadrature.integrand(t, q_now, v_now, vdot_now, lambda_now, f);
    yp_now.segment(iz, nz) = f;
  }
}

// IDA restarted at t from y, y' at order 1, first step h0 (IDA's choice when 0).
void IdaIntegrator::Impl::reinit(double t, double h0) {
  Statistics totals;
  read_statistics(totals, restart_statistics);
  restart_statistics = totals;
  difference_evaluations_at_restart = equations->difference_evaluations();
  difference_due = true;
  failures_at_difference = 0;
  LIMBER_DEMAND(IDAReInit(ida, t, y, yp) == IDA_SUCCESS);
  t_reached = t;
  if (h0 > 0.0) LIMBER_DEMAND(IDASetInitStep(ida, h0) == IDA_SUCCESS);
  set_stop_time();
}

// After a corrector failure: λ's Newton weight loosened (kLambdaRelaxation) and IDA
// restarted from the state it reached with its last step (the first step at t0, where IDA
// has taken none). False when the relaxations are spent or there is no λ.
bool IdaIntegrator::Impl::relax_multiplier_weight() {
  if (lambda_relaxations >= kMaxLambdaRelaxations || nc == 0) return false;
  ++lambda_relaxations;
  LIMBER_DEMAND(IDAGetDky(ida, t_reached, 0, y) == IDA_SUCCESS);
  Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(atol_vec), n);
  atol.segment(ilambda, nc) *= kLambdaRelaxation;
  LIMBER_DEMAND(apply_error_weights() == IDA_SUCCESS);
  double h_last = 0.0;
  IDAGetLastStep(ida, &h_last);
  restart_from_y(t_reached, h_last > 0.0 ? h_last : first_step);
  return true;
}

// After a failed step (or a struggling one): at a singular configuration (the held rows' rank
// margin below near_ratio of the start's), restart past it, or on other rows where they hold
// (singular_step_over.h). Returns nullopt when not at one (the caller reports IDA's failure),
// else success or the failure naming it.
std::optional<Status> IdaIntegrator::Impl::step_over_singular_configuration(double near_ratio) {
  LIMBER_DEMAND(IDAGetDky(ida, t_reached, 0, y) == IDA_SUCCESS);
  Eigen::Map<Eigen::VectorXd> y_now(N_VGetArrayPointer(y), n);
  const double limit = next_breakpoint < breakpoints.size() ? breakpoints[next_breakpoint] : options.t_stop;
  const StepOverOutcome over =
      step_overs.step_over(*system, options.quadrature, t_reached, y_now.head(nq), y_now.segment(iv, nv),
                           y_now.segment(iz, nz), limit, "IDA's corrector failed", near_ratio);
  if (over.kind == StepOverOutcome::kNotSingular) return std::nullopt;
  if (over.kind == StepOverOutcome::kRowsReselected) restart(t_reached);
  if (over.kind != StepOverOutcome::kSteppedOver) return over.status;
  const SteppedOverStretch& stretch = step_overs.stretch();
  y_now.segment(iz, nz) = stretch.z1;
  load_state(stretch.t1, stretch.q1, stretch.v1, stretch.vdot1, stretch.lambda1);
  reinit(stretch.t1, 0.1 * (stretch.t1 - stretch.t0));
  jumped = true;
  return over.status;
}

// After IDASolve failed with `flag`: true when IDA goes on (restarted past a singular
// configuration, or on other rows, or with λ's weight loosened), else false with the failure.
bool IdaIntegrator::Impl::recover_from_failure(int flag) {
  // At a singular configuration: restart past it, or stop naming it.
  if (const std::optional<Status> over = step_over_singular_configuration()) {
    if (over->ok()) return true;
    failed = true;
    failure = *over;
    return false;
  }
  // Elsewhere, a corrector that cannot converge λ to its weight: loosen it and go on.
  if (flag == IDA_CONV_FAIL && relax_multiplier_weight()) return true;
  double t_fail = t_reached;
  IDAGetCurrentTime(ida, &t_fail);
  failed = true;
  failure = {status_code_of_ida_flag(flag), t_fail,
             fmt::format("at t = {:.6g} s: IDA failed with flag {} ({}{})", t_fail, flag, last_message,
                         flag == IDA_CONV_FAIL && lambda_relaxations > 0
                             ? fmt::format("; the multipliers' Newton weight loosened {} times before",
                                           lambda_relaxations)
                             : "")};
  return false;
}
}  // namespace limber::integrate
