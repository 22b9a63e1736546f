#include "integrate/singular_step_over.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>


#include <Eigen/SVD>
#include <fmt/format.h>

#include "core/error.h"
#include "integrate/consistent_state.h"

namespace limber::integrate {

double held_rows_margin(MechanicalSystem& system, double t, const Eigen::VectorXd& q) {
  if (system.nc() == 0) return 1.0;
  Eigen::MatrixXd G;
  system.constraint_jacobian_v(t, q, G);
  return unit_rows_margin(std::move(G));
}

double unit_rows_margin(Eigen::MatrixXd G) {
  if (G.rows() == 0) return 1.0;
  // Unit rows: independent of units and of the mechanism's size (multibody/redundancy.h).
  for (Eigen::Index k = 0; k < G.rows(); ++k) {
    const double norm = G.row(k).norm();
    if (norm > 0.0) G.row(k) /= norm;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(G);
  return svd.singularValues()(svd.singularValues().size() - 1);
}

bool predict_across(MechanicalSystem& system, double t0, const Eigen::VectorXd& q0,
                    const Eigen::VectorXd& v0, const Eigen::VectorXd& vdot0, double t,
                    Eigen::VectorXd& q, Eigen::VectorXd& v) {
  const double s = t - t0;
  system.integrate_coordinates(q0, s * v0 + 0.5 * s * s * vdot0, q);
  v = v0 + s * vdot0;
  Eigen::VectorXd q_projected = q, v_projected = v;
  if (!project_initial_state(system, t, q_projected, v_projected).ok()) return false;
  q = q_projected;
  v = v_projected;
  return true;
}

std::string singular_failure_message(double t, double ratio, const std::string& what_failed) {
  return fmt::format(
      "at t = {:.6g} s: {} at a singular configuration (the constraint equations lose rank "
      "there: smallest singular value {:.2g} of its start value), and stepping over it "
      "failed. Remedies: the other integrator (--integrator), another rtol or step, or a "
      "start or geometry that keeps the mechanism off the singular path (e.g. a third, "
      "parallel crank in a parallelogram)",
      t, what_failed, ratio);
}

StepOver step_over_singular(MechanicalSystem& system, double t, const Eigen::VectorXd& q_failed,
                            const Eigen::VectorXd& v_failed, double margin_start, double t_limit,
                            const std::function<double(double)>& landing_time) {
  StepOver out;
  const Eigen::VectorXd& q = out.q_from = q_failed;
  const Eigen::VectorXd& v = out.v_from = v_failed;
  const Eigen::VectorXd& vdot = out.vdot_from;
  const double sigma = held_rows_margin(system, t, q);
  const double ratio = margin_start > 0.0 ? sigma / margin_start : 1.0;
  const auto fail = [&](const std::string& why) {
    out.status = {StatusCode::kConvergenceFailures, t, singular_failure_message(t, ratio, why)};
    return out;
  };
  // The departure's accelerations from the saddle-point system: the integrator's own carry the
  // corrector's trouble (IDA's v̇ reached 1e7 m/s² on the 2-chain, whose true one is 16).
  if (const Status solved = solve_accelerations(system, t, out.q_from, out.v_from, out.vdot_from, out.lambda_from);
      !solved.ok()) {
    return fail("the accelerations there could not be solved: " + solved.message);
  }
  // σ's rate along the motion, by a difference over a displacement of 1e-7 of the coordinates.
  Eigen::MatrixXd N;
  system.kinematic_matrix(q, N);
  const double speed = (N * v).lpNorm<Eigen::Infinity>();
  double rate = 0.0;
  if (speed > 0.0) {
    const double epsilon = 1e-7 * std::max(1.0, q.lpNorm<Eigen::Infinity>()) / speed;
    Eigen::VectorXd q_ahead;
    system.integrate_coordinates(q, epsilon * v, q_ahead);
    rate = (held_rows_margin(system, t + epsilon, q_ahead) - sigma) / epsilon;
  }
  // A rank lost here, or lost ahead (or just behind) along the motion: by the set of rows held,
  // which other rows cure (the system reselects them there), or by the mechanism.
  out.near = ratio < kRankLostRatio;
  if (!out.near && rate != 0.0) {
    const double t_instant = t - sigma / rate;
    Eigen::VectorXd q_instant, v_instant;
    const bool projected = predict_across(system, t, q, v, vdot, t_instant, q_instant, v_instant);
    out.near = !projected || held_rows_margin(system, t_instant, q_instant) < kRankLossConfirmRatio * sigma;
    // Asked without a change; the system switches only to rows that hold there.
    Eigen::MatrixXd G_candidate;
    out.rows_reselected = out.near && projected &&
                          system.reselection_candidate(t_instant, q_instant, G_candidate) &&
                          !(unit_rows_margin(std::move(G_candidate)) < kNearSingularRatio * margin_start);
    if (out.rows_reselected) {
      const bool switched = system.reselect_constraints(t_instant, q_instant);
      LIMBER_DEMAND(switched);  // the question just asked, at the same (t, q)
      return out;
    }
  }
  if (!out.near) return out;
  if (!(speed > 0.0)) return fail("the mechanism rests");
  if (rate == 0.0) return fail("the rank margin does not change along the motion");
  // Land as far past the singular instant as the failure stood before it; further when the
  // landing point is no better conditioned than the departure.
  double delta = 2.0 * sigma / std::abs(rate);
  for (int doubling = 0; doubling <= kMaxStepOverDoublings; ++doubling, delta *= 2.0) {
    out.t = landing_time ? landing_time(t + delta) : t + delta;
    if (out.t > t_limit) return fail("the stretch to step over reaches the end of the run or a jump");
    if (!predict_across(system, t, q, v, vdot, out.t, out.q, out.v)) continue;
    if (held_rows_margin(system, out.t, out.q) < sigma) continue;
    const Status solved = solve_accelerations(system, out.t, out.q, out.v, out.vdot, out.lambda);
    if (!solved.ok()) return fail("the accelerations past it could not be solved: " + solved.message);
    out.status = Status::success(out.t);
    return out;
  }
  return fail(fmt::format("no state past it up to 2^{} times its distance is better conditioned",
                          kMaxStepOverDoublings));
}

void SteppedOverStretch::serve(MechanicalSystem& system, double t, Sample& out) const {
  const double theta = (t - t0) / (t1 - t0);
  out.t = t;
  predict_across(system, t0, q0, v0, vdot0, t, out.q, out.v);
  out.vdot = (1.0 - theta) * vdot0 + theta * vdot1;
  out.lambda = (1.0 - theta) * lambda0 + theta * lambda1;
  out.integrals = (1.0 - theta) * z0 + theta * z1;
}

void SingularStepOvers::start(MechanicalSystem& system, double t, const Eigen::VectorXd& q) {
  margin_start_ = held_rows_margin(system, t, q);
  in_a_row_ = 0;
  stretch_.reset();
}

const SteppedOverStretch* SingularStepOvers::holding(double t) const {
  if (!stretch_ || !(t < stretch_->t1 - 1e-12 * std::max(1.0, std::abs(t)))) return nullptr;
  return &*stretch_;
}

StepOverOutcome SingularStepOvers::step_over(MechanicalSystem& system, const Quadrature& quadrature, double t,
                                             const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& z,
                                             double t_limit, const std::string& what_failed, double near_ratio,
                                             const std::function<double(double)>& landing_time) {
  const double ratio = held_rows_margin(system, t, q) / margin_start_;
  if (!(ratio < near_ratio)) return {};
  StepOver over = step_over_singular(system, t, q, v, margin_start_, t_limit, landing_time);
  if (!over.near) return {};
  const auto failed = [](Status status) { return StepOverOutcome{StepOverOutcome::kFailed, std::move(status)}; };
  if (++in_a_row_ > kMaxStepOversInARow) {
    return failed({StatusCode::kConvergenceFailures, t,
                   singular_failure_message(t, ratio, fmt::format("{} after {} step-overs", what_failed,
                                                                  kMaxStepOversInARow))});
  }
  if (over.rows_reselected) return {StepOverOutcome::kRowsReselected, Status::success(t)};
  if (!over.status.ok()) return failed(over.status);
  // New rows may suit the landing point better (their multipliers then follow).
  if (system.reselect_constraints(over.t, over.q)) {
    const Status solved = solve_accelerations(system, over.t, over.q, over.v, over.vdot, over.lambda);
    if (!solved.ok()) return failed({solved.code, over.t, singular_failure_message(over.t, ratio, solved.message)});
  }
  // An event between the ends would be missed: refuse rather than skip it.
  if (const int ne = system.num_events(); ne > 0) {
    Eigen::VectorXd e0, e1;
    system.event_functions(t, q, v, e0);
    system.event_functions(over.t, over.q, over.v, e1);
    for (int k = 0; k < ne; ++k) {
      if (e0(k) < 0.0 && e1(k) >= 0.0) {
        return failed({StatusCode::kConvergenceFailures, t,
                       singular_failure_message(t, ratio, "a hinge limit switches inside the stretch")});
      }
    }
  }
  SteppedOverStretch s;
  s.t0 = t;
  s.q0 = q;
  s.v0 = v;
  s.vdot0 = std::move(over.vdot_from);
  s.lambda0 = std::move(over.lambda_from);
  s.z0 = z;
  s.t1 = over.t;
  s.q1 = std::move(over.q);
  s.v1 = std::move(over.v);
  s.vdot1 = std::move(over.vdot);
  s.lambda1 = std::move(over.lambda);
  // The integrals by the trapezoidal rule across the stretch.
  s.z1 = z;
  if (quadrature.size > 0) {
    Eigen::VectorXd f0(quadrature.size), f1(quadrature.size);
    quadrature.integrand(s.t0, s.q0, s.v0, s.vdot0, s.lambda0, f0);
    quadrature.integrand(s.t1, s.q1, s.v1, s.vdot1, s.lambda1, f1);
    s.z1 += 0.5 * (s.t1 - s.t0) * (f0 + f1);
  }
  stretch_ = std::move(s);
  return {StepOverOutcome::kSteppedOver, Status::success(stretch_->t1)};
}

}  // namespace limber::integrate
