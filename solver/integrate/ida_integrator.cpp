#include "integrate/ida_integrator.h"
#include "integrate/wall_clock_budget.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "core/error.h"
#include "integrate/combined_statistics.h"
#include "integrate/consistent_state.h"
#include "integrate/dense_lu_solver.h"
#include "integrate/ggl_equations.h"
#include "integrate/ida_first_step.h"
#include "integrate/ida_status.h"
#include "integrate/singular_step_over.h"

namespace limber::integrate {
namespace {

double time_tolerance(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }

// Fraction of rtol × the largest starting multiplier below which λ's Newton weight does not go.
constexpr double kLambdaWeight = 0.01;

// After IDA's corrector fails away from any singular configuration, λ's Newton weight is
// loosened by kLambdaRelaxation and IDA restarts from the last state reached, at most
// kMaxLambdaRelaxations times in a run. λ carries the round-off of v̇ (ε/h), so the weight
// above asks for digits that small steps cannot give at rtol 1e-10: Bricard's linkage
// (tests/run/data) failed at t = 0 with atol 1e-12 and at t = 0.8 s with atol 1e-10, each
// with h ~ 1e-13; the parallelogram failed at t = 8e-6 s. Runs that did not fail are unchanged.
constexpr double kLambdaRelaxation = 100.0;
constexpr int kMaxLambdaRelaxations = 3;

// Largest growth of the step from one step to the next (IDA's default 2). On a lightly damped
// elastic mode a doubled step fails its error test, IDA halves it back and doubles it again,
// so BDF1 never gets the run of equal steps it needs to raise its order: the flexible
// slider-crank at rtol 1e-6 crawled at h ≈ 5 µs for 14 ms (2 519 rejected steps); with 1.5,
// 246 rejected steps over the whole 0.3 s.
constexpr double kMaxStepGrowth = 1.5;

// Non-finite residuals IDA may recover from (by cutting the step) within one advance_to.
constexpr int kMaxNonFiniteRetries = 10;

// Rejected attempts within one accepted step within kStruggleRatio of a singular
// configuration after which IDA steps over it at once instead of crawling on to its
// corrector's failure (at rtol 1e-8 the simple parallelogram took 200 rejected steps per
// passage that way). At 0.1 the stretch stepped over, whose samples are predicted, was 10
// times longer and its samples 2e-5 m off (docs/integrators.md).
constexpr int kStruggle = 3;
constexpr double kStruggleRatio = 1e-2;

// IDA's error weights per group (IdaErrorWeights::kPerGroup), defined below.
int ida_error_weights(N_Vector y, N_Vector w, void* user_data);

}  // namespace

// The layout of y = [q, v, λ, μ, z] is the equations' (ggl_equations.h).
struct IdaIntegrator::Impl : GglLayout {
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

  SUNContext context = nullptr;
  N_Vector y = nullptr, yp = nullptr, id = nullptr, atol_vec = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver solver = nullptr;
  void* ida = nullptr;

  // Scratch space: events, y' of a restart.
  Eigen::VectorXd q, v, f;
  Eigen::MatrixXd N;

  ~Impl() { release(); }

  void release() {
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
  int residual(double t, const double* y_data, const double* yp_data, double* r_data) {
    if (equations->residual(t, y_data, yp_data, r_data)) return 0;
    return ++nonfinite_residuals <= kMaxNonFiniteRetries ? 1 : -1;
  }

  // IDA's counters since the last (re)start, added to `before` (the totals at that restart).
  void read_statistics(Statistics& stats, const Statistics& before) const {
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
    stats.residual_evaluations = value + linear_solver_residuals;
    double last_step = 0.0;
    IDAGetLastStep(ida, &last_step);
    stats.last_step = last_step;
    stats = combined(before, stats);
  }

  // New constraint rows at time t (the current step end, or a located event): the multipliers
  // change meaning, so IDA restarts there.
  void reselect_constraints(double t) {
    LIMBER_DEMAND(IDAGetDky(ida, t, 0, y) == IDA_SUCCESS);
    const Eigen::VectorXd q_now = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), nq);
    if (system->reselect_constraints(t, q_now)) restart(t);
  }

  // The events located at t_reached switch their modes; IDA restarts there.
  void apply_pending_events() {
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
  void set_stop_time() {
    const double stop =
        next_breakpoint < breakpoints.size()
            ? breakpoints[next_breakpoint] - 0.5 * time_tolerance(breakpoints[next_breakpoint])
            : options.t_stop;
    if (std::isfinite(stop)) LIMBER_DEMAND(IDASetStopTime(ida, stop) == IDA_SUCCESS);
  }

  // At a velocity breakpoint (IDA stopped there): restart with v after the jump and the
  // integrals' jump (mechanical_system.h, velocity_breakpoints).
  void apply_breakpoint() {
    if (next_breakpoint >= breakpoints.size() ||
        t_reached < breakpoints[next_breakpoint] - time_tolerance(t_reached)) {
      return;
    }
    restart(breakpoints[next_breakpoint++], true);
  }

  // Restart at t (inside the last step, or at a velocity breakpoint just after it) at order 1,
  // from the current step size, with λ, v̇ from the saddle-point system and μ = 0; q, v and
  // the integrals carry over (across a breakpoint, `jump`, with the integrals' jump added).
  void restart(double t, bool jump = false) {
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
  void restart_from_y(double t, double h0, bool jump = false) {
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

  // IDA's error weights from rtol and atol_vec, per component or per group (IdaErrorWeights).
  int set_tolerances() {
    if (options.ida_error_weights == IdaErrorWeights::kPerComponent) {
      return IDASVtolerances(ida, options.rtol, atol_vec);
    }
    return IDAWFtolerances(ida, ida_error_weights);
  }

  // After a corrector failure: λ's Newton weight loosened (kLambdaRelaxation) and IDA
  // restarted from the state it reached with its last step (the first step at t0, where IDA
  // has taken none). False when the relaxations are spent or there is no λ.
  bool relax_multiplier_weight() {
    if (lambda_relaxations >= kMaxLambdaRelaxations || nc == 0) return false;
    ++lambda_relaxations;
    LIMBER_DEMAND(IDAGetDky(ida, t_reached, 0, y) == IDA_SUCCESS);
    Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(atol_vec), n);
    atol.segment(ilambda, nc) *= kLambdaRelaxation;
    LIMBER_DEMAND(set_tolerances() == IDA_SUCCESS);
    double h_last = 0.0;
    IDAGetLastStep(ida, &h_last);
    restart_from_y(t_reached, h_last > 0.0 ? h_last : first_step);
    return true;
  }

  // y = [q, v, λ, 0, z], y' = [N v, v̇, 0, 0, f] at t (z as it stands in y).
  void load_state(double t, const Eigen::VectorXd& q_now, const Eigen::VectorXd& v_now,
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
  void reinit(double t, double h0) {
    Statistics totals;
    read_statistics(totals, restart_statistics);
    restart_statistics = totals;
    LIMBER_DEMAND(IDAReInit(ida, t, y, yp) == IDA_SUCCESS);
    t_reached = t;
    if (h0 > 0.0) LIMBER_DEMAND(IDASetInitStep(ida, h0) == IDA_SUCCESS);
    set_stop_time();
  }

  // After a failed step (or a struggling one): at a singular configuration (the held rows' rank
  // margin below near_ratio of the start's), restart past it, or on other rows where they hold
  // (singular_step_over.h). Returns nullopt when not at one (the caller reports IDA's failure),
  // else success or the failure naming it.
  std::optional<Status> step_over_singular_configuration(double near_ratio = kNearSingularRatio) {
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
  bool recover_from_failure(int flag) {
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

  // MechanicalSystem::step_accepted, then IntegratorOptions::on_step when set, with the state
  // IDA returned at t (the end of its step, or a located event): y and y' as IDASolve left them.
  void report_step(double t) const {
    const double* y_data = N_VGetArrayPointer(y);
    const double* yp_data = N_VGetArrayPointer(yp);
    const Eigen::VectorXd q_t = Eigen::Map<const Eigen::VectorXd>(y_data, nq);
    const Eigen::VectorXd v_t = Eigen::Map<const Eigen::VectorXd>(y_data + iv, nv);
    const Eigen::VectorXd vdot_t = Eigen::Map<const Eigen::VectorXd>(yp_data + iv, nv);
    const Eigen::VectorXd lambda_t = Eigen::Map<const Eigen::VectorXd>(y_data + ilambda, nc);
    system->step_accepted(t, q_t, v_t, vdot_t, lambda_t);
    if (options.on_step) options.on_step(t, q_t, v_t, vdot_t, lambda_t);
  }

  // IntegratorOptions::kPerGroup: w_i = 1 / (rtol max(|y_i|, max over y_i's group) + atol_i),
  // the groups q and v; λ, μ and z as IDASVtolerances weighs them.
  void group_error_weights(const double* y_data, double* w_data) const {
    const Eigen::Map<const Eigen::VectorXd> y_now(y_data, n);
    const Eigen::Map<const Eigen::VectorXd> atol(N_VGetArrayPointer(atol_vec), n);
    Eigen::Map<Eigen::VectorXd> w(w_data, n);
    const Eigen::VectorXd scale = y_now.cwiseAbs();
    w = (options.rtol * scale + atol).cwiseInverse();
    const double q_scale = nq > 0 ? scale.head(nq).maxCoeff() : 0.0;
    const double v_scale = nv > 0 ? scale.segment(iv, nv).maxCoeff() : 0.0;
    w.head(nq) = (options.rtol * scale.head(nq).cwiseMax(q_scale) + atol.head(nq)).cwiseInverse();
    w.segment(iv, nv) = (options.rtol * scale.segment(iv, nv).cwiseMax(v_scale) + atol.segment(iv, nv)).cwiseInverse();
  }

  // Event functions of the system at IDA's (t, y), for its root finding.
  int events(double t, const double* y_data, double* e_data) {
    q = Eigen::Map<const Eigen::VectorXd>(y_data, nq);
    v = Eigen::Map<const Eigen::VectorXd>(y_data + iv, nv);
    system->event_functions(t, q, v, e_values);
    Eigen::Map<Eigen::VectorXd>(e_data, ne) = e_values;
    return e_values.allFinite() ? 0 : -1;
  }
};

namespace {

int ida_jacobian(double t, double c_j, N_Vector y, N_Vector yp, N_Vector, SUNMatrix J,
                 void* user_data, N_Vector, N_Vector, N_Vector) {
  // 1 (recoverable) on non-finite values.
  return static_cast<IdaIntegrator::Impl*>(user_data)->equations->newton_matrix(
             t, c_j, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), SUNDenseMatrix_Data(J))
             ? 0
             : 1;
}

int ida_residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
  return static_cast<IdaIntegrator::Impl*>(user_data)->residual(t, N_VGetArrayPointer(y),
                                                                 N_VGetArrayPointer(yp),
                                                                 N_VGetArrayPointer(r));
}

int ida_error_weights(N_Vector y, N_Vector w, void* user_data) {
  static_cast<IdaIntegrator::Impl*>(user_data)->group_error_weights(N_VGetArrayPointer(y), N_VGetArrayPointer(w));
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
  s.release();
  s.system = &system;
  s.options = options;
  s.budget.start(options.max_wall_seconds);
  s.t0 = x0.t;
  s.stepped = false;
  s.failed = false;
  s.restart_statistics = {};
  s.t_reached = x0.t;
  s.pending_events.clear();
  s.rejected_before = 0;
  s.jumped = false;
  s.ne = system.num_events();
  s.breakpoints.clear();
  s.next_breakpoint = 0;
  for (const double t : system.velocity_breakpoints()) {
    if (t > x0.t + time_tolerance(x0.t) && t < options.t_stop - time_tolerance(options.t_stop)) {
      s.breakpoints.push_back(t);
    }
  }
  stats_ = {};

  // Sizes and layout of y = [q, v, λ, μ, z].
  s.equations.emplace(system, s.options.quadrature);
  static_cast<GglLayout&>(s) = s.equations->layout();
  s.f.resize(s.nz);
  s.N.resize(s.nq, s.nv);

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

  // y0 = [q, v, λ, 0, 0], y0' = [N v, v̇, 0, 0, f]; id marks q, v, z differential.
  LIMBER_DEMAND(SUNContext_Create(nullptr, &s.context) == 0);
  s.y = N_VNew_Serial(s.n, s.context);
  s.yp = N_VNew_Serial(s.n, s.context);
  s.id = N_VNew_Serial(s.n, s.context);
  Eigen::Map<Eigen::VectorXd> y(N_VGetArrayPointer(s.y), s.n);
  Eigen::Map<Eigen::VectorXd> yp(N_VGetArrayPointer(s.yp), s.n);
  Eigen::Map<Eigen::VectorXd> id(N_VGetArrayPointer(s.id), s.n);
  y.setZero();
  yp.setZero();
  id.setZero();
  y.head(s.nq) = q;
  y.segment(s.iv, s.nv) = v;
  y.segment(s.ilambda, s.nc) = lambda;
  system.kinematic_matrix(q, s.N);
  yp.head(s.nq) = s.N * v;
  yp.segment(s.iv, s.nv) = vdot;
  if (s.nz > 0) {
    options.quadrature.integrand(x0.t, q, v, vdot, lambda, s.f);
    yp.segment(s.iz, s.nz) = s.f;
  }
  id.head(s.iv + s.nv).setOnes();
  id.segment(s.iz, s.nz).setOnes();

  // IDA with a dense direct solver and the Newton matrix the options ask for: IDA's difference
  // quotient or the structured one (Impl::jacobian).
  s.ida = IDACreate(s.context);
  s.A = SUNDenseMatrix(s.n, s.n, s.context);
  // Eigen's LU with the structured matrix; SUNDIALS' own with differences: on the satellite
  // deployment (n = 280) IDA's difference quotient factorised by Eigen's LU took 2 751 steps,
  // 456 rejected, where SUNLinSol_Dense takes 2 331 and 49 (1.5 s at rtol 1e-4; not understood).
  const bool structured = options.ida_newton_matrix == IdaNewtonMatrix::kStructured;
  s.solver = structured ? make_dense_lu_solver(s.n, s.context)
                        : SUNLinSol_Dense(s.y, s.A, s.context);
  int flag = IDAInit(s.ida, ida_residual, x0.t, s.y, s.yp);
  flag = flag < 0 ? flag : IDASetUserData(s.ida, &s);
  flag = flag < 0 ? flag : IDASetErrHandlerFn(s.ida, ida_error_handler, &s);
  // μ vanishes on the exact solution; its Newton iterates carry position round-off divided by
  // the step (1e-16/h), which atol = 1e-10 would reject at small h. Its weight is therefore
  // loose (atol 1): the positions it corrects are tested with their own weights.
  s.atol_vec = N_VNew_Serial(s.n, s.context);
  Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(s.atol_vec), s.n);
  atol.setConstant(options.atol);
  atol.segment(s.imu, s.nc + s.nh).setConstant(1.0);
  // λ is out of the error test but in Newton's convergence test: its weight no tighter than
  // 1 % of rtol relative to the largest starting multiplier (an absolute atol of 1e-10 N asks a
  // kN joint force for 16 digits, which Newton cannot deliver at the start's tiny steps: the
  // seed set-up failed at t = 7e-9 s with rtol 1e-8).
  atol.segment(s.ilambda, s.nc)
      .setConstant(std::max(options.atol, kLambdaWeight * options.rtol * lambda.lpNorm<Eigen::Infinity>()));
  if (options.quadrature.atol > 0.0) atol.segment(s.iz, s.nz).setConstant(options.quadrature.atol);
  flag = flag < 0 ? flag : s.set_tolerances();
  flag = flag < 0 ? flag : IDASetLinearSolver(s.ida, s.solver, s.A);
  if (structured) flag = flag < 0 ? flag : IDASetJacFn(s.ida, ida_jacobian);
  flag = flag < 0 ? flag : IDASetId(s.ida, s.id);
  flag = flag < 0 ? flag : IDASetSuppressAlg(s.ida, SUNTRUE);
  flag = flag < 0 ? flag : IDASetMaxNumSteps(s.ida, options.max_steps);
  flag = flag < 0 ? flag : IDASetEtaMax(s.ida, kMaxStepGrowth);
  if (flag >= 0 && options.max_order > 0) flag = IDASetMaxOrd(s.ida, options.max_order);
  if (flag >= 0 && options.max_step > 0.0) flag = IDASetMaxStep(s.ida, options.max_step);
  const double h0 = options.initial_step > 0.0 ? options.initial_step
                                               : initial_step(system, {x0.t, q, v}, vdot, options);
  flag = flag < 0 ? flag : IDASetInitStep(s.ida, h0);
  s.first_step = h0;
  if (flag >= 0) s.set_stop_time();
  // Events: only rises through 0 switch a mode (mechanical_system.h).
  if (flag >= 0 && s.ne > 0) {
    flag = IDARootInit(s.ida, s.ne, ida_events);
    std::vector<int> rising(static_cast<size_t>(s.ne), 1);
    flag = flag < 0 ? flag : IDASetRootDirection(s.ida, rising.data());
    flag = flag < 0 ? flag : IDASetNoInactiveRootWarn(s.ida);
  }
  LIMBER_DEMAND(flag >= 0);
  if (options.on_step) options.on_step(x0.t, q, v, vdot, lambda);
  return Status::success(x0.t);
}

Status IdaIntegrator::advance_to(double t_out, Sample& out) {
  Impl& s = *impl_;
  LIMBER_DEMAND(s.system != nullptr);
  if (s.failed) return s.failure;
  bool restart_due = false;  // an event changed the system's equations (restart_due)
  if (t_out < s.t0 - time_tolerance(t_out) || t_out > s.options.t_stop + time_tolerance(t_out)) {
    throw InputError(fmt::format("output time: expected {} ≤ t ≤ {}, got {}", s.t0,
                                 s.options.t_stop, t_out));
  }

  // The initial time is served from y0 (IDA cannot return before its first step).
  if (s.stepped || t_out > s.t0 + time_tolerance(s.t0)) {
    s.nonfinite_residuals = 0;
    // One step at a time until past t_out, then y(t_out) from IDA's interpolating polynomial
    // (what IDA_NORMAL does); between steps events switch modes and the system may pick new
    // constraint rows. An event located past t_out is applied after t_out is served.
    while (s.t_reached < t_out - time_tolerance(t_out)) {
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
      double t_current = s.t_reached;
      const int flag = IDASolve(s.ida, t_out, &t_current, s.y, s.yp, IDA_ONE_STEP);
      s.stepped = true;
      s.t_reached = t_current;
      if (flag == IDA_ROOT_RETURN) {
        std::vector<int> found(static_cast<size_t>(s.ne), 0);
        LIMBER_DEMAND(IDAGetRootInfo(s.ida, found.data()) == IDA_SUCCESS);
        for (int k = 0; k < s.ne; ++k) {
          if (found[k] > 0) s.pending_events.push_back(k);
        }
      }
      s.read_statistics(stats_, s.restart_statistics);
      if (flag < 0) {
        if (s.recover_from_failure(flag)) continue;
        return s.failure;
      }
      s.jumped = false;
      s.step_overs.accepted_step();
      const long rejected = stats_.rejected_steps - s.rejected_before;
      s.rejected_before = stats_.rejected_steps;
      s.report_step(t_current);
      if (s.budget.spent() || stats_.steps > s.options.max_steps) {
        s.failed = true;
        s.failure = s.budget.spent()
                        ? Status{StatusCode::kWallClock, t_current,
                                 fmt::format("at t = {:.6g} s: the wall-clock budget of {:g} s is spent (last "
                                             "step {:.3g} s)",
                                             t_current, s.options.max_wall_seconds, stats_.last_step)}
                        : Status{StatusCode::kTooManySteps, t_current,
                                 fmt::format("at t = {:.6g} s: more than {} steps", t_current, s.options.max_steps)};
        return s.failure;
      }
      // Struggling near a singular configuration: step over it now (a failed try leaves IDA
      // as it was, to go on or fail on its own).
      if (rejected >= kStruggle && s.pending_events.empty()) s.step_over_singular_configuration(kStruggleRatio);
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
  }

  // Unpack y(t_out), y'(t_out).
  const double* y = N_VGetArrayPointer(s.y);
  const double* yp = N_VGetArrayPointer(s.yp);
  out.t = t_out;
  out.q = Eigen::Map<const Eigen::VectorXd>(y, s.nq);
  out.v = Eigen::Map<const Eigen::VectorXd>(y + s.iv, s.nv);
  out.vdot = Eigen::Map<const Eigen::VectorXd>(yp + s.iv, s.nv);
  out.lambda = Eigen::Map<const Eigen::VectorXd>(y + s.ilambda, s.nc);
  out.integrals = Eigen::Map<const Eigen::VectorXd>(y + s.iz, s.nz);
  out.statistics = stats_;
  if (!out.q.allFinite() || !out.v.allFinite() || !out.lambda.allFinite()) {
    s.failed = true;
    s.failure = {StatusCode::kNaN, t_out,
                 fmt::format("at t = {:.6g} s: the solution is not finite", t_out)};
    return s.failure;
  }
  if (restart_due) {
    s.failed = true;
    s.failure = {StatusCode::kRestartDue, t_out, fmt::format("at t = {:.6g} s: the equations change", t_out)};
    return s.failure;
  }
  return Status::success(t_out);
}

}  // namespace limber::integrate
