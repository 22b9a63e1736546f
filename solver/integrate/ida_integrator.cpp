// IDA set up on the GGL equations and stepped to each output time (ida_integrator.h); its
// restarts are in ida_restarts.cpp, its state and constants in ida_integrator_impl.h.
#include "integrate/ida_integrator.h"

#include <fmt/format.h>

#include "core/error.h"
#include "integrate/combined_statistics.h"
#include "integrate/consistent_state.h"
#include "integrate/dense_lu_solver.h"
#include "integrate/ida_first_step.h"
#include "integrate/ida_integrator_impl.h"

namespace limber::integrate {

namespace {

int ida_jacobian(double t, double c_j, N_Vector y, N_Vector yp, N_Vector, SUNMatrix J,
                 void* user_data, N_Vector, N_Vector, N_Vector) {
  // 1 (recoverable) on non-finite values.
  return static_cast<IdaIntegrator::Impl*>(user_data)->newton_matrix(
             t, c_j, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), SUNDenseMatrix_Data(J))
             ? 0
             : 1;
}

int ida_residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
  return static_cast<IdaIntegrator::Impl*>(user_data)->residual(t, N_VGetArrayPointer(y),
                                                                 N_VGetArrayPointer(yp),
                                                                 N_VGetArrayPointer(r));
}

// IdaErrorWeights::kPerGroup: IDA asks for the weights at each step.
int ida_error_weights(N_Vector y, N_Vector w, void* user_data) {
  static_cast<IdaIntegrator::Impl*>(user_data)->group_error_weights(N_VGetArrayPointer(y),
                                                                     N_VGetArrayPointer(w));
  return 0;
}

int ida_events(double t, N_Vector y, N_Vector, double* e, void* user_data) {
  return static_cast<IdaIntegrator::Impl*>(user_data)->events(t, N_VGetArrayPointer(y), e);
}

// Keeps IDA's message for our status instead of printing it on stderr.
void ida_error_handler(int, const char* module, const char* function, char* message,
                       void* user_data) {
  static_cast<IdaIntegrator::Impl*>(user_data)->last_message =
      fmt::format("{}:{}: {}", module, function, message);
}

}  // namespace

void IdaIntegrator::Impl::release() {
  if (ida != nullptr) IDAFree(&ida);
  if (solver != nullptr) SUNLinSolFree(solver);
  if (A != nullptr) SUNMatDestroy(A);
  if (y != nullptr) N_VDestroy(y);
  if (yp != nullptr) N_VDestroy(yp);
  if (id != nullptr) N_VDestroy(id);
  if (atol_vec != nullptr) N_VDestroy(atol_vec);
  if (context != nullptr) SUNContext_Free(&context);
  ida = nullptr;
  solver = nullptr;
  A = nullptr;
  y = yp = id = atol_vec = nullptr;
}

// F(t, y, y') (ggl_equations.h); on non-finite values returns 1 (recoverable: IDA cuts the
// step) at most kMaxNonFiniteRetries times per advance_to, then −1 (IDA_RES_FAIL).
int IdaIntegrator::Impl::residual(double t, const double* y_data, const double* yp_data, double* r_data) {
  if (equations->residual(t, y_data, yp_data, r_data)) return 0;
  return ++nonfinite_residuals <= kMaxNonFiniteRetries ? 1 : -1;
}

// IDA's counters since the last (re)start, added to `before` (the totals at that restart).
void IdaIntegrator::Impl::read_statistics(Statistics& stats, const Statistics& before) const {
  long value = 0;
  IDAGetNumSteps(ida, &value);
  stats.steps = value;
  long error_test_failures = 0;
  IDAGetNumErrTestFails(ida, &error_test_failures);
  long convergence_failures = 0;
  IDAGetNumNonlinSolvConvFails(ida, &convergence_failures);
  stats.rejected_steps = error_test_failures + convergence_failures;
  stats.newton_failures = convergence_failures;
  IDAGetNumNonlinSolvIters(ida, &value);
  stats.newton_iterations = value;
  IDAGetNumJacEvals(ida, &value);
  stats.jacobian_evaluations = value;
  long linear_solver_residuals = 0;
  IDAGetNumResEvals(ida, &value);
  IDAGetNumLinResEvals(ida, &linear_solver_residuals);
  stats.residual_evaluations = value + linear_solver_residuals + equations->difference_evaluations() -
                               difference_evaluations_at_restart;
  double last_step = 0.0;
  IDAGetLastStep(ida, &last_step);
  stats.last_step = last_step;
  stats = combined(before, stats);
}

// The structured Newton matrix (ggl_equations.h), its kept difference refreshed when due.
bool IdaIntegrator::Impl::newton_matrix(double t, double c_j, const double* y_data, const double* yp_data, double* J) {
  long failures = 0;
  IDAGetNumNonlinSolvConvFails(ida, &failures);
  const bool refresh = difference_due || failures > failures_at_difference;
  difference_due = false;
  failures_at_difference = failures;
  return equations->newton_matrix(t, c_j, y_data, yp_data, J, refresh);
}

// MechanicalSystem::step_accepted, then IntegratorOptions::on_step when set, with the state
// IDA returned at t (the end of its step, or a located event): y and y' as IDASolve left them.
void IdaIntegrator::Impl::report_step(double t) const {
  const double* y_data = N_VGetArrayPointer(y);
  const double* yp_data = N_VGetArrayPointer(yp);
  const Eigen::VectorXd q_t = Eigen::Map<const Eigen::VectorXd>(y_data, nq);
  const Eigen::VectorXd v_t = Eigen::Map<const Eigen::VectorXd>(y_data + iv, nv);
  const Eigen::VectorXd vdot_t = Eigen::Map<const Eigen::VectorXd>(yp_data + iv, nv);
  const Eigen::VectorXd lambda_t = Eigen::Map<const Eigen::VectorXd>(y_data + ilambda, nc);
  system->step_accepted(t, q_t, v_t, vdot_t, lambda_t);
  if (options.on_step) options.on_step(t, q_t, v_t, vdot_t, lambda_t);
}

// Event functions of the system at IDA's (t, y), for its root finding.
int IdaIntegrator::Impl::events(double t, const double* y_data, double* e_data) {
  q = Eigen::Map<const Eigen::VectorXd>(y_data, nq);
  v = Eigen::Map<const Eigen::VectorXd>(y_data + iv, nv);
  system->event_functions(t, q, v, e_values);
  Eigen::Map<Eigen::VectorXd>(e_data, ne) = e_values;
  return e_values.allFinite() ? 0 : -1;
}

void IdaIntegrator::Impl::start_run(MechanicalSystem& system_in, const InitialState& x0,
                                    const IntegratorOptions& options_in) {
  release();
  system = &system_in;
  options = options_in;
  budget.start(options.max_wall_seconds);
  t0 = x0.t;
  stepped = false;
  failed = false;
  restart_statistics = {};
  t_reached = x0.t;
  pending_events.clear();
  rejected_before = 0;
  jumped = false;
  difference_due = true;
  failures_at_difference = 0;
  difference_evaluations_at_restart = 0;
  ne = system->num_events();
  breakpoints.clear();
  next_breakpoint = 0;
  for (const double t : system->velocity_breakpoints()) {
    if (t > x0.t + time_tolerance(x0.t) && t < options.t_stop - time_tolerance(options.t_stop)) {
      breakpoints.push_back(t);
    }
  }
  // Sizes and layout of y = [q, v, λ, μ, z].
  equations.emplace(*system, options.quadrature);
  static_cast<GglLayout&>(*this) = equations->layout();
  f.resize(nz);
  N.resize(nq, nv);
}

void IdaIntegrator::Impl::load_initial_state(double t, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                                             const Eigen::VectorXd& vdot0, const Eigen::VectorXd& lambda0) {
  LIMBER_DEMAND(SUNContext_Create(nullptr, &context) == 0);
  y = N_VNew_Serial(n, context);
  yp = N_VNew_Serial(n, context);
  id = N_VNew_Serial(n, context);
  // y0 = [q, v, λ, 0, 0], y0' = [N v, v̇, 0, 0, f].
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), n).setZero();
  load_state(t, q0, v0, vdot0, lambda0);
  // id marks q, v, z differential.
  Eigen::Map<Eigen::VectorXd> id_now(N_VGetArrayPointer(id), n);
  id_now.setZero();
  id_now.head(iv + nv).setOnes();
  id_now.segment(iz, nz).setOnes();
}

int IdaIntegrator::Impl::set_tolerances(const Eigen::VectorXd& lambda0) {
  // μ vanishes on the exact solution; its Newton iterates carry position round-off divided by
  // the step (1e-16/h), which atol = 1e-10 would reject at small h. Its weight is therefore
  // loose (atol 1): the positions it corrects are tested with their own weights.
  atol_vec = N_VNew_Serial(n, context);
  Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(atol_vec), n);
  atol.setConstant(options.atol);
  atol.segment(imu, nc + nh).setConstant(1.0);
  // λ is out of the error test but in Newton's convergence test: its weight no tighter than
  // rtol relative to the largest starting multiplier (kLambdaWeight; an absolute atol of 1e-10 N
  // asks a kN joint force for 16 digits, which Newton cannot deliver at the start's tiny steps:
  // the seed set-up failed at t = 7e-9 s with rtol 1e-8).
  atol.segment(ilambda, nc)
      .setConstant(std::max(options.atol, kLambdaWeight * options.rtol * lambda0.lpNorm<Eigen::Infinity>()));
  if (options.quadrature.atol > 0.0) atol.segment(iz, nz).setConstant(options.quadrature.atol);
  return apply_error_weights();
}

int IdaIntegrator::Impl::apply_error_weights() {
  if (options.ida_error_weights == IdaErrorWeights::kPerComponent) {
    return IDASVtolerances(ida, options.rtol, atol_vec);
  }
  return IDAWFtolerances(ida, ida_error_weights);
}

void IdaIntegrator::Impl::group_error_weights(const double* y_data, double* w_data) const {
  const Eigen::Map<const Eigen::VectorXd> y_now(y_data, n);
  const Eigen::Map<const Eigen::VectorXd> atol(N_VGetArrayPointer(atol_vec), n);
  Eigen::Map<Eigen::VectorXd> w(w_data, n);
  const Eigen::VectorXd scale = y_now.cwiseAbs();
  w = (options.rtol * scale + atol).cwiseInverse();
  const double q_scale = nq > 0 ? scale.head(nq).maxCoeff() : 0.0;
  const double v_scale = nv > 0 ? scale.segment(iv, nv).maxCoeff() : 0.0;
  w.head(nq) = (options.rtol * scale.head(nq).cwiseMax(q_scale) + atol.head(nq)).cwiseInverse();
  w.segment(iv, nv) =
      (options.rtol * scale.segment(iv, nv).cwiseMax(v_scale) + atol.segment(iv, nv)).cwiseInverse();
}

int IdaIntegrator::Impl::configure_ida(double t, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                                       const Eigen::VectorXd& vdot0, const Eigen::VectorXd& lambda0) {
  // IDA with a dense direct solver and the Newton matrix the options ask for: IDA's difference
  // quotient or the structured one (Impl::newton_matrix).
  ida = IDACreate(context);
  A = SUNDenseMatrix(n, n, context);
  // Eigen's LU with the structured matrix; SUNDIALS' own with differences: on the satellite
  // deployment (n = 280) IDA's difference quotient factorised by Eigen's LU took 2 751 steps,
  // 456 rejected, where SUNLinSol_Dense takes 2 331 and 49 (1.5 s at rtol 1e-4; not understood).
  const bool structured = options.ida_newton_matrix == IdaNewtonMatrix::kStructured;
  solver = structured ? make_dense_lu_solver(n, context) : SUNLinSol_Dense(y, A, context);
  int flag = IDAInit(ida, ida_residual, t, y, yp);
  flag = flag < 0 ? flag : IDASetUserData(ida, this);
  flag = flag < 0 ? flag : IDASetErrHandlerFn(ida, ida_error_handler, this);
  flag = flag < 0 ? flag : set_tolerances(lambda0);
  flag = flag < 0 ? flag : IDASetLinearSolver(ida, solver, A);
  if (structured) flag = flag < 0 ? flag : IDASetJacFn(ida, ida_jacobian);
  flag = flag < 0 ? flag : IDASetId(ida, id);
  flag = flag < 0 ? flag : IDASetSuppressAlg(ida, SUNTRUE);
  flag = flag < 0 ? flag : IDASetMaxNumSteps(ida, options.max_steps);
  flag = flag < 0 ? flag : IDASetEtaMax(ida, kMaxStepGrowth);
  if (flag >= 0 && options.max_order > 0) flag = IDASetMaxOrd(ida, options.max_order);
  if (flag >= 0 && options.max_step > 0.0) flag = IDASetMaxStep(ida, options.max_step);
  first_step = options.initial_step > 0.0 ? options.initial_step
                                          : initial_step(*system, {t, q0, v0}, vdot0, options);
  flag = flag < 0 ? flag : IDASetInitStep(ida, first_step);
  if (flag >= 0) set_stop_time();
  // Events: only rises through 0 switch a mode (mechanical_system.h).
  if (flag >= 0 && ne > 0) {
    flag = IDARootInit(ida, ne, ida_events);
    std::vector<int> rising(static_cast<size_t>(ne), 1);
    flag = flag < 0 ? flag : IDASetRootDirection(ida, rising.data());
    flag = flag < 0 ? flag : IDASetNoInactiveRootWarn(ida);
  }
  return flag;
}

bool IdaIntegrator::Impl::take_step(double t_out, Statistics& stats) {
  double t_current = t_reached;
  const int flag = IDASolve(ida, t_out, &t_current, y, yp, IDA_ONE_STEP);
  stepped = true;
  t_reached = t_current;
  // Events located in this step wait for the next one (apply_pending_events).
  if (flag == IDA_ROOT_RETURN) {
    std::vector<int> found(static_cast<size_t>(ne), 0);
    LIMBER_DEMAND(IDAGetRootInfo(ida, found.data()) == IDA_SUCCESS);
    for (int k = 0; k < ne; ++k) {
      if (found[k] > 0) pending_events.push_back(k);
    }
    add_twin_events();
  }
  read_statistics(stats, restart_statistics);
  if (flag < 0) return recover_from_failure(flag);
  jumped = false;
  step_overs.accepted_step();
  const long rejected = stats.rejected_steps - rejected_before;
  rejected_before = stats.rejected_steps;
  report_step(t_current);
  // The run's limits: wall clock and steps.
  if (budget.spent() || stats.steps > options.max_steps) {
    failed = true;
    failure = budget.spent()
                  ? Status{StatusCode::kWallClock, t_current,
                           fmt::format("at t = {:.6g} s: the wall-clock budget of {:g} s is spent (last "
                                       "step {:.3g} s)",
                                       t_current, options.max_wall_seconds, stats.last_step)}
                  : Status{StatusCode::kTooManySteps, t_current,
                           fmt::format("at t = {:.6g} s: more than {} steps", t_current, options.max_steps)};
    return false;
  }
  // Struggling near a singular configuration: step over it now (a failed try leaves IDA
  // as it was, to go on or fail on its own).
  if (rejected >= kStruggle && pending_events.empty()) step_over_singular_configuration(kStruggleRatio);
  return true;
}

void IdaIntegrator::Impl::add_twin_events() {
  // e at the root (y, y' as IDASolve returned them there) and event_tolerance past it.
  const double* y_data = N_VGetArrayPointer(y);
  const double* yp_data = N_VGetArrayPointer(yp);
  q = Eigen::Map<const Eigen::VectorXd>(y_data, nq);
  v = Eigen::Map<const Eigen::VectorXd>(y_data + iv, nv);
  system->event_functions(t_reached, q, v, e_values);
  const Eigen::VectorXd e_now = e_values;
  const double tau = options.event_tolerance;
  q += tau * Eigen::Map<const Eigen::VectorXd>(yp_data, nq);
  v += tau * Eigen::Map<const Eigen::VectorXd>(yp_data + iv, nv);
  system->event_functions(t_reached + tau, q, v, e_values);
  for (int k = 0; k < ne; ++k) {
    const bool pending = std::find(pending_events.begin(), pending_events.end(), k) != pending_events.end();
    if (!pending && e_now(k) < 0.0 && e_values(k) >= 0.0) pending_events.push_back(k);
  }
}

Status IdaIntegrator::Impl::serve_sample(double t_out, bool restart_due, const Statistics& stats, Sample& out) {
  const double* y_data = N_VGetArrayPointer(y);
  const double* yp_data = N_VGetArrayPointer(yp);
  out.t = t_out;
  out.q = Eigen::Map<const Eigen::VectorXd>(y_data, nq);
  out.v = Eigen::Map<const Eigen::VectorXd>(y_data + iv, nv);
  out.vdot = Eigen::Map<const Eigen::VectorXd>(yp_data + iv, nv);
  out.lambda = Eigen::Map<const Eigen::VectorXd>(y_data + ilambda, nc);
  out.integrals = Eigen::Map<const Eigen::VectorXd>(y_data + iz, nz);
  out.statistics = stats;
  if (!out.q.allFinite() || !out.v.allFinite() || !out.lambda.allFinite()) {
    failed = true;
    failure = {StatusCode::kNaN, t_out, fmt::format("at t = {:.6g} s: the solution is not finite", t_out)};
    return failure;
  }
  if (restart_due) {
    failed = true;
    failure = {StatusCode::kRestartDue, t_out, fmt::format("at t = {:.6g} s: the equations change", t_out)};
    return failure;
  }
  return Status::success(t_out);
}

IdaIntegrator::IdaIntegrator() : impl_(std::make_unique<Impl>()) {}
IdaIntegrator::~IdaIntegrator() = default;

Status IdaIntegrator::init(MechanicalSystem& system, const InitialState& x0,
                           const IntegratorOptions& options) {
  options.validate();
  LIMBER_DEMAND(options.method == Method::kIda);
  if (x0.q.size() != system.nq() || x0.v.size() != system.nv()) {
    throw InputError(fmt::format("initial state: expected {} coordinates and {} velocities, got "
                                 "{} and {}",
                                 system.nq(), system.nv(), x0.q.size(), x0.v.size()));
  }
  Impl& s = *impl_;
  s.start_run(system, x0, options);
  stats_ = {};

  // Consistent initial state: projected q, v; v̇, λ from the saddle-point system.
  Eigen::VectorXd q = x0.q, v = x0.v, vdot, lambda;
  Status status = project_initial_state(system, x0.t, q, v);
  if (status.ok()) status = solve_accelerations(system, x0.t, q, v, vdot, lambda);
  if (!status.ok()) {
    s.failed = true;
    s.failure = status;
    return status;
  }
  s.step_overs.start(system, x0.t, q);
  system.step_accepted(x0.t, q, v, vdot, lambda);

  s.load_initial_state(x0.t, q, v, vdot, lambda);
  LIMBER_DEMAND(s.configure_ida(x0.t, q, v, vdot, lambda) >= 0);
  if (options.on_step) options.on_step(x0.t, q, v, vdot, lambda);
  return Status::success(x0.t);
}

Status IdaIntegrator::advance_to(double t_out, Sample& out) {
  Impl& s = *impl_;
  LIMBER_DEMAND(s.system != nullptr);
  if (s.failed) return s.failure;
  bool restart_due = false;  // an event changed the system's equations (restart_due)
  if (t_out < s.t0 - Impl::time_tolerance(t_out) || t_out > s.options.t_stop + Impl::time_tolerance(t_out)) {
    throw InputError(fmt::format("output time: expected {} ≤ t ≤ {}, got {}", s.t0,
                                 s.options.t_stop, t_out));
  }
  // The initial time is served from y0 (IDA cannot return before its first step).
  if (!s.stepped && t_out <= s.t0 + Impl::time_tolerance(s.t0)) return s.serve_sample(t_out, false, stats_, out);

  s.nonfinite_residuals = 0;
  // One step at a time until past t_out, then y(t_out) from IDA's interpolating polynomial
  // (what IDA_NORMAL does); between steps events switch modes and the system may pick new
  // constraint rows. An event located past t_out is applied after t_out is served.
  while (s.t_reached < t_out - Impl::time_tolerance(t_out)) {
    // (Right after a step-over IDA has no history to interpolate a restart from.)
    if (s.stepped && !s.jumped) {
      s.apply_pending_events();
      // New equations at the event: y, y' hold the state there (the restart loaded them).
      if (s.system->restart_due()) {
        t_out = s.t_reached;
        restart_due = true;
        break;
      }
      s.apply_breakpoint();
      s.reselect_constraints(s.t_reached);
    }
    if (!s.take_step(t_out, stats_)) return s.failure;
  }
  // A sample inside a stretch stepped over (before IDA's restart there).
  if (const SteppedOverStretch* stretch = restart_due ? nullptr : s.step_overs.holding(t_out)) {
    stretch->serve(*s.system, t_out, out);
    out.statistics = stats_;
    return Status::success(t_out);
  }
  // A sample on a velocity breakpoint: IDA stopped half a time tolerance before it.
  const double t_state = std::min(t_out, s.t_reached);
  if (!restart_due) {
    LIMBER_DEMAND(IDAGetDky(s.ida, t_state, 0, s.y) == IDA_SUCCESS);
    LIMBER_DEMAND(IDAGetDky(s.ida, t_state, 1, s.yp) == IDA_SUCCESS);
  }
  return s.serve_sample(t_out, restart_due, stats_, out);
}

}  // namespace limber::integrate
