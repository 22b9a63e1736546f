#include "integrate/generalized_alpha.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.h"
#include "integrate/consistent_state.h"
#include "integrate/singular_test.h"

namespace limber::integrate {
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
// after one on the way back to the grid) are not shown to IntegratorOptions::on_step: their v̇
// and λ carry the position round-off amplified by 1/(βh²) (see the header). Measured on the
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

// A compressed sparse matrix's pattern as one array: its outer, then its inner indices.
std::vector<int> sparse_pattern(const Eigen::SparseMatrix<double>& A) {
  std::vector<int> out(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  out.insert(out.end(), A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  return out;
}

// Two times closer than this (relative) are the same output time.
double time_tolerance(double t) { return 1e-12 * std::max(1.0, std::abs(t)); }

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

Status GeneralizedAlpha::init(const MechanicalSystem& system, const InitialState& x0,
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
  if (options_.on_step && stats_.last_step >= kObservedStepFraction * grid_step_) {
    options_.on_step(curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
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

Status GeneralizedAlpha::locate_events(double h) {
  if (curr_.events.size() == 0) return Status::success(next_.t);
  system_->event_functions(next_.t, next_.q, next_.v, next_.events);
  // The functions that rose through 0 in this step, and the largest of them: it crosses first.
  std::vector<int> rising;
  for (Eigen::Index k = 0; k < curr_.events.size(); ++k) {
    if (curr_.events(k) < 0.0 && next_.events(k) >= 0.0) rising.push_back(static_cast<int>(k));
  }
  if (rising.empty()) return Status::success(next_.t);
  const auto largest = [&rising](const Eigen::VectorXd& e) {
    double value = -std::numeric_limits<double>::infinity();
    for (const int k : rising) value = std::max(value, e(k));
    return value;
  };
  // Illinois bracketing of the crossing in the step size: e < 0 at h_lo, ≥ 0 at h_hi.
  double h_lo = 0.0, e_lo = largest(curr_.events);
  double h_hi = h, e_hi = largest(next_.events);
  StepState at_hi = next_;
  Eigen::VectorXd xi_hi = xi_last_;
  int side = 0;
  while (h_hi - h_lo > options_.event_tolerance) {
    // Regula falsi, kept a hundredth of the bracket inside it.
    const double width = h_hi - h_lo;
    const double h_mid =
        std::clamp(h_lo - e_lo * width / (e_hi - e_lo), h_lo + 0.01 * width, h_hi - 0.01 * width);
    ++stats_.rejected_steps;
    if (attempt_step(h_mid) != Attempt::kAccepted) {
      return failure(StatusCode::kConvergenceFailures,
                     fmt::format("Newton did not converge in a step h = {:.4g} s shortened to "
                                 "locate an event", h_mid));
    }
    system_->event_functions(next_.t, next_.q, next_.v, next_.events);
    const double e_mid = largest(next_.events);
    if (e_mid >= 0.0) {
      h_hi = h_mid;
      e_hi = e_mid;
      at_hi = next_;
      xi_hi = xi_last_;
      if (side == 1) e_lo *= 0.5;
      side = 1;
    } else {
      h_lo = h_mid;
      e_lo = e_mid;
      if (side == -1) e_hi *= 0.5;
      side = -1;
    }
  }
  // The step that ends just past the crossing; its crossing events switch before the next,
  // with those that cross within the event tolerance after it (at their rate over the step):
  // a symmetric mechanism's twin latches switch together, not one a step of ~1e-9 s later,
  // whose index-3 multipliers would carry the position round-off over β h² (kN spikes in the
  // satellite's event peaks).
  next_ = std::move(at_hi);
  xi_last_ = xi_hi;
  const double h_crossing = next_.t - curr_.t;
  for (const int k : rising) {
    const double rate = (next_.events(k) - curr_.events(k)) / h_crossing;
    if (next_.events(k) + rate * options_.event_tolerance >= 0.0) pending_events_.push_back(k);
  }
  return Status::success(next_.t);
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

void GeneralizedAlpha::open_event_window(double t) {
  if (options_.event_step > 0.0 && options_.event_window > 0.0) window_end_ = t + options_.event_window;
  start_grid(t);
}

void GeneralizedAlpha::start_grid(double t) {
  grid_in_window_ = in_event_window(t);
  grid_origin_ = t;
  grid_index_ = 0;
  grid_step_ = grid_in_window_ ? options_.event_step : options_.step;
  h_try_ = grid_step_;
  halvings_ = 0;
}

bool GeneralizedAlpha::in_event_window(double t) const { return t < window_end_ - time_tolerance(t); }

Status GeneralizedAlpha::apply_pending_events() {
  if (pending_events_.empty()) return Status::success(curr_.t);
  for (const int k : pending_events_) system_->apply_event(k, curr_.t, curr_.q, curr_.v);
  pending_events_.clear();
  // New force law: consistent v̇ and λ, a = v̇, no extrapolation across the switch, and a
  // fresh iteration matrix; the integrals carry on with the new integrand.
  const Status status =
      solve_accelerations(*system_, curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
  if (!status.ok()) {
    return failure(status.code, fmt::format("after an event, the accelerations could not be "
                                            "solved: {}", status.message));
  }
  restart_at_current();
  // Without event windows the scheme returns to its grid; with them a window opens here.
  if (options_.event_step > 0.0 && options_.event_window > 0.0) open_event_window(curr_.t);
  return Status::success(curr_.t);
}

void GeneralizedAlpha::restart_at_current() {
  curr_.a = curr_.vdot;
  evaluate_integrand(curr_);
  system_->event_functions(curr_.t, curr_.q, curr_.v, curr_.events);
  prev_ = curr_;
  xi_last_.setZero();
  jacobian_h_ = 0.0;
}

Status GeneralizedAlpha::apply_breakpoint() {
  if (next_breakpoint_ >= breakpoints_.size() ||
      curr_.t < breakpoints_[next_breakpoint_] - time_tolerance(curr_.t)) {
    return Status::success(curr_.t);
  }
  ++next_breakpoint_;
  // The impulsive velocity change the new g_t demands, then v̇ and λ after it; restart as
  // after an event.
  const Eigen::VectorXd v_before = curr_.v;
  Status status = project_initial_state(*system_, curr_.t, curr_.q, curr_.v);
  if (status.ok()) {
    status = solve_accelerations(*system_, curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
  }
  if (!status.ok()) {
    return failure(status.code, fmt::format("at a velocity jump of a prescribed motion, the state "
                                            "after it could not be solved: {}", status.message));
  }
  if (options_.quadrature.jump && curr_.integrals.size() > 0) {
    Eigen::VectorXd dz(curr_.integrals.size());
    options_.quadrature.jump(curr_.t, curr_.q, v_before, curr_.v, dz);
    curr_.integrals += dz;
  }
  restart_at_current();
  return Status::success(curr_.t);
}

Status GeneralizedAlpha::reselect_constraints() {
  // As IDA between its steps (ida_integrator.cpp): the system may pick new independent rows
  // when the current ones turn ill-conditioned along the motion. Their multipliers change
  // meaning, so the scheme restarts there like after an event: v̇ and λ from the saddle-point
  // system, a = v̇, no extrapolation across the switch, a fresh iteration matrix.
  if (!system_->reselect_constraints(curr_.t, curr_.q)) return Status::success(curr_.t);
  return restart_on_new_rows();
}

Status GeneralizedAlpha::restart_on_new_rows() {
  const Status status =
      solve_accelerations(*system_, curr_.t, curr_.q, curr_.v, curr_.vdot, curr_.lambda);
  if (!status.ok()) {
    return failure(status.code, fmt::format("after new constraint rows were selected, the "
                                            "accelerations could not be solved: {}", status.message));
  }
  restart_at_current();
  return Status::success(curr_.t);
}

bool GeneralizedAlpha::converged(const Eigen::VectorXd& xi, const Eigen::VectorXd& lambda_scaled,
                                 const Eigen::VectorXd& delta, double roundoff) const {
  // ξ: relative to the step's displacement, with a floor at the round-off of q ⊕ ξ.
  const double tol = options_.newton_tolerance;
  const double xi_floor = roundoff * (1.0 + curr_.q.lpNorm<Eigen::Infinity>());
  const bool xi_converged =
      delta.head(nv_).lpNorm<Eigen::Infinity>() <= tol * xi.lpNorm<Eigen::Infinity>() + xi_floor;
  // λ̃ through the force Gᵀλ̃ it applies (M, G of eval_, the last evaluation), relative to that
  // force, with the floor the ξ round-off causes in the O(1)-conditioned scaled system.
  const double force_change = (eval_.G.transpose() * delta.tail(nc_)).lpNorm<Eigen::Infinity>();
  const double force = (eval_.G.transpose() * lambda_scaled).lpNorm<Eigen::Infinity>();
  const bool lambda_converged =
      force_change <= tol * force + largest_mass_entry() * xi_floor;
  return xi_converged && lambda_converged;
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

bool GeneralizedAlpha::refresh_jacobian(double h, const Eigen::VectorXd& xi,
                                        const Eigen::VectorXd& lambda_scaled,
                                        const Eigen::VectorXd& r) {
  ++stats_.jacobian_evaluations;
  probe_.t = next_.t;
  r_perturbed_.resize(nv_ + nc_);
  // Columns for ξ: forward differences of the scaled residual (the √ε rule).
  const double epsilon =
      std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, curr_.q.lpNorm<Eigen::Infinity>());
  Eigen::VectorXd xi_perturbed = xi;
  for (int j = 0; j < nv_; ++j) {
    xi_perturbed(j) = xi(j) + epsilon;
    end_of_step_kinematics(h, xi_perturbed, probe_);
    scaled_residual(h, probe_, lambda_scaled, r_perturbed_);
    J_.col(j) = (r_perturbed_ - r) / epsilon;
    xi_perturbed(j) = xi(j);
  }
  // Columns for λ̃ = βh²λ: [Gᵀ; 0] at the current iterate.
  end_of_step_kinematics(h, xi, probe_);
  system_->constraint_jacobian_v(probe_.t, probe_.q, eval_.G);
  J_.topRightCorner(nv_, nc_) = eval_.G.transpose();
  J_.bottomRightCorner(nc_, nc_).setZero();
  if (!J_.allFinite()) return false;
  if (sparse_) {
    J_sparse_ = J_.sparseView();
    slots_valid_ = false;
  }
  if (has_structure_ && !sparse_) {
    dense_structured_block(h, correction_);
    correction_ = J_.topLeftCorner(nv_, nv_) - correction_;
    correction_h_ = h;
  }
  jacobian_h_ = h;
  jacobian_age_ = 0;
  jacobian_structured_ = false;
  return factorize_iteration_matrix();
}

void GeneralizedAlpha::dense_structured_block(double h, Eigen::MatrixXd& block) {
  const auto& [alpha_m, alpha_f, beta, gamma] = coef_;
  block = ((1.0 - alpha_m) / (1.0 - alpha_f)) * eval_.M;
  block.diagonal() += beta * h * h * stiffness_ + gamma * h * damping_;
  if (system_->coupled_stiffness(next_.t, next_.q, coupled_)) block += beta * h * h * coupled_;
}

bool GeneralizedAlpha::build_structured_jacobian(double h) {
  ++stats_.jacobian_evaluations;
  jacobian_structured_ = true;
  jacobian_h_ = h;
  jacobian_age_ = 0;
  // ∂r/∂ξ: βh² M ∂v̇/∂ξ = (1 − α_m)/(1 − α_f) M, βh² k ∂q/∂ξ, βh² c ∂v/∂ξ = γh c; ∂g/∂ξ = G;
  // plus the internal forces that couple velocities (a nonlinear body's beams), at the last
  // state evaluated.
  if (!sparse_) {
    Eigen::MatrixXd block;
    dense_structured_block(h, block);
    // What the last matrix of differences held beyond the structured one (force elements and
    // constraint forces through the joints' node rotations), scaled to this h as a stiffness.
    if (correction_h_ > 0.0) block += (h / correction_h_) * (h / correction_h_) * correction_;
    J_.topLeftCorner(nv_, nv_) = block;
    J_.topRightCorner(nv_, nc_) = eval_.G.transpose();
    J_.bottomLeftCorner(nc_, nv_) = eval_.G;
    J_.bottomRightCorner(nc_, nc_).setZero();
    if (!J_.allFinite()) return false;
    return factorize_iteration_matrix();
  }
  sparse_structured_matrix(h);
  if (!Eigen::Map<const Eigen::VectorXd>(J_sparse_.valuePtr(), J_sparse_.nonZeros()).allFinite()) return false;
  return factorize_iteration_matrix();
}

void GeneralizedAlpha::sparse_structured_matrix(double h) {
  const auto& [alpha_m, alpha_f, beta, gamma] = coef_;
  const bool coupled = system_->coupled_stiffness(next_.t, next_.q, coupled_);
  bool valid = slots_valid_ && slots_.mass_pattern == sparse_pattern(eval_.M_sparse) &&
               slots_.coupled_pattern == (coupled ? sparse_pattern(coupled_) : std::vector<int>{});
  // A constraint entry outside the pattern (G's zeros change with the configuration) renews it.
  for (int j = 0; valid && j < nv_; ++j) {
    for (int i = 0; i < nc_; ++i) {
      if (eval_.G(i, j) != 0.0 && slots_.g[static_cast<std::size_t>(j * nc_ + i)] < 0) {
        valid = false;
        break;
      }
    }
  }
  if (!valid) build_sparse_pattern(coupled);
  // Scatter: c M, k and c on the diagonal, the coupled derivatives, G in both places.
  double* values = J_sparse_.valuePtr();
  std::fill(values, values + J_sparse_.nonZeros(), 0.0);
  const double c_mass = (1.0 - alpha_m) / (1.0 - alpha_f);
  const double* mass = eval_.M_sparse.valuePtr();
  for (std::size_t k = 0; k < slots_.mass.size(); ++k) values[slots_.mass[k]] += c_mass * mass[k];
  if (has_structure_) {
    for (int i = 0; i < nv_; ++i) values[slots_.diagonal[static_cast<std::size_t>(i)]] += beta * h * h * stiffness_(i) + gamma * h * damping_(i);
  }
  for (std::size_t k = 0; k < slots_.coupled.size(); ++k) values[slots_.coupled[k]] += beta * h * h * coupled_.valuePtr()[k];
  for (int j = 0; j < nv_; ++j) {
    for (int i = 0; i < nc_; ++i) {
      const double g = eval_.G(i, j);
      if (g == 0.0) continue;
      const std::size_t at = static_cast<std::size_t>(j * nc_ + i);
      values[slots_.g[at]] += g;
      values[slots_.g_transposed[at]] += g;
    }
  }
}

void GeneralizedAlpha::build_sparse_pattern(bool coupled) {
  // Every entry any source may write, with G's entries seen so far kept (no flip-flop).
  std::vector<Eigen::Triplet<double>> entries;
  const auto add_pattern = [&entries](const Eigen::SparseMatrix<double>& A) {
    for (int j = 0; j < A.outerSize(); ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) entries.emplace_back(static_cast<int>(it.row()), j, 0.0);
    }
  };
  add_pattern(eval_.M_sparse);
  if (coupled) add_pattern(coupled_);
  for (int i = 0; i < nv_; ++i) entries.emplace_back(i, i, 0.0);
  const bool had_g = slots_.g.size() == static_cast<std::size_t>(nv_ * nc_);
  for (int j = 0; j < nv_; ++j) {
    for (int i = 0; i < nc_; ++i) {
      if (eval_.G(i, j) == 0.0 && !(had_g && slots_.g[static_cast<std::size_t>(j * nc_ + i)] >= 0)) continue;
      entries.emplace_back(nv_ + i, j, 0.0);
      entries.emplace_back(j, nv_ + i, 0.0);
    }
  }
  J_sparse_.resize(nv_ + nc_, nv_ + nc_);
  J_sparse_.setFromTriplets(entries.begin(), entries.end());
  J_sparse_.makeCompressed();
  // Slots: each entry's place in its column (rows ascending).
  const auto slot = [this](int row, int col) {
    const int* begin = J_sparse_.innerIndexPtr() + J_sparse_.outerIndexPtr()[col];
    const int* end = J_sparse_.innerIndexPtr() + J_sparse_.outerIndexPtr()[col + 1];
    const int* at = std::lower_bound(begin, end, row);
    LIMBER_DEMAND(at != end && *at == row);
    return static_cast<int>(at - J_sparse_.innerIndexPtr());
  };
  const auto slots_of = [&slot](const Eigen::SparseMatrix<double>& A, std::vector<int>& out) {
    out.clear();
    for (int j = 0; j < A.outerSize(); ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) out.push_back(slot(static_cast<int>(it.row()), j));
    }
  };
  slots_of(eval_.M_sparse, slots_.mass);
  slots_.mass_pattern = sparse_pattern(eval_.M_sparse);
  if (coupled) {
    slots_of(coupled_, slots_.coupled);
    slots_.coupled_pattern = sparse_pattern(coupled_);
  } else {
    slots_.coupled.clear();
    slots_.coupled_pattern.clear();
  }
  slots_.diagonal.resize(static_cast<std::size_t>(nv_));
  for (int i = 0; i < nv_; ++i) slots_.diagonal[static_cast<std::size_t>(i)] = slot(i, i);
  std::vector<int> g(static_cast<std::size_t>(nv_ * nc_), -1), g_transposed = g;
  for (int j = 0; j < nv_; ++j) {
    for (int i = 0; i < nc_; ++i) {
      const std::size_t at = static_cast<std::size_t>(j * nc_ + i);
      if (eval_.G(i, j) == 0.0 && !(had_g && slots_.g[at] >= 0)) continue;
      g[at] = slot(nv_ + i, j);
      g_transposed[at] = slot(j, nv_ + i);
    }
  }
  slots_.g = std::move(g);
  slots_.g_transposed = std::move(g_transposed);
  slots_valid_ = true;
}

bool GeneralizedAlpha::factorize_iteration_matrix() {
  if (!sparse_) {
    lu_.compute(J_);
    return !is_singular(J_, lu_);
  }
  if (!sparse_lu_.factorize(J_sparse_)) return false;
  if (sparse_lu_.rcond() > kSingularRcond) return true;
  // A small estimate: judged as the dense matrices are, on the equilibrated matrix (rare).
  const Eigen::MatrixXd dense(J_sparse_);
  return !is_singular(dense, Eigen::PartialPivLU<Eigen::MatrixXd>(dense));
}

void GeneralizedAlpha::solve_iteration_matrix(const Eigen::VectorXd& r, Eigen::VectorXd& delta) {
  if (sparse_) {
    delta = -sparse_lu_.solve(r);
  } else {
    delta = -lu_.solve(r);
  }
}

double GeneralizedAlpha::largest_mass_entry() const {
  if (!sparse_) return eval_.M.lpNorm<Eigen::Infinity>();
  return Eigen::Map<const Eigen::VectorXd>(eval_.M_sparse.valuePtr(), eval_.M_sparse.nonZeros())
      .lpNorm<Eigen::Infinity>();
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

std::optional<Status> GeneralizedAlpha::step_over_singular_configuration(const std::string& why) {
  // Land on a grid point, where the scheme goes on with its step.
  const auto on_grid = [this](double t) {
    return grid_origin_ + std::ceil((t - grid_origin_) / grid_step_ - 1e-9) * grid_step_;
  };
  const double limit = next_breakpoint_ < breakpoints_.size() ? breakpoints_[next_breakpoint_] : options_.t_stop;
  const StepOverOutcome over = step_overs_.step_over(*system_, options_.quadrature, curr_.t, curr_.q, curr_.v,
                                                     curr_.integrals, limit, why, kNearSingularRatio, on_grid);
  if (over.kind == StepOverOutcome::kNotSingular) return std::nullopt;
  if (over.kind == StepOverOutcome::kFailed) {
    failed_ = true;
    failure_ = over.status;
    return failure_;
  }
  if (over.kind == StepOverOutcome::kRowsReselected) {
    // Other rows hold there: the scheme restarts on them from curr_, with its step.
    h_try_ = grid_step_;
    halvings_ = 0;
    return restart_on_new_rows();
  }
  // Restart at the landing point, as after an event, back on the grid.
  const SteppedOverStretch& stretch = step_overs_.stretch();
  curr_.t = stretch.t1;
  curr_.q = stretch.q1;
  curr_.v = stretch.v1;
  curr_.vdot = stretch.vdot1;
  curr_.lambda = stretch.lambda1;
  curr_.integrals = stretch.z1;
  restart_at_current();
  grid_index_ = static_cast<long>(std::floor((curr_.t - grid_origin_) / grid_step_ + 1e-9));
  h_try_ = grid_step_;
  halvings_ = 0;
  if (grid_in_window_ && !in_event_window(curr_.t)) start_grid(curr_.t);
  return check_budgets();
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
