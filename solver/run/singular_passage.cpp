#include "run/singular_passage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "multibody/redundancy.h"

namespace limber::run {

std::string SingularPassage::message() const {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  const std::string branch =
      velocity_jump < 0.0
          ? "the run went on through it; which branch it took is not checked (the run started "
            "or ended inside the passage): check the motion after it"
      : changed_branch()
          ? fmt::format("the run CHANGED BRANCH there: the frame velocity of {} jumped by {:.2g} "
                        "of the frame speeds across it, an impulse no force of the model gives "
                        "(unless it holds an impact there): a smaller step or tolerance, or a "
                        "start off the singular path, keeps the motion on its branch",
                        jump_body, velocity_jump)
          : fmt::format("the run stayed on the branch it arrived on (velocities continuous "
                        "across it to {:.1g} of the frame speeds)",
                        velocity_jump);
  return fmt::format("the constraint equations lose rank at t = {:.6g} s (singular value {:.2g} "
                     "of its start value; joints {}): a singular configuration, where the "
                     "mechanism may switch branches (a parallelogram may fold into an "
                     "anti-parallelogram); {}",
                     t, ratio, list, branch);
}

namespace {

// True when the measure is certainly above the passage threshold at the Gram matrix S Sᵀ of
// unit rows (m x m), with `rank` independent rows and the start value `start`. With every row
// independent (rank = m) the measure is the smallest eigenvalue of S Sᵀ. A Cholesky factor of
// S Sᵀ − s I exists only when that eigenvalue exceeds s less the factor's rounding, at most
// (m + 1) m ε ‖S Sᵀ‖ (Higham, Accuracy and Stability of Numerical Algorithms, Thm. 10.3); with
// s = 2 τ plus twice that, it is above the passage threshold τ = (kSingularRatio start)² by
// more than the eigen-solve's own rounding, so the eigen-solve would find no passage either.
bool clearly_regular(const Eigen::MatrixXd& gram, int rank, double start) {
  const auto m = gram.rows();
  if (rank != m) return false;
  const double tau = kSingularRatio * kSingularRatio * start * start;
  const double rounding = (static_cast<double>(m) + 1.0) * static_cast<double>(m) *
                          std::numeric_limits<double>::epsilon() * gram.cwiseAbs().rowwise().sum().maxCoeff();
  const double shift = 2.0 * (tau + rounding);
  const Eigen::LLT<Eigen::MatrixXd> shifted(gram - shift * Eigen::MatrixXd::Identity(m, m));
  return shifted.info() == Eigen::Success;
}

}  // namespace

SingularPassageMonitor::SingularPassageMonitor(const multibody::Model& model, int rank,
                                               std::vector<bool> released)
    : model_(model), rank_(rank) {
  for (int row = 0; row < model.num_equations(); ++row) {
    const bool out = static_cast<std::size_t>(row) < released.size() && released[static_cast<std::size_t>(row)];
    if (!out) rows_.push_back(row);
  }
}

bool SingularPassageMonitor::add(const multibody::State& state, const Eigen::MatrixXd& G) {
  if (rank_ <= 0 || model_.num_equations() == 0) return false;
  // The rows still in force only: a released joint's rows would only add zero singular values,
  // and the eigen-solve below costs m³ (the satellite's 48 hold-down rows made it 5 times
  // dearer, 16 % of the run).
  unit_rows_ = multibody::unit_rows(G(rows_, Eigen::all));
  const Eigen::MatrixXd& S = unit_rows_;
  // Singular values and left vectors of S from its Gram matrix S Sᵀ (m x m, cheap for the
  // few equations of a mechanism; JacobiSVD of S made the deployment run 60 % slower). Its
  // eigenvalues ascend: the rank-th largest is at m − rank. Rounding in σ² (1e-16) is far
  // below the threshold (kSingularRatio² ~ 1e-4 of the start value).
  const int m = static_cast<int>(rows_.size());
  if (rank_ > m) return false;
  // S Sᵀ from its lower half (the Cholesky factor reads no other), mirrored for the eigen-solve.
  gram_.setZero(m, m);
  gram_.selfadjointView<Eigen::Lower>().rankUpdate(S);
  gram_.triangularView<Eigen::StrictlyUpper>() = gram_.transpose();
  const Eigen::MatrixXd& gram = gram_;
  // Far from a passage a Cholesky factor proves it (the usual sample), at a fifth of the
  // eigen-solve's cost.
  if (start_ <= 0.0 || !clearly_regular(gram, rank_, start_)) {
    // Eigenvalues only; the vectors (which joints) only near a singularity.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram, Eigen::EigenvaluesOnly);
    const double sigma = std::sqrt(std::max(0.0, eigen.eigenvalues()(m - rank_)));
    if (start_ < 0.0) start_ = sigma;
    const double ratio = start_ > 0.0 ? sigma / start_ : 1.0;
    if (ratio < kSingularRatio) {
      if (!open_) {
        current_ = {};
        current_.ratio = 2.0;  // above any ratio in a passage: the first sample sets it
      }
      if (ratio < current_.ratio) {
        current_.t = state.t;
        current_.ratio = ratio;
        current_.names.clear();
        eigen.compute(gram, Eigen::ComputeEigenvectors);
        const Eigen::VectorXd u = eigen.eigenvectors().col(m - rank_);
        const double largest = u.cwiseAbs().maxCoeff();
        for (int k = 0; k < m; ++k) {
          if (std::abs(u(k)) < 0.1 * largest) continue;
          const multibody::ConstraintEquation& eq = model_.equations[static_cast<size_t>(rows_[k])];
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
  }
  const bool ended = close(&state);
  // The latest two samples outside a passage.
  before_[0] = before_[1];
  before_[1] = {state.t, state.v};
  moments_ = std::min(moments_ + 1, 2);
  return ended;
}

bool SingularPassageMonitor::finish() { return close(nullptr); }

bool SingularPassageMonitor::close(const multibody::State* after) {
  if (!open_) return false;
  open_ = false;
  if (after != nullptr && moments_ == 2) current_.velocity_jump = branch_jump(*after, current_.jump_body);
  last_ = current_;
  return true;
}

double SingularPassageMonitor::branch_jump(const multibody::State& after, std::string& body) const {
  // Linear prediction from the two samples before the passage to the one after it.
  const Moment& b1 = before_[1];
  const Moment& b2 = before_[0];
  const Eigen::VectorXd predicted = b1.v + (b1.v - b2.v) * ((after.t - b1.t) / (b1.t - b2.t));
  // Frame speeds before the passage: the scales of the linear and angular jumps.
  double linear_scale = 0.0, angular_scale = 0.0;
  for (const multibody::Body& b : model_.bodies) {
    if (b.nv < 6) continue;
    linear_scale = std::max(linear_scale, b1.v.segment<3>(b.v_offset).norm());
    angular_scale = std::max(angular_scale, b1.v.segment<3>(b.v_offset + 3).norm());
  }
  double jump = 0.0;
  for (const multibody::Body& b : model_.bodies) {
    if (b.nv < 6) continue;
    const Eigen::VectorXd d = after.v.segment<6>(b.v_offset) - predicted.segment<6>(b.v_offset);
    const double linear = linear_scale > 0.0 ? d.head<3>().norm() / linear_scale : 0.0;
    const double angular = angular_scale > 0.0 ? d.tail<3>().norm() / angular_scale : 0.0;
    if (std::max(linear, angular) > jump) {
      jump = std::max(linear, angular);
      body = b.name;
    }
  }
  return jump;
}

}  // namespace limber::run
