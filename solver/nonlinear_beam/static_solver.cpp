#include "nonlinear_beam/static_solver.h"

#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <cmath>

#include "core/error.h"

namespace limber::nonlinear_beam {

namespace {

// Outcome of Newton at one load factor.
struct NewtonOutcome {
  StaticStatus status = StaticStatus::kConverged;
  int iterations = 0;
  double residual = 0.0;  // last relative residual
};

// What the Newton iterations of one solve share: the assembly workspace, the LU factor (its
// pattern analysed once: the tangent's pattern never changes) and the fixed-DOF mask.
struct NewtonContext {
  BeamWorkspace workspace;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  bool pattern_analysed = false;
  std::vector<bool> fixed;
};

// Holds the fixed DOFs in the full tangent in place: their rows and columns become those of
// the identity, so the solve gives zero increments there.
void hold_fixed_dofs(const std::vector<bool>& fixed, SparseMatrix& k) {
  for (int col = 0; col < k.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(k, col); it; ++it) {
      if (fixed[it.row()] || fixed[col]) it.valueRef() = it.row() == col ? 1.0 : 0.0;
    }
  }
}

NewtonOutcome newton(const BeamStructure& structure, const Eigen::VectorXd& f_ext, double lambda,
                     const StaticOptions& options, NewtonContext& context, BeamState& state) {
  const double f_scale = std::max(f_ext.norm(), 1e-300);
  NewtonOutcome out;
  for (int it = 0; it < options.max_iterations; ++it) {
    // Residual, zero at the fixed DOFs.
    evaluate_force_and_tangent(structure, state, context.workspace);
    Eigen::VectorXd r = context.workspace.result.force - lambda * f_ext;
    for (int i = 0; i < structure.dof_count(); ++i) {
      if (context.fixed[i]) r(i) = 0.0;
    }
    out.residual = r.norm() / f_scale;
    if (!std::isfinite(out.residual)) {
      out.status = StaticStatus::kNotConverged;
      return out;
    }

    // Newton step.
    SparseMatrix& k = context.workspace.result.tangent;
    hold_fixed_dofs(context.fixed, k);
    if (!context.pattern_analysed) {
      context.lu.analyzePattern(k);
      context.pattern_analysed = true;
    }
    context.lu.factorize(k);
    if (context.lu.info() != Eigen::Success) {
      out.status = StaticStatus::kSingularTangent;
      return out;
    }
    const Eigen::VectorXd delta = context.lu.solve(-r);
    apply_increment(state, delta);
    out.iterations = it + 1;

    // Increment test (translations against the size, spins in rad) and residual test.
    double du = 0.0;
    double dw = 0.0;
    for (int node = 0; node < structure.node_count(); ++node) {
      du = std::max(du, delta.segment<3>(6 * node).cwiseAbs().maxCoeff());
      dw = std::max(dw, delta.segment<3>(6 * node + 3).cwiseAbs().maxCoeff());
    }
    const bool small_step = du <= options.increment_tolerance * structure.size &&
                            dw <= options.increment_tolerance;
    if (small_step) {
      // The residual after the step decides.
      const Eigen::VectorXd f_after = internal_force(structure, state) - lambda * f_ext;
      double r2 = 0.0;
      for (int i : structure.free_dofs) r2 += f_after(i) * f_after(i);
      out.residual = std::sqrt(r2) / f_scale;
      if (out.residual <= options.residual_tolerance ||
          std::sqrt(r2) <= structure.force_roundoff) {
        return out;
      }
    }
  }
  out.status = StaticStatus::kNotConverged;
  return out;
}

}  // namespace

StaticSolution solve_static(const BeamStructure& structure, const std::vector<NodalLoad>& loads,
                            const StaticOptions& options) {
  LIMBER_DEMAND(options.load_increments >= 1 && options.max_iterations >= 1);

  // The total external load vector.
  Eigen::VectorXd f_ext = Eigen::VectorXd::Zero(structure.dof_count());
  for (const NodalLoad& load : loads) {
    LIMBER_DEMAND(load.node >= 0 && load.node < structure.node_count());
    f_ext.segment<3>(6 * load.node) += load.force;
    f_ext.segment<3>(6 * load.node + 3) += load.moment;
  }

  // Shared Newton data.
  NewtonContext context;
  context.workspace = make_workspace(structure);
  context.fixed.assign(structure.dof_count(), true);
  for (int i : structure.free_dofs) context.fixed[i] = false;

  StaticSolution solution;
  solution.state = reference_state(structure);
  double step = 1.0 / options.load_increments;
  int bisections = 0;
  while (solution.load_factor < 1.0) {
    // Next load factor, landing exactly on 1.
    double target = solution.load_factor + step;
    if (target > 1.0 - 1e-12) target = 1.0;
    BeamState trial = solution.state;
    const NewtonOutcome outcome = newton(structure, f_ext, target, options, context, trial);
    if (outcome.status == StaticStatus::kConverged) {
      solution.state = std::move(trial);
      solution.load_factor = target;
      solution.iterations.push_back(outcome.iterations);
      continue;
    }
    // Halve the increment, or give up.
    if (bisections < options.max_bisections) {
      ++bisections;
      step *= 0.5;
      continue;
    }
    solution.status = outcome.status;
    solution.message = fmt::format(
        "nonlinear beam statics: Newton-Raphson failed at load factor {:.6g} (last converged "
        "{:.6g}, after {} halvings of the increment): {} (relative residual {:.3g} after {} "
        "iterations, tolerance {:.3g})",
        target, solution.load_factor, bisections,
        outcome.status == StaticStatus::kSingularTangent ? "singular tangent stiffness"
                                                         : "no convergence",
        outcome.residual, outcome.iterations, options.residual_tolerance);
    return solution;
  }
  return solution;
}

void require_converged(const StaticSolution& solution) {
  if (solution.status != StaticStatus::kConverged) throw NumericalError(solution.message);
}

}  // namespace limber::nonlinear_beam
