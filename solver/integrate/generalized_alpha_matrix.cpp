// Generalized-α's iteration matrix: when it is rebuilt, the structured matrix (dense, with the
// kept difference; or sparse, filled through slots found once per pattern), its factorisation
// (dense LU or KLU) and solves. The scheme itself is in generalized_alpha.cpp.
#include "integrate/generalized_alpha.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "integrate/singular_test.h"

namespace limber::integrate {
namespace {

// A compressed sparse matrix's pattern as one array: its outer, then its inner indices.
std::vector<int> sparse_pattern(const Eigen::SparseMatrix<double>& A) {
  std::vector<int> out(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  out.insert(out.end(), A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  return out;
}

}  // namespace

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
  if (coupled_derivatives(h)) block += beta * h * h * coupled_;
}

bool GeneralizedAlpha::coupled_derivatives(double h) {
  const bool stiffness = system_->coupled_stiffness(next_.t, next_.q, coupled_);
  if (!system_->coupled_damping(next_.t, next_.q, coupled_damping_)) return stiffness;
  // ∂v/∂ξ = γ/(βh) ∂q/∂ξ: the damping enters as a stiffness scaled by γ/(βh).
  const double scale = coef_.gamma / (coef_.beta * h);
  if (stiffness) {
    coupled_ += scale * coupled_damping_;
  } else {
    coupled_ = scale * coupled_damping_;
  }
  return true;
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
  const bool coupled = coupled_derivatives(h);
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


}  // namespace limber::integrate
