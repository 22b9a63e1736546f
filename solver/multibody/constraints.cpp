#include "multibody/constraints.h"
#include "multibody/evaluated.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <variant>

#include "multibody/body.h"
#include "multibody/released_joints.h"

namespace limber::multibody {

double wrap_angle(double x) {
  const double two_pi = 2.0 * std::numbers::pi;
  double y = std::fmod(x + std::numbers::pi, two_pi);
  if (y < 0.0) y += two_pi;
  return y == 0.0 ? std::numbers::pi : y - std::numbers::pi;
}

void update_marker_kinematics(const Model& model, const State& state, Stage stage, Workspace& ws) {
  update_marker_kinematics(model, state, stage, ReleasedJoints{}, ws);
}

void update_marker_kinematics(const Model& model, const State& state, Stage stage, const ReleasedJoints& released,
                              Workspace& ws) {
  const Eigen::VectorXd* v = stage == Stage::kVelocity ? &state.v : nullptr;
  const bool some_released = !released.markers.empty();
  for (size_t k = 0; k < model.markers.size(); ++k) {
    if (some_released && released.markers[k]) continue;
    marker_kinematics(model, k, state.q, v, ws.markers[k]);
  }
}

namespace {

// The markers a force element acts through.
std::vector<int> force_markers(const ForceElement& force) {
  return std::visit(
      [](const auto& element) -> std::vector<int> {
        if constexpr (std::is_same_v<std::decay_t<decltype(element)>, PointLoad>) {
          return {element.marker};
        } else {
          return {element.marker_i, element.marker_j};
        }
      },
      force);
}

}  // namespace

ReleasedJoints released_joints(const Model& model, const std::vector<bool>& released_rows) {
  ReleasedJoints out;
  if (released_rows.empty()) return out;
  out.rows = released_rows;
  // Markers of released rows, less those a row in force or a force element uses.
  std::vector<bool> of_released(model.markers.size(), false), in_force(model.markers.size(), false);
  for (int row = 0; row < model.num_equations(); ++row) {
    const ConstraintEquation& e = model.equations[static_cast<std::size_t>(row)];
    std::vector<bool>& users = released_rows[static_cast<std::size_t>(row)] ? of_released : in_force;
    users[static_cast<std::size_t>(e.marker_i)] = true;
    users[static_cast<std::size_t>(e.marker_j)] = true;
  }
  for (const ForceElement& force : model.forces) {
    for (const int marker : force_markers(force)) in_force[static_cast<std::size_t>(marker)] = true;
  }
  out.markers.assign(model.markers.size(), false);
  for (std::size_t k = 0; k < model.markers.size(); ++k) out.markers[k] = of_released[k] && !in_force[k];
  return out;
}

RelativeAngle relative_angle(const FrameKinematics& mi, const FrameKinematics& mj, Stage stage) {
  RelativeAngle out;
  const Eigen::Vector3d x_i = mi.R_WF.col(0), y_i = mi.R_WF.col(1), x_j = mj.R_WF.col(0);
  // Position: θ and the rate vector u.
  const double s = x_j.dot(y_i), c = x_j.dot(x_i), n = s * s + c * c;
  const Eigen::Vector3d A = x_j.cross(y_i), B = x_j.cross(x_i);
  out.theta = std::atan2(s, c);
  out.u = (c * A - s * B) / n;
  if (stage == Stage::kPosition) return out;
  // Velocity: θ̇ and u̇·Δω from ṡ = A·Δω, ċ = B·Δω and the axis rates ω × axis.
  const Eigen::Vector3d dw = mj.w_W - mi.w_W;
  const double s_dot = A.dot(dw), c_dot = B.dot(dw), n_dot = 2.0 * (c * c_dot + s * s_dot);
  const Eigen::Vector3d xj_dot = mj.w_W.cross(x_j);
  const Eigen::Vector3d A_dot = xj_dot.cross(y_i) + x_j.cross(mi.w_W.cross(y_i));
  const Eigen::Vector3d B_dot = xj_dot.cross(x_i) + x_j.cross(mi.w_W.cross(x_i));
  const Eigen::Vector3d u_dot = (c_dot * A + c * A_dot - s_dot * B - s * B_dot) / n - out.u * n_dot / n;
  out.rate = out.u.dot(dw);
  out.bias = out.u.dot(mj.alpha_bias - mi.alpha_bias) + u_dot.dot(dw);
  return out;
}

namespace {

// Adds uᵀ J (J: a 3 x nv Jacobian of `frame`) to row `row` of G, over the columns of the
// frame's body only (the rest of J is zero).
void add_row_product(const FrameKinematics& frame, const Eigen::Vector3d& u, const Eigen::MatrixXd& J,
                     Eigen::MatrixXd& G, int row) {
  G.row(row).segment(frame.body_v_offset, frame.body_nv).noalias() +=
      u.transpose() * J.middleCols(frame.body_v_offset, frame.body_nv);
}

// One row: value, Jacobian row, g_t and γ of a primitive; f is the driver's function value.
void evaluate_row(const ConstraintEquation& e, const FrameKinematics& mi, const FrameKinematics& mj,
                  const FunctionValue& f, Stage stage, int row, Workspace& ws) {
  const bool velocity = stage == Stage::kVelocity;
  const Eigen::Vector3d a = mi.R_WF.col(e.axis_i);
  ws.g_t(row) = -f.first;
  ws.gamma(row) = 0.0;
  // Only the two frames' body blocks are ever written (add_row_product; G starts zero): clear
  // those, not the whole row (a strided pass over a nonlinear body's hundreds of columns).
  ws.G.row(row).segment(mi.body_v_offset, mi.body_nv).setZero();
  ws.G.row(row).segment(mj.body_v_offset, mj.body_nv).setZero();
  switch (e.kind) {
    case EquationKind::kDot1: {
      const Eigen::Vector3d b = mj.R_WF.col(e.axis_j);
      const Eigen::Vector3d axb = a.cross(b);
      ws.g(row) = a.dot(b);
      add_row_product(mi, axb, mi.J_w, ws.G, row);
      add_row_product(mj, -axb, mj.J_w, ws.G, row);
      if (velocity) {
        const Eigen::Vector3d dw = mi.w_W - mj.w_W;
        const Eigen::Vector3d axb_dot = mi.w_W.cross(a).cross(b) + a.cross(mj.w_W.cross(b));
        ws.gamma(row) = -axb.dot(mi.alpha_bias - mj.alpha_bias) - axb_dot.dot(dw);
      }
      break;
    }
    case EquationKind::kDot2: {
      const Eigen::Vector3d d = mj.p_W - mi.p_W;
      const Eigen::Vector3d axd = a.cross(d);
      ws.g(row) = a.dot(d) - f.value;
      add_row_product(mi, axd, mi.J_w, ws.G, row);
      add_row_product(mj, a, mj.J_p, ws.G, row);
      add_row_product(mi, -a, mi.J_p, ws.G, row);
      if (velocity) {
        const Eigen::Vector3d d_dot = mj.v_W - mi.v_W;
        const Eigen::Vector3d a_dot = mi.w_W.cross(a);
        ws.gamma(row) = -mi.alpha_bias.dot(axd) - mi.w_W.dot(a_dot.cross(d) + a.cross(d_dot)) -
                        a_dot.dot(d_dot) - a.dot(mj.a_bias - mi.a_bias) + f.second;
      }
      break;
    }
    case EquationKind::kAngle: {
      const RelativeAngle angle = relative_angle(mi, mj, stage);
      ws.g(row) = wrap_angle(angle.theta - f.value);
      add_row_product(mj, angle.u, mj.J_w, ws.G, row);
      add_row_product(mi, -angle.u, mi.J_w, ws.G, row);
      if (velocity) ws.gamma(row) = -angle.bias + f.second;
      break;
    }
  }
}

}  // namespace

void evaluate_constraints(const Model& model, const State& state, Stage stage, Workspace& ws) {
  evaluate_constraints(model, state, stage, ReleasedJoints{}, ws);
}

void evaluate_constraints(const Model& model, const State& state, Stage stage, const ReleasedJoints& released,
                          Workspace& ws) {
  update_marker_kinematics(model, state, stage, released, ws);
  evaluate_constraint_rows(model, state, stage, released, ws);
}

void evaluate_constraint_rows(const Model& model, const State& state, Stage stage, Workspace& ws) {
  evaluate_constraint_rows(model, state, stage, ReleasedJoints{}, ws);
}

void evaluate_constraint_rows(const Model& model, const State& state, Stage stage, const ReleasedJoints& released,
                              Workspace& ws) {
  const bool some_released = !released.rows.empty();
  for (int row = 0; row < model.num_equations(); ++row) {
    if (some_released && released.rows[static_cast<std::size_t>(row)]) continue;
    const ConstraintEquation& e = model.equations[row];
    // Drivers supply f(t); joint equations have f = 0.
    const FunctionValue f =
        e.driver >= 0 ? model.drivers[e.driver].motion.evaluate(state.t) : FunctionValue{};
    evaluate_row(e, ws.markers[e.marker_i], ws.markers[e.marker_j], f, stage, row, ws);
  }
}

ConstraintViolation constraint_violation(const Model& model, const State& state, Workspace& ws,
                                         const std::vector<bool>& released) {
  if (model.num_equations() == 0) return {};
  evaluate_constraints(model, state, Stage::kPosition, ws);
  return violation_of_rows(model, state, ws, released);
}

ConstraintViolation violation_of_rows(const Model& model, const State& state, const Workspace& ws,
                                      const std::vector<bool>& released) {
  if (model.num_equations() == 0) return {};
  const Eigen::VectorXd rate = ws.G * state.v + ws.g_t;
  ConstraintViolation out;
  for (int row = 0; row < model.num_equations(); ++row) {
    if (!released.empty() && released[static_cast<std::size_t>(row)]) continue;
    out.position = std::max(out.position, std::abs(ws.g(row)));
    out.velocity = std::max(out.velocity, std::abs(rate(row)));
  }
  return out;
}

}  // namespace limber::multibody
