#include "nonlinear_beam/static_solver.h"

#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <cmath>

#include "core/error.h"
#include "fe/assembly.h"

namespace limber::nonlinear_beam {

namespace {

// Outcome of Newton at one load factor.
struct NewtonOutcome {
  StaticStatus status = StaticStatus::kConverged;
  int iterations = 0;
  double residual = 0.0;  // last relative residual
};

NewtonOutcome newton(const BeamStructure& structure, const Eigen::VectorXd& f_ext, double lambda,
                     const StaticOptions& options, BeamState& state) {
  const std::vector<int>& free = structure.free_dofs;
  const double f_scale = std::max(f_ext.norm(), 1e-300);
  NewtonOutcome out;
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  bool pattern_known = false;
  for (int it = 0; it < options.max_iterations; ++it) {
    // Residual on the free DOFs.
    ForceAndTangent ft = internal_force_and_tangent(structure, state);
    const Eigen::VectorXd r_full = ft.force - lambda * f_ext;
    Eigen::VectorXd r(free.size());
    for (std::size_t i = 0; i < free.size(); ++i) r(i) = r_full(free[i]);
    out.residual = r.norm() / f_scale;
    if (!std::isfinite(out.residual)) {
      out.status = StaticStatus::kNotConverged;
      return out;
    }

    // Newton step on the free DOFs.
    const SparseMatrix k = fe::restrict_to(ft.tangent, free);
    if (!pattern_known) {
      lu.analyzePattern(k);
      pattern_known = true;
    }
    lu.factorize(k);
    if (lu.info() != Eigen::Success) {
      out.status = StaticStatus::kSingularTangent;
      return out;
    }
    const Eigen::VectorXd step = lu.solve(-r);
    Eigen::VectorXd delta = Eigen::VectorXd::Zero(structure.dof_count());
    for (std::size_t i = 0; i < free.size(); ++i) delta(free[i]) = step(i);
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
      for (int i : free) r2 += f_after(i) * f_after(i);
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

  StaticSolution solution;
  solution.state = reference_state(structure);
  double step = 1.0 / options.load_increments;
  int bisections = 0;
  while (solution.load_factor < 1.0) {
    // Next load factor, landing exactly on 1.
    double target = solution.load_factor + step;
    if (target > 1.0 - 1e-12) target = 1.0;
    BeamState trial = solution.state;
    const NewtonOutcome outcome = newton(structure, f_ext, target, options, trial);
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
