// Generalized-α's discontinuities: events located inside a step and the event windows after
// them, prescribed motions' velocity jumps, new constraint rows, and the step over a singular
// configuration. The scheme itself is in generalized_alpha.cpp.
#include "integrate/generalized_alpha.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "integrate/consistent_state.h"
#include "integrate/singular_test.h"

namespace limber::integrate {

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


}  // namespace limber::integrate
