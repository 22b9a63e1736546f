#include "multibody/assembly.h"

#include <Eigen/QR>
#include <fmt/format.h>

#include "core/error.h"
#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"

namespace limber::multibody {

namespace {

// A mask of the velocity directions the assembly may change.
Eigen::VectorXd free_mask(const Model& model, const AssemblyOptions& options) {
  Eigen::VectorXd mask = Eigen::VectorXd::Ones(model.nv);
  for (const HeldCoordinate& h : options.held) {
    if (h.body <= 0 || h.body >= static_cast<int>(model.bodies.size()) || h.component < 0 ||
        h.component > 5) {
      throw InputError(fmt::format("held coordinate: expected a moving body and a component 0-5, "
                                   "got body {} component {}", h.body, h.component));
    }
    mask(model.bodies[h.body].v_offset + h.component) = 0.0;
  }
  return mask;
}

// Minimum-norm solution x of (G diag(mask)) x = rhs.
Eigen::VectorXd minimum_norm_step(const Eigen::MatrixXd& G, const Eigen::VectorXd& mask,
                                  const Eigen::VectorXd& rhs) {
  const Eigen::MatrixXd G_free = G * mask.asDiagonal();
  return mask.asDiagonal() * Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(G_free).solve(rhs);
}

}  // namespace

AssemblyResult assemble_positions(const Model& model, State& state, Workspace& ws,
                                  const AssemblyOptions& options) {
  const Eigen::VectorXd mask = free_mask(model, options);
  AssemblyResult result;
  Eigen::VectorXd q_next = state.q;
  for (result.iterations = 0;; ++result.iterations) {
    // Residual and its worst equation.
    evaluate_constraints(model, state, Stage::kPosition, ws);
    Eigen::Index worst = 0;
    result.residual = model.num_equations() > 0 ? ws.g.cwiseAbs().maxCoeff(&worst) : 0.0;
    result.worst_equation = model.num_equations() > 0 ? static_cast<int>(worst) : -1;
    if (result.residual <= options.tolerance) return result;
    if (result.iterations == options.max_iterations) break;
    // Newton step on the manifold: q ← q ⊕ (−G⁺ g).
    const Eigen::VectorXd dv = minimum_norm_step(ws.G, mask, -ws.g);
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      integrate_body_coordinates(model, b, state.q, dv, q_next);
    }
    state.q = q_next;
  }
  result.status = AssemblyStatus::kNotConverged;
  const ConstraintEquation& e = model.equations[result.worst_equation];
  result.message = fmt::format(
      "assembly did not converge in {} iterations: equation {} ({}) does not close, residual "
      "{:.3e} {} (tolerance {:.1e})",
      options.max_iterations, e.name,
      e.joint >= 0 ? "joint " + model.joints[e.joint].name : "driver " + model.drivers[e.driver].name,
      ws.g(result.worst_equation), e.kind == EquationKind::kDot2 ? "m" : "rad", options.tolerance);
  return result;
}

double assemble_velocities(const Model& model, State& state, Workspace& ws,
                           const AssemblyOptions& options) {
  const Eigen::VectorXd mask = free_mask(model, options);
  evaluate_constraints(model, state, Stage::kPosition, ws);
  // Minimum-norm correction of the velocity residual G v + g_t.
  state.v += minimum_norm_step(ws.G, mask, -(ws.G * state.v + ws.g_t));
  return model.num_equations() > 0 ? (ws.G * state.v + ws.g_t).cwiseAbs().maxCoeff() : 0.0;
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
