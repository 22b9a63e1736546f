#include "multibody/assembly.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.h"
#include "core/minimum_norm.h"
#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/nonlinear_body.h"
#include "multibody/dynamics.h"

namespace limber::multibody {

namespace {

// Velocity residual, relative to the velocities and driver rates, that counts as closed.
constexpr double kVelocityTolerance = 1e-10;

// A mask of the velocity directions the assembly may change: all but the held ones and,
// unless `modes_free`, the modal coordinates of flexible bodies.
Eigen::VectorXd free_mask(const Model& model, const AssemblyOptions& options, bool modes_free) {
  Eigen::VectorXd mask = Eigen::VectorXd::Ones(model.nv);
  for (const HeldCoordinate& h : options.held) {
    if (h.body <= 0 || h.body >= static_cast<int>(model.bodies.size()) || h.component < 0 ||
        h.component > 5) {
      throw InputError(fmt::format("held coordinate: expected a moving body and a component 0-5, "
                                   "got body {} component {}", h.body, h.component));
    }
    mask(model.bodies[h.body].v_offset + h.component) = 0.0;
  }
  if (modes_free) return mask;
  for (const Body& b : model.bodies) {
    if (b.kind == BodyKind::kFlexible) mask.segment(b.v_offset + 6, b.nv - 6).setZero();
  }
  return mask;
}

bool has_flexible_body(const Model& model) {
  return std::any_of(model.bodies.begin(), model.bodies.end(),
                     [](const Body& b) { return b.kind == BodyKind::kFlexible; });
}

// Minimum-norm solution x of (G diag(mask)) x = rhs, the rank decided as in redundancy.h
// (rows scaled to unit norm, relative threshold): equations that are redundant up to the
// rounding in a flexible body's mode shapes must not count as independent, or the step picks
// up an arbitrary O(1) part along them (e.g. out-of-plane velocities of a planar mechanism).
Eigen::VectorXd minimum_norm_step(const Eigen::MatrixXd& G, const Eigen::VectorXd& mask,
                                  const Eigen::VectorXd& rhs) {
  Eigen::MatrixXd G_free = G * mask.asDiagonal();
  Eigen::VectorXd scaled_rhs = rhs;
  for (Eigen::Index row = 0; row < G_free.rows(); ++row) {
    const double norm = G_free.row(row).norm();
    if (norm > 0.0) G_free.row(row) /= norm, scaled_rhs(row) /= norm;
  }
  return mask.asDiagonal() * minimum_norm_solve(G_free, scaled_rhs, kRedundancyThreshold);
}

// Newton on g = 0 in the directions of `mask`; fills `result` (status, residual, worst row).
void newton_assembly(const Model& model, State& state, Workspace& ws,
                     const AssemblyOptions& options, const Eigen::VectorXd& mask,
                     AssemblyResult& result) {
  Eigen::VectorXd q_next = state.q;
  result.status = AssemblyStatus::kOk;
  for (result.iterations = 0;; ++result.iterations) {
    // Residual and its worst equation.
    evaluate_constraints(model, state, Stage::kPosition, ws);
    Eigen::Index worst = 0;
    result.residual = model.num_equations() > 0 ? ws.g.cwiseAbs().maxCoeff(&worst) : 0.0;
    result.worst_equation = model.num_equations() > 0 ? static_cast<int>(worst) : -1;
    if (result.residual <= options.tolerance) return;
    if (result.iterations == options.max_iterations) break;
    // Newton step on the manifold: q ← q ⊕ (−G⁺ g).
    const Eigen::VectorXd dv = minimum_norm_step(ws.G, mask, -ws.g);
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      integrate_body_coordinates(model, b, state.q, dv, q_next);
    }
    state.q = q_next;
  }
  result.status = AssemblyStatus::kNotConverged;
}

}  // namespace

AssemblyResult assemble_positions(const Model& model, State& state, Workspace& ws,
                                  const AssemblyOptions& options) {
  AssemblyResult result;
  const Eigen::VectorXd q_given = state.q;
  // Where the positions as given are off.
  evaluate_constraints(model, state, Stage::kPosition, ws);
  if (model.num_equations() > 0) {
    Eigen::Index worst = 0;
    result.given_residual = ws.g.cwiseAbs().maxCoeff(&worst);
    result.given_worst_equation = static_cast<int>(worst);
  }
  const double given_value = model.num_equations() > 0 ? ws.g(result.given_worst_equation) : 0.0;
  newton_assembly(model, state, ws, options, free_mask(model, options, false), result);
  // A mechanism that closes only by deforming its flexible bodies: let the modes move.
  if (result.status != AssemblyStatus::kOk && has_flexible_body(model)) {
    state.q = q_given;
    newton_assembly(model, state, ws, options, free_mask(model, options, true), result);
    result.modes_released = true;
  }
  if (result.status == AssemblyStatus::kOk) return result;
  const auto describe = [&](const ConstraintEquation& e) {
    return fmt::format("{} ({})", e.name,
                       e.joint >= 0 ? "joint " + model.joints[e.joint].name : "driver " + model.drivers[e.driver].name);
  };
  const auto unit = [](const ConstraintEquation& e) { return e.kind == EquationKind::kDot2 ? "m" : "rad"; };
  const ConstraintEquation& e = model.equations[result.worst_equation];
  const ConstraintEquation& given = model.equations[result.given_worst_equation];
  result.message = fmt::format(
      "assembly did not converge in {} iterations: equation {} does not close, residual "
      "{:.3e} {} (tolerance {:.1e}); as given, the largest gap was equation {}, {:.3e} {}",
      options.max_iterations, describe(e), ws.g(result.worst_equation), unit(e), options.tolerance,
      describe(given), given_value, unit(given));
  return result;
}

double assemble_velocities(const Model& model, State& state, Workspace& ws,
                           const AssemblyOptions& options, bool* modes_released) {
  evaluate_constraints(model, state, Stage::kPosition, ws);
  const auto residual = [&](const Eigen::VectorXd& v) {
    return model.num_equations() > 0 ? (ws.G * v + ws.g_t).cwiseAbs().maxCoeff() : 0.0;
  };
  // Minimum-norm correction of the velocity residual G v + g_t, modal rates kept; a nonlinear
  // body's nodes move as one rigid body in it, as a modal body's frame does (nonlinear_body.h).
  const auto project = [&](bool modes_free) {
    const Eigen::VectorXd mask = free_mask(model, options, modes_free);
    const Eigen::VectorXd rhs = -(ws.G * state.v + ws.g_t);
    if (model.nonlinear_bodies.empty()) return Eigen::VectorXd(state.v + minimum_norm_step(ws.G, mask, rhs));
    const Eigen::MatrixXd B = mask.asDiagonal() * rigid_nonlinear_velocity_basis(model, state.q);
    const Eigen::VectorXd x = minimum_norm_step(ws.G * B, Eigen::VectorXd::Ones(B.cols()), rhs);
    return Eigen::VectorXd(state.v + B * x);
  };
  Eigen::VectorXd v = project(false);
  // Rates the frames alone cannot meet (a driver deforming a body): let the modes move.
  const double scale = 1.0 + state.v.lpNorm<Eigen::Infinity>() + ws.g_t.lpNorm<Eigen::Infinity>();
  const bool release = has_flexible_body(model) && residual(v) > kVelocityTolerance * scale;
  if (release) v = project(true);
  if (modes_released != nullptr) *modes_released = release;
  state.v = v;
  return residual(state.v);
}

void solve_accelerations(const Model& model, const State& state,
                         const ConstraintPartition& partition, Workspace& ws,
                         Eigen::VectorXd& v_dot, Eigen::VectorXd& lambda) {
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  mass_matrix(model, state, ws);
  generalized_forces(model, state, ws);
  // Independent rows only: G_c, γ_c.
  const int nc = static_cast<int>(partition.independent.size());
  Eigen::MatrixXd G(nc, model.nv);
  Eigen::VectorXd gamma(nc);
  for (int k = 0; k < nc; ++k) {
    G.row(k) = ws.G.row(partition.independent[k]);
    gamma(k) = ws.gamma(partition.independent[k]);
  }
  // Schur complement: (G M⁻¹ Gᵀ) λ = G M⁻¹ Q − γ, then M v̇ = Q − Gᵀ λ.
  const Eigen::LLT<Eigen::MatrixXd> M_llt(ws.M);
  LIMBER_DEMAND(M_llt.info() == Eigen::Success);
  const Eigen::MatrixXd Minv_Gt = M_llt.solve(G.transpose());
  const Eigen::VectorXd Minv_Q = M_llt.solve(ws.Q);
  lambda = (G * Minv_Gt).ldlt().solve(G * Minv_Q - gamma);
  v_dot = Minv_Q - Minv_Gt * lambda;
}

}  // namespace limber::multibody
