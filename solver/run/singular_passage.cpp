#include "run/singular_passage.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "multibody/constraints.h"
#include "multibody/redundancy.h"

namespace limber::run {

std::string SingularPassage::message() const {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return fmt::format("the constraint equations lose rank at t = {:.6g} s (singular value {:.2g} "
                     "of its start value; joints {}): a singular configuration, where the "
                     "mechanism may switch branches (a parallelogram may fold into an "
                     "anti-parallelogram); the run went on through it on one branch: check "
                     "the motion after it",
                     t, ratio, list);
}

SingularPassageMonitor::SingularPassageMonitor(const multibody::Model& model, int rank)
    : model_(model), rank_(rank), workspace_(model) {}

bool SingularPassageMonitor::add(const multibody::State& state) {
  if (rank_ <= 0 || model_.num_equations() == 0) return false;
  multibody::evaluate_constraints(model_, state, multibody::Stage::kPosition, workspace_);
  const Eigen::MatrixXd S = multibody::unit_rows(workspace_.G);
  // Singular values and left vectors of S from its Gram matrix S Sᵀ (m x m, cheap for the
  // few equations of a mechanism; JacobiSVD of S made the deployment run 60 % slower). Its
  // eigenvalues ascend: the rank-th largest is at m − rank. Rounding in σ² (1e-16) is far
  // below the threshold (kSingularRatio² ~ 1e-4 of the start value).
  const int m = model_.num_equations();
  if (rank_ > m) return false;
  const Eigen::MatrixXd gram = S * S.transpose();
  // Eigenvalues only at every sample; the vectors (which joints) only near a singularity.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram, Eigen::EigenvaluesOnly);
  const double sigma = std::sqrt(std::max(0.0, eigen.eigenvalues()(m - rank_)));
  if (start_ < 0.0) start_ = sigma;
  const double ratio = start_ > 0.0 ? sigma / start_ : 1.0;
  if (ratio < kSingularRatio) {
    if (!open_ || ratio < current_.ratio) {
      current_.t = state.t;
      current_.ratio = ratio;
      current_.names.clear();
      eigen.compute(gram, Eigen::ComputeEigenvectors);
      const Eigen::VectorXd u = eigen.eigenvectors().col(m - rank_);
      const double largest = u.cwiseAbs().maxCoeff();
      for (int row = 0; row < model_.num_equations(); ++row) {
        if (std::abs(u(row)) < 0.1 * largest) continue;
        const multibody::ConstraintEquation& eq = model_.equations[static_cast<size_t>(row)];
        const std::string name =
            eq.joint >= 0 ? model_.joints[static_cast<size_t>(eq.joint)].name
                          : eq.name.substr(0, eq.name.find('.'));
        if (std::find(current_.names.begin(), current_.names.end(), name) == current_.names.end()) {
          current_.names.push_back(name);
        }
      }
    }
    open_ = true;
    return false;
  }
  return finish();
}

bool SingularPassageMonitor::finish() {
  if (!open_) return false;
  open_ = false;
  last_ = current_;
  return true;
}

}  // namespace limber::run
