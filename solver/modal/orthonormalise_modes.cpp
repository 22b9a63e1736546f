#include "modal/orthonormalise_modes.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "core/error.h"
#include "modal/normal_modes.h"

namespace limber::modal {
namespace {

// Dimension of span(Q) ∩ span(rigid): principal cosines near 1 (Q M-orthonormal).
int rigid_dimension(const Eigen::SparseMatrix<double>& mass, const Eigen::MatrixXd& m_q,
                    const Eigen::MatrixXd& rigid_motion) {
  if (rigid_motion.cols() == 0 || m_q.cols() == 0) return 0;
  // M-orthonormal rigid basis R = Psi_N L^-T with Psi_N^T M Psi_N = L L^T.
  const Eigen::LLT<Eigen::MatrixXd> llt(rigid_motion.transpose() * (mass * rigid_motion));
  const Eigen::MatrixXd cosines =
      llt.matrixL().solve((m_q.transpose() * rigid_motion).transpose()).transpose();
  const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(cosines).singularValues();
  int d = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s[i] > 1.0 - kRigidCosineTolerance) ++d;
  }
  return d;
}

// The candidates M-orthonormalised by Gram-Schmidt (two passes), nearly dependent ones dropped.
struct GramSchmidtBasis {
  Eigen::MatrixXd q;               // n x kept, M-orthonormal
  Eigen::MatrixXd m_q;             // M q
  Eigen::VectorXd candidate_norm;  // M-norm of each candidate, m
  std::vector<bool> dropped;       // per candidate
};

GramSchmidtBasis gram_schmidt(const Eigen::SparseMatrix<double>& mass,
                              const Eigen::MatrixXd& candidates, const std::vector<ModeInfo>& info,
                              double dependency_tolerance, std::vector<std::string>& notices) {
  const Eigen::Index n = candidates.rows();
  const Eigen::Index m = candidates.cols();
  GramSchmidtBasis basis{Eigen::MatrixXd(n, m), Eigen::MatrixXd(n, m), Eigen::VectorXd(m),
                         std::vector<bool>(static_cast<std::size_t>(m), false)};
  Eigen::MatrixXd& q = basis.q;
  Eigen::MatrixXd& m_q = basis.m_q;
  Eigen::Index kept = 0;
  for (Eigen::Index j = 0; j < m; ++j) {
    Eigen::VectorXd x = candidates.col(j);
    basis.candidate_norm[j] = std::sqrt(x.dot(mass * x));
    for (int pass = 0; pass < 2; ++pass) {
      for (Eigen::Index i = 0; i < kept; ++i) x -= q.col(i) * m_q.col(i).dot(x);
    }
    Eigen::VectorXd m_x = mass * x;
    const double norm = std::sqrt(std::max(x.dot(m_x), 0.0));
    const double relative = basis.candidate_norm[j] > 0.0 ? norm / basis.candidate_norm[j] : 0.0;
    if (relative < dependency_tolerance) {
      notices.push_back(fmt::format(
          "dropped {}: dependent on the vectors before it (M-norm left after projection {:.3g} "
          "of its own, tolerance {:.3g})",
          info[static_cast<std::size_t>(j)].label, relative, dependency_tolerance));
      basis.dropped[static_cast<std::size_t>(j)] = true;
      continue;
    }
    q.col(kept) = x / norm;
    m_q.col(kept) = m_x / norm;
    ++kept;
  }
  q.conservativeResize(n, kept);
  m_q.conservativeResize(n, kept);
  return basis;
}

// One-to-one origin labels: each final mode takes the candidate with the largest M-weighted
// participation |phi^T M x| / |x|_M left, dropped candidates never.
std::vector<int> origin_of_modes(const Eigen::MatrixXd& m_phi, const Eigen::MatrixXd& candidates,
                                 const GramSchmidtBasis& basis) {
  Eigen::MatrixXd participation = (m_phi.transpose() * candidates).cwiseAbs();
  for (Eigen::Index j = 0; j < candidates.cols(); ++j) {
    if (basis.dropped[static_cast<std::size_t>(j)]) {
      participation.col(j).setConstant(-1.0);
    } else {
      participation.col(j) /= basis.candidate_norm[j];
    }
  }
  std::vector<int> origin(static_cast<std::size_t>(m_phi.cols()), -1);
  for (Eigen::Index assigned = 0; assigned < m_phi.cols(); ++assigned) {
    Eigen::Index k = 0;
    Eigen::Index j = 0;
    participation.maxCoeff(&k, &j);
    origin[static_cast<std::size_t>(k)] = static_cast<int>(j);
    participation.row(k).setConstant(-1.0);
    participation.col(j).setConstant(-1.0);
  }
  return origin;
}

}  // namespace

OrthonormalisedModes orthonormalise_modes(const Eigen::SparseMatrix<double>& stiffness,
                                          const Eigen::SparseMatrix<double>& mass,
                                          const Eigen::MatrixXd& candidates,
                                          const std::vector<ModeInfo>& info,
                                          const Eigen::MatrixXd& rigid_motion,
                                          double dependency_tolerance) {
  const Eigen::Index n = candidates.rows();
  const Eigen::Index m = candidates.cols();
  LIMBER_DEMAND(static_cast<std::size_t>(m) == info.size());
  LIMBER_DEMAND(dependency_tolerance > 0.0 && dependency_tolerance < 1.0);
  OrthonormalisedModes result;

  // 1. M-Gram-Schmidt, two passes, dropping nearly dependent candidates.
  const GramSchmidtBasis basis =
      gram_schmidt(mass, candidates, info, dependency_tolerance, result.notices);
  const Eigen::MatrixXd& q = basis.q;
  const Eigen::MatrixXd& m_q = basis.m_q;
  const Eigen::Index kept = q.cols();

  // 2. Reduced eigenproblem on the span: K_r = Q^T K Q, M_r = I.
  Eigen::MatrixXd k_r = q.transpose() * (stiffness * q);
  k_r = 0.5 * (k_r + k_r.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reduced(k_r);
  // Fails only on non-finite entries: no mode then, and the notice says why (the caller turns
  // an empty set into the status "no mode left").
  if (reduced.info() != Eigen::Success) {
    result.notices.push_back("the reduced eigenproblem Qᵀ K Q did not converge (non-finite "
                             "stiffness or mass values)");
    result.mode_set.shapes.resize(n, 0);
    return result;
  }

  // 3. Drop the zero-frequency vectors of rigid motion contained in the span.
  const int d = rigid_dimension(mass, m_q, rigid_motion);
  const Eigen::Index final_count = kept - d;
  if (d > 0) {
    result.notices.push_back(fmt::format(
        "removed {} zero-frequency vector(s): rigid motion in the span, carried by the frame", d));
    const double f_dropped = std::abs(frequency_hz(reduced.eigenvalues()[d - 1]));
    if (final_count > 0 &&
        f_dropped >= kRigidFrequencyRatio * frequency_hz(reduced.eigenvalues()[d])) {
      result.notices.push_back(fmt::format(
          "a removed rigid vector has {:.6g} Hz, not far below the next ({:.6g} Hz)", f_dropped,
          frequency_hz(reduced.eigenvalues()[d])));
    }
  }
  const Eigen::MatrixXd phi = q * reduced.eigenvectors().rightCols(final_count);
  const Eigen::VectorXd omega2 = reduced.eigenvalues().tail(final_count);

  // 4. One-to-one origin labels by decreasing M-weighted participation.
  const Eigen::MatrixXd m_phi = m_q * reduced.eigenvectors().rightCols(final_count);
  const std::vector<int> origin = origin_of_modes(m_phi, candidates, basis);

  ModeSet& set = result.mode_set;
  set.shapes = phi;
  set.modal_stiffness = omega2;
  for (Eigen::Index k = 0; k < final_count; ++k) {
    ModeInfo mode = info[static_cast<std::size_t>(origin[static_cast<std::size_t>(k)])];
    mode.frequency_hz = frequency_hz(omega2[k]);
    set.modes.push_back(mode);
  }
  return result;
}

}  // namespace limber::modal
