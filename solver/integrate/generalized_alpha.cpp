#include "integrate/generalized_alpha.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "integrate/consistent_state.h"
#include "integrate/singular_test.h"

namespace limber::integrate {

double GeneralizedAlpha::time_tolerance(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }
namespace {

// Newton contraction rate above which a reused iteration matrix is rebuilt.
constexpr double kRefreshRate = 0.1;
// Accepted steps after which the iteration matrix is rebuilt anyway (IDA uses 20 as well).
constexpr int kMaxJacobianAge = 20;
// The same for a sparse system (a nonlinear body): its coupled stiffness turns with the body
// (translations in ground axes), so a kept matrix slows Newton within a few steps, and a fresh
// structured one costs about three residuals. On the seed set-up with the nonlinear rod (1 s,
// h = 1e-4 s): rebuilt after 20 steps (or when Newton slows) 6.1 Newton iterations per step,
// 9.3 s CPU; after 3: 4.8, 8.8 s; after 2: 4.1, 8.1 s; every step: 3.0, 9.2 s.
constexpr int kMaxSparseJacobianAge = 2;
// Steps shorter than this fraction of the nominal step (cut back to an event, or ending just
// after one on the way back to the grid) are not shown to IntegratorOptions::on_step nor to
// MechanicalSystem::step_accepted: their v̇ and λ carry the position round-off amplified by
// 1/(βh²) (see the header). Measured on the
// satellite deployment: the step locating the second of two latches 1e-9 s apart gave joint
// reactions of 1e5 N against 80 N. At 1 % of h the amplification is 1e4 times that of a full
// step (2.6e-5 m/s² at h = 0.5 ms).
constexpr double kObservedStepFraction = 0.01;
// Contraction rate above which increments at the round-off level count as stalled.
constexpr double kSlowRate = 0.5;
// Newton increments below this multiple of ε times the size of what they correct are round-off;
// the larger bound applies once the increments have stopped shrinking (stalled in the noise).
constexpr double kRoundoff = 10.0 * std::numeric_limits<double>::epsilon();
constexpr double kRoundoffStall = 1e3 * std::numeric_limits<double>::epsilon();

}  // namespace

GeneralizedAlphaCoefficients GeneralizedAlphaCoefficients::from_rho_inf(double rho_inf) {
  // Chung & Hulbert 1993: α_m, α_f from ρ∞, second-order γ and the β that maximises damping.
  GeneralizedAlphaCoefficients c;
  c.alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
  c.alpha_f = rho_inf / (rho_inf + 1.0);
  c.gamma = 0.5 + c.alpha_f - c.alpha_m;
  c.beta = 0.25 * (c.gamma + 0.5) * (c.gamma + 0.5);
  return c;
}

Status GeneralizedAlpha::init(MechanicalSystem& system, const InitialState& x0,
                              const IntegratorOptions& options) {
  options.validate();
  LIMBER_DEMAND(options.method == Method::kGeneralizedAlpha);
  if (x0.q.size() != system.nq() || x0.v.size() != system.nv()) {
    throw InputError(fmt::format("initial state: expected {} coordinates and {} velocities, got "
                                 "{} and {}",
                                 system.nq(), system.nv(), x0.q.size(), x0.v.size()));
  }
  system_ = &system;
  options_ = options;
  coef_ = GeneralizedAlphaCoefficients::from_rho_inf(options.rho_inf);
  nv_ = system.nv();
  nc_ = system.nc();
  window_end_ = -std::numeric_limits<double>::infinity();
  open_event_window(x0.t);
  failed_ = false;
  stats_ = {};
  budget_.start(options.max_wall_seconds);
  largest_increment_ = {};
  largest_error_ = {};
  jacobian_h_ = 0.0;
  J_.resize(nv_ + nc_, nv_ + nc_);
  has_structure_ = system.diagonal_stiffness_damping(stiffness_, damping_);
  sparse_ = system.sparse();
  slots_valid_ = false;
  structured_pause_ = 0;

  // Consistent start: projected q, v; v̇ and λ from the saddle-point system; a_0 = v̇_0.
  curr_.t = x0.t;
  curr_.q = x0.q;
  curr_.v = x0.v;
  Status status = project_initial_state(system, x0.t, curr_.q, curr_.v);
  if (status.ok()) status = solve_accelerations(system, x0.t, curr_.q, curr_.v, curr_.vdot,
                                                curr_.lambda);
  if (!status.ok()) {
    failed_ = true;
    failure_ = status;
    return status;
  }
  step_overs_.start(system, x0.t, curr_.q);
  curr_.a = curr_.vdot;
  curr_.integrals = Eigen::VectorXd::Zero(options.quadrature.size);
  evaluate_integrand(curr_);
  system.event_functions(curr_.t, curr_.q, curr_.v, curr_.events);
  pending_events_.clear();
  breakpoints_.clear();
  next_breakpoint_ = 0;
  for (const double t : system.velocity_breakpoints()) {
    if (t > x0.t + time_tolerance(x0.t) && t < options.t_stop - time_tolerance(options.t_stop)) {
      breakpoints_.push_back(t);
    }
  }
  prev_ = curr_;
  xi_last_ = Eigen::VectorXd::Zero(nv_);
  system.step_accepted(curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
  if (options_.on_step) options_.on_step(curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
  return Status::success(x0.t);
}

Status GeneralizedAlpha::advance_to(double t_out, Sample& out) {
  LIMBER_DEMAND(system_ != nullptr);
  if (failed_) return failure_;
  // (A stretch stepped over serves the samples inside it.)
  const SteppedOverStretch* stretch = step_overs_.holding(t_out);
  const double t_earliest = stretch != nullptr ? stretch->t0 : prev_.t;
  if (t_out < t_earliest - time_tolerance(t_out) || t_out > options_.t_stop + time_tolerance(t_out)) {
    throw InputError(fmt::format("output time: expected {} ≤ t ≤ {}, got {}", t_earliest,
                                 options_.t_stop, t_out));
  }
  // Step until the last step ends at or after t_out.
  while (curr_.t < t_out - time_tolerance(t_out)) {
    const Status status = take_step();
    // New equations at an event: the state there, and this integrator ends.
    if (status.code == StatusCode::kRestartDue) {
      interpolate(curr_.t, out);
      failed_ = true;
      failure_ = status;
    }
    if (!status.ok()) return status;
  }
  if ((stretch = step_overs_.holding(t_out)) != nullptr) {
    stretch->serve(*system_, t_out, out);
    out.statistics = stats_;
    return Status::success(t_out);
  }
  interpolate(t_out, out);
  return Status::success(t_out);
}

Status GeneralizedAlpha::accept_step(double h) {
  if (const Status status = locate_events(h); !status.ok()) return status;
  stats_.last_step = next_.t - curr_.t;
  if (structured_pause_ > 0) --structured_pause_;
  step_overs_.accepted_step();
  prev_ = std::move(curr_);
  curr_ = next_;
  ++stats_.steps;
  estimate_local_error();
  if (stats_.last_step >= kObservedStepFraction * grid_step_) {
    system_->step_accepted(curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
    if (options_.on_step) options_.on_step(curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
  }
  return Status::success(curr_.t);
}

Status GeneralizedAlpha::check_budgets() {
  if (budget_.spent()) {
    return failure(StatusCode::kWallClock,
                   fmt::format("the wall-clock budget of {:g} s is spent", options_.max_wall_seconds));
  }
  if (stats_.steps > options_.max_steps) {
    return failure(StatusCode::kTooManySteps, fmt::format("more than {} steps", options_.max_steps));
  }
  return Status::success(curr_.t);
}

Status GeneralizedAlpha::take_step() {
  if (const Status status = apply_pending_events(); !status.ok()) return status;
  if (system_->restart_due()) {
    return {StatusCode::kRestartDue, curr_.t, fmt::format("at t = {:.6g} s: the equations change", curr_.t)};
  }
  if (const Status status = apply_breakpoint(); !status.ok()) return status;
  if (const Status status = reselect_constraints(); !status.ok()) return status;
  // The next grid point (or the end of the event window), or the next velocity breakpoint
  // when it comes first.
  const double grid_end = grid_in_window_ ? std::min(window_end_, options_.t_stop) : options_.t_stop;
  const double grid_target =
      std::min(grid_origin_ + static_cast<double>(grid_index_ + 1) * grid_step_, grid_end);
  const double target = next_breakpoint_ < breakpoints_.size()
                            ? std::min(grid_target, breakpoints_[next_breakpoint_])
                            : grid_target;
  for (;;) {
    const double h = std::min(h_try_, target - curr_.t);
    const Attempt attempt = attempt_step(h);
    if (attempt == Attempt::kAccepted) {
      if (const Status status = accept_step(h); !status.ok()) return status;
      // On the target: snap the time; back on the grid, restore its step, and at the end of
      // an event window go on with the step.
      if (target - curr_.t <= time_tolerance(target)) {
        curr_.t = target;
        if (grid_target - target <= time_tolerance(target)) {
          ++grid_index_;
          h_try_ = grid_step_;
          halvings_ = 0;
          if (grid_in_window_ && !in_event_window(curr_.t)) start_grid(curr_.t);
        }
      }
      return check_budgets();
    }
    if (attempt == Attempt::kStaleJacobian) {
      ++stats_.rejected_steps;
      ++stats_.newton_failures;
      continue;
    }
    if (attempt == Attempt::kSingular && !stepped_over_) {
      // The step ends on a singular configuration (a linkage with its links collinear at a
      // grid point): step over it with a step half as long again, then back to the grid.
      ++stats_.rejected_steps;
      stepped_over_ = true;
      h_try_ = 1.5 * h;
      const Attempt over = attempt_step(h_try_);
      if (over == Attempt::kAccepted) {
        if (const Status status = accept_step(h_try_); !status.ok()) return status;
        grid_index_ = static_cast<long>(std::floor((curr_.t - grid_origin_) / grid_step_ + 1e-9));
        h_try_ = grid_step_;
        halvings_ = 0;
        stepped_over_ = false;
        if (grid_in_window_ && !in_event_window(curr_.t)) start_grid(curr_.t);
        return check_budgets();
      }
      h_try_ = h;
    }
    stepped_over_ = false;
    if (attempt == Attempt::kSingular) {
      const std::string why = fmt::format("the iteration matrix of a step h = {:.4g} s is singular "
                                          "(dependent constraints or a singular mass matrix)", h);
      if (const std::optional<Status> over = step_over_singular_configuration(why)) return *over;
      return failure(StatusCode::kSingularJacobian, why);
    }
    // A failed Newton iteration rejects the step: retry with h/2 a bounded number of times.
    ++stats_.rejected_steps;
    ++stats_.newton_failures;
    if (halvings_ == options_.max_step_halvings) {
      if (attempt == Attempt::kNaN) {
        return failure(StatusCode::kNaN,
                       fmt::format("the model returned non-finite values in a step h = {:.4g} s "
                                   "(after {} halvings)", h, halvings_));
      }
      const std::string why = fmt::format("Newton did not converge (at most {} iterations) in a step "
                                          "h = {:.4g} s (after {} halvings)",
                                          options_.max_newton_iterations, h, halvings_);
      if (const std::optional<Status> over = step_over_singular_configuration(why)) return *over;
      return failure(StatusCode::kConvergenceFailures, why);
    }
    h_try_ = 0.5 * h;
    ++halvings_;
  }
}

GeneralizedAlpha::Attempt GeneralizedAlpha::attempt_step(double h) {
  const auto& [alpha_m, alpha_f, beta, gamma] = coef_;
  const double bh2 = beta * h * h;
  next_.t = curr_.t + h;

  // Predictor: v̇ and λ extrapolated linearly from the last step (held at the first), a from
  // the α relation, ξ from the Newmark formula.
  const double previous_h = curr_.t - prev_.t;
  const double ratio = previous_h > 0.0 ? h / previous_h : 0.0;
  const Eigen::VectorXd vdot_pred = curr_.vdot + ratio * (curr_.vdot - prev_.vdot);
  const Eigen::VectorXd a_pred =
      (alpha_f * curr_.vdot - alpha_m * curr_.a + (1.0 - alpha_f) * vdot_pred) / (1.0 - alpha_m);
  Eigen::VectorXd xi = h * curr_.v + h * h * (0.5 - beta) * curr_.a + bh2 * a_pred;
  Eigen::VectorXd lambda_scaled =
      bh2 * (curr_.lambda + ratio * (curr_.lambda - prev_.lambda));
  Eigen::VectorXd r(nv_ + nc_), delta(nv_ + nc_);
  end_of_step_kinematics(h, xi, next_);
  scaled_residual(h, next_, lambda_scaled, r);

  // Iteration matrices: the structured one first (no residual), rebuilt once when Newton slows
  // down with it; then differences, which pause the structured one for kMaxJacobianAge steps.
  // `fresh`: a matrix of differences built in this attempt, the last resort.
  bool fresh = false, fresh_structured = false;
  const auto rebuild = [&]() {
    if (has_structure_ && structured_pause_ == 0 && !fresh_structured) {
      fresh_structured = true;
      if (build_structured_jacobian(h)) return true;
    }
    if (jacobian_structured_) structured_pause_ = kMaxJacobianAge;
    fresh = true;
    return refresh_jacobian(h, xi, lambda_scaled, r);
  };
  // Reuse the iteration matrix of the previous step when it was built for this h (up to the
  // round-off of t_{n+1} − t_n).
  if (!(std::abs(jacobian_h_ - h) <= 1e-9 * h) ||
      jacobian_age_ >= (sparse_ && jacobian_structured_ ? kMaxSparseJacobianAge : kMaxJacobianAge)) {
    if (!r.allFinite()) return Attempt::kNaN;
    if (!rebuild()) return Attempt::kSingular;
  }

  // Newton iteration on (ξ, βh²λ).
  double previous_norm = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < options_.max_newton_iterations; ++iteration) {
    if (!r.allFinite()) return Attempt::kNaN;
    solve_iteration_matrix(r, delta);
    xi += delta.head(nv_);
    lambda_scaled += delta.tail(nc_);
    ++stats_.newton_iterations;
    end_of_step_kinematics(h, xi, next_);
    // Converged when the increment is below the tolerance, or when the increments have
    // stalled at the round-off level.
    const double norm = delta.lpNorm<Eigen::Infinity>();
    const double rate = norm / previous_norm;
    const bool done = converged(xi, lambda_scaled, delta, kRoundoff) ||
                      (rate > kSlowRate && converged(xi, lambda_scaled, delta, kRoundoffStall));
    if (!done || !next_.q.allFinite()) {
      // Not converged: rebuild a reused matrix when Newton slows down or diverges.
      previous_norm = norm;
      scaled_residual(h, next_, lambda_scaled, r);
      if (!r.allFinite()) return Attempt::kNaN;
      if (rate >= 1.0 && fresh) return Attempt::kNewtonFailed;
      if (rate > kRefreshRate && !fresh) {
        if (!rebuild()) return Attempt::kSingular;
        previous_norm = std::numeric_limits<double>::infinity();
      }
      continue;
    }

    // Converged: complete the end-of-step state.
    next_.lambda = lambda_scaled / bh2;
    if (!next_.v.allFinite() || !next_.vdot.allFinite() || !next_.lambda.allFinite()) {
      return Attempt::kNaN;
    }
    evaluate_integrand(next_);
    next_.integrals = curr_.integrals + 0.5 * h * (curr_.integrand + next_.integrand);
    xi_last_ = xi;
    ++jacobian_age_;
    return Attempt::kAccepted;
  }
  // Out of iterations: a reused or structured matrix gets one more chance with the same h, on
  // differences.
  if (!fresh) {
    if (jacobian_structured_) structured_pause_ = kMaxJacobianAge;
    jacobian_h_ = 0.0;
    return Attempt::kStaleJacobian;
  }
  return Attempt::kNewtonFailed;
}

void GeneralizedAlpha::estimate_local_error() {
  // Leading term of the position increment's local error, (β − 1/6) h² (a_{n+1} − a_n)
  // (Zienkiewicz & Xie 1991); its largest value over the run against the run's largest
  // increment ξ, so that a start from rest (tiny increments) does not inflate it.
  const double h = curr_.t - prev_.t;
  const double beta = coef_.beta;
  const Eigen::VectorXd xi = h * prev_.v + h * h * ((0.5 - beta) * prev_.a + beta * curr_.a);
  const int regime = grid_in_window_ ? 1 : 0;
  largest_increment_[regime] = std::max(largest_increment_[regime], xi.norm());
  largest_error_[regime] =
      std::max(largest_error_[regime], std::abs(beta - 1.0 / 6.0) * h * h * (curr_.a - prev_.a).norm());
  stats_.max_local_error = 0.0;
  for (int k = 0; k < 2; ++k) {
    if (largest_increment_[k] > 0.0) {
      stats_.max_local_error = std::max(stats_.max_local_error, largest_error_[k] / largest_increment_[k]);
    }
  }
}

bool GeneralizedAlpha::converged(const Eigen::VectorXd& xi, const Eigen::VectorXd& lambda_scaled,
                                 const Eigen::VectorXd& delta, double roundoff) const {
  // ξ: relative to the step's displacement, with a floor at the round-off of q ⊕ ξ.
  const double tol = options_.newton_tolerance;
  const double xi_floor = roundoff * (1.0 + curr_.q.lpNorm<Eigen::Infinity>());
  const bool xi_converged =
      delta.head(nv_).lpNorm<Eigen::Infinity>() <= tol * xi.lpNorm<Eigen::Infinity>() + xi_floor;
  if (!xi_converged) return false;
  // λ̃ through the force Gᵀλ̃ it applies (M, G of eval_, the last evaluation), relative to that
  // force, with the floor the ξ round-off causes in the O(1)-conditioned scaled system (a
  // pass over M, needed only when the relative test alone fails: the floor is ≥ 0).
  const double force_change = (eval_.G.transpose() * delta.tail(nc_)).lpNorm<Eigen::Infinity>();
  const double force = (eval_.G.transpose() * lambda_scaled).lpNorm<Eigen::Infinity>();
  return force_change <= tol * force || force_change <= tol * force + largest_mass_entry() * xi_floor;
}

void GeneralizedAlpha::end_of_step_kinematics(double h, const Eigen::VectorXd& xi,
                                              StepState& s) const {
  const auto& [alpha_m, alpha_f, beta, gamma] = coef_;
  // a from the Newmark position formula, then v, v̇ and q (Arnold & Brüls 2007, eq. (9)).
  s.a = (xi / (h * h) - curr_.v / h - (0.5 - beta) * curr_.a) / beta;
  s.v = curr_.v + h * (1.0 - gamma) * curr_.a + h * gamma * s.a;
  s.vdot = ((1.0 - alpha_m) * s.a + alpha_m * curr_.a - alpha_f * curr_.vdot) / (1.0 - alpha_f);
  system_->integrate_coordinates(curr_.q, xi, s.q);
}

void GeneralizedAlpha::scaled_residual(double h, const StepState& s,
                                       const Eigen::VectorXd& lambda_scaled, Eigen::VectorXd& r) {
  const double bh2 = coef_.beta * h * h;
  ++stats_.residual_evaluations;
  system_->evaluate(s.t, s.q, s.v, false, eval_);
  if (sparse_) {
    r.head(nv_).noalias() = bh2 * (eval_.M_sparse * s.vdot - eval_.Q);
  } else {
    r.head(nv_).noalias() = bh2 * (eval_.M * s.vdot - eval_.Q);
  }
  r.head(nv_).noalias() += eval_.G.transpose() * lambda_scaled;
  r.tail(nc_) = eval_.g;
}

void GeneralizedAlpha::evaluate_integrand(StepState& s) const {
  s.integrand.resize(options_.quadrature.size);
  if (options_.quadrature.size > 0) {
    options_.quadrature.integrand(s.t, s.q, s.v, s.vdot, s.lambda, s.integrand);
  }
}

void GeneralizedAlpha::interpolate(double t_out, Sample& out) const {
  const double h = curr_.t - prev_.t;
  const double theta = h > 0.0 ? std::clamp((t_out - prev_.t) / h, 0.0, 1.0) : 1.0;
  // Cubic Hermite tangent displacement: Δ(0) = 0, Δ(1) = ξ, slopes h v_n and h v_{n+1}.
  const double t2 = theta * theta;
  const double t3 = t2 * theta;
  const Eigen::VectorXd displacement = (t3 - 2.0 * t2 + theta) * h * prev_.v +
                                       (3.0 * t2 - 2.0 * t3) * xi_last_ + (t3 - t2) * h * curr_.v;
  out.t = t_out;
  system_->integrate_coordinates(prev_.q, displacement, out.q);
  // Everything else linearly.
  out.v = (1.0 - theta) * prev_.v + theta * curr_.v;
  out.vdot = (1.0 - theta) * prev_.vdot + theta * curr_.vdot;
  out.lambda = (1.0 - theta) * prev_.lambda + theta * curr_.lambda;
  out.integrals = (1.0 - theta) * prev_.integrals + theta * curr_.integrals;
  out.statistics = stats_;
}

Status GeneralizedAlpha::failure(StatusCode code, const std::string& why) {
  failed_ = true;
  failure_ = {code, curr_.t, fmt::format("at t = {:.6g} s: {}", curr_.t, why)};
  if (code == StatusCode::kConvergenceFailures || code == StatusCode::kSingularJacobian) {
    const double ratio = held_rows_margin(*system_, curr_.t, curr_.q) / step_overs_.margin_start();
    if (ratio < kNearSingularRatio) failure_.message = singular_failure_message(curr_.t, ratio, why);
  }
  return failure_;
}

}  // namespace limber::integrate
