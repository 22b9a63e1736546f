#include "multibody/linearization.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "core/error.h"
#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"

namespace limber::multibody {

namespace {

constexpr double kDifferenceStep = 1e-6;  // ε of the central differences [m, rad, kg^½ m; per s]

// The rows of ws.G and ws.g at `rows`.
Eigen::MatrixXd rows_of(const Eigen::MatrixXd& G, const std::vector<int>& rows) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), G.cols());
  for (std::size_t k = 0; k < rows.size(); ++k) out.row(static_cast<Eigen::Index>(k)) = G.row(rows[k]);
  return out;
}

// r = M(q) v̇0 + G_i(q)ᵀ λ0 − Q(t, q, v) at the state's q and v.
Eigen::VectorXd residual(const Model& model, const std::vector<int>& rows, const State& state,
                         const Eigen::VectorXd& vdot, const Eigen::VectorXd& lambda, Workspace& ws) {
  mass_matrix(model, state, ws);
  generalized_forces(model, state, ws);
  evaluate_constraints(model, state, Stage::kPosition, ws);
  return ws.M * vdot + rows_of(ws.G, rows).transpose() * lambda - ws.Q;
}

// The first-order problem [0 I; −K_m −C_m] of the elastic modes (K_m, C_m in their normal
// coordinates): each root belongs to the normal mode that dominates its displacement part; a
// mode with its two roots gets ω_n = √(s1 s2) and ζ = −(s1 + s2)/(2 ω_n) (a conjugate pair: |s|
// and −Re s/|s|; two real roots: overdamped, ζ > 1). Writes modes' entries `elastic`.
void damp_elastic_modes(const Eigen::MatrixXd& K_m, const Eigen::MatrixXd& C_m, const Eigen::VectorXd& w2,
                        const std::vector<Eigen::Index>& elastic, SystemModes& modes) {
  const Eigen::Index ne = K_m.rows();
  if (ne == 0) return;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * ne, 2 * ne);
  A.topRightCorner(ne, ne).setIdentity();
  A.bottomLeftCorner(ne, ne) = -K_m;
  A.bottomRightCorner(ne, ne) = -C_m;
  const Eigen::EigenSolver<Eigen::MatrixXd> first_order(A, true);
  const Eigen::VectorXcd s = first_order.eigenvalues();
  const Eigen::MatrixXcd V = first_order.eigenvectors();
  std::vector<std::vector<std::complex<double>>> roots(static_cast<std::size_t>(ne));
  for (Eigen::Index r = 0; r < 2 * ne; ++r) {
    Eigen::Index owner = 0;
    V.col(r).head(ne).cwiseAbs().maxCoeff(&owner);
    roots[static_cast<std::size_t>(owner)].push_back(s(r));
  }
  for (Eigen::Index k = 0; k < ne; ++k) {
    const Eigen::Index i = elastic[static_cast<std::size_t>(k)];
    if (w2(i) < 0.0) continue;  // unstable: a growing and a decaying root, no damping ratio
    const auto& own = roots[static_cast<std::size_t>(k)];
    if (own.size() == 2) {
      const double w_n = std::sqrt(std::abs((own[0] * own[1]).real()));
      modes.frequencies_hz(i) = w_n / (2.0 * std::numbers::pi);
      modes.damping(i) = -(own[0] + own[1]).real() / (2.0 * w_n);
    } else {
      // Roots shared out unevenly (close, strongly coupled modes): modal damping φᵀCφ / 2ω.
      ++modes.approximate_damping;
      modes.damping(i) = C_m(k, k) / (2.0 * std::sqrt(w2(i)));
    }
  }
}

// The modes in ascending frequencies_hz (damping may swap close undamped neighbours).
SystemModes sorted_by_frequency(const SystemModes& modes) {
  const Eigen::Index n = modes.frequencies_hz.size();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return modes.frequencies_hz(a) < modes.frequencies_hz(b);
  });
  SystemModes sorted = modes;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = order[static_cast<std::size_t>(k)];
    sorted.frequencies_hz(k) = modes.frequencies_hz(i);
    sorted.damping(k) = modes.damping(i);
    sorted.undamped_hz(k) = modes.undamped_hz(i);
    sorted.shapes.col(k) = modes.shapes.col(i);
  }
  return sorted;
}

}  // namespace

Eigen::VectorXd displaced_coordinates(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& xi) {
  Eigen::VectorXd out = q;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    integrate_body_coordinates(model, static_cast<int>(b), q, xi, out);
  }
  return out;
}

Eigen::MatrixXd null_space_basis(const Eigen::MatrixXd& G, int nv) {
  if (G.rows() == 0) return Eigen::MatrixXd::Identity(nv, nv);
  Eigen::BDCSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
  svd.setThreshold(kRedundancyThreshold);
  return svd.matrixV().rightCols(nv - svd.rank());
}

LinearizationStatus tangent_matrices(const Model& model, const ConstraintPartition& partition,
                                     const State& state, TangentMatrices& out, std::string& message) {
  const int nv = model.nv;
  const std::vector<int>& rows = partition.independent;
  const int nc = static_cast<int>(rows.size());
  Workspace ws(model);
  mass_matrix(model, state, ws);
  generalized_forces(model, state, ws);
  evaluate_constraints(model, state, Stage::kVelocity, ws);
  out.M = ws.M;
  out.G = rows_of(ws.G, rows);
  out.rows = rows;

  // The independent rows must keep their rank here: a lost one frees a motion the joints forbid.
  if (nc > 0) {
    Eigen::BDCSVD<Eigen::MatrixXd> svd(out.G, Eigen::ComputeFullU);
    const Eigen::VectorXd& sigma = svd.singularValues();  // min(nc, nv) of them, descending
    const double smallest = nc > nv ? 0.0 : sigma(nc - 1);
    if (smallest <= kRedundancyThreshold * sigma(0)) {
      // The last left singular vector combines the dependent rows.
      const Eigen::VectorXd u = svd.matrixU().col(nc - 1);
      std::string names;
      for (int k = 0; k < nc; ++k) {
        if (std::abs(u(k)) < 0.1 * u.cwiseAbs().maxCoeff()) continue;
        names += (names.empty() ? "" : ", ") + model.equations[static_cast<std::size_t>(rows[k])].name;
      }
      message = fmt::format(
          "the constraints are singular at the linearization point: equation(s) {} depend on each "
          "other here (smallest singular value {:.3g} of {:.3g}), so the motions the joints allow "
          "are not known to first order; linearize slightly off this configuration",
          names, smallest, sigma(0));
      return LinearizationStatus::kSingularConstraints;
    }
  }

  // v̇0 and λ0 of the state from [M G_iᵀ; G_i 0][v̇; λ] = [Q; γ_i] (zero at an equilibrium).
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nv + nc, nv + nc);
  A.topLeftCorner(nv, nv) = ws.M;
  A.topRightCorner(nv, nc) = out.G.transpose();
  A.bottomLeftCorner(nc, nv) = out.G;
  Eigen::VectorXd b(nv + nc);
  b << ws.Q, Eigen::VectorXd(rows_of(ws.gamma, rows));
  const Eigen::VectorXd x = A.fullPivLu().solve(b);
  out.vdot = x.head(nv);
  out.lambda = x.tail(nc);

  // K = ∂r/∂ξ and C = ∂r/∂v by central differences, column by column.
  out.K.resize(nv, nv);
  out.C.resize(nv, nv);
  State s = state;
  Eigen::VectorXd xi = Eigen::VectorXd::Zero(nv);
  for (int j = 0; j < nv; ++j) {
    xi(j) = kDifferenceStep;
    s.q = displaced_coordinates(model, state.q, xi);
    const Eigen::VectorXd plus = residual(model, rows, s, out.vdot, out.lambda, ws);
    xi(j) = -kDifferenceStep;
    s.q = displaced_coordinates(model, state.q, xi);
    out.K.col(j) = (plus - residual(model, rows, s, out.vdot, out.lambda, ws)) / (2.0 * kDifferenceStep);
    xi(j) = 0.0;
  }
  s.q = state.q;
  for (int j = 0; j < nv; ++j) {
    s.v = state.v;
    s.v(j) += kDifferenceStep;
    const Eigen::VectorXd plus = residual(model, rows, s, out.vdot, out.lambda, ws);
    s.v(j) = state.v(j) - kDifferenceStep;
    out.C.col(j) = (plus - residual(model, rows, s, out.vdot, out.lambda, ws)) / (2.0 * kDifferenceStep);
  }
  return LinearizationStatus::kOk;
}

Eigen::LLT<Eigen::MatrixXd> reduced_mass_factor(const Eigen::MatrixXd& M, const Eigen::MatrixXd& Z) {
  const Eigen::MatrixXd Mr = Z.transpose() * M * Z;
  Eigen::LLT<Eigen::MatrixXd> llt(0.5 * (Mr + Mr.transpose()));
  if (llt.info() != Eigen::Success) {
    throw NumericalError("linearize: the mass matrix on the joints' free motions is not positive definite");
  }
  return llt;
}

SystemModes system_modes(const TangentMatrices& tangent, const Eigen::MatrixXd& Z, double zero_threshold_hz) {
  const Eigen::Index n = Z.cols();
  SystemModes modes;
  modes.frequencies_hz = Eigen::VectorXd::Zero(n);
  modes.damping = Eigen::VectorXd::Zero(n);
  modes.undamped_hz = Eigen::VectorXd::Zero(n);
  modes.shapes = Eigen::MatrixXd::Zero(Z.rows(), n);
  if (n == 0) return modes;

  // Mass-normalized coordinates x = Lᵀ y with Zᵀ M Z = L Lᵀ: ẍ + C̃ ẋ + K̃ x = 0.
  const Eigen::LLT<Eigen::MatrixXd> llt = reduced_mass_factor(tangent.M, Z);
  const auto L = llt.matrixL();
  const auto tilde = [&](const Eigen::MatrixXd& X) {
    const Eigen::MatrixXd Y = L.solve(Z.transpose() * X * Z);
    return Eigen::MatrixXd(L.solve(Y.transpose()).transpose());
  };
  const Eigen::MatrixXd K_t = tilde(tangent.K), C_t = tilde(tangent.C);

  // Undamped normal modes of the symmetric part, ω² ascending.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (K_t + K_t.transpose()));
  const Eigen::VectorXd& w2 = eig.eigenvalues();
  const Eigen::MatrixXd& X = eig.eigenvectors();
  modes.shapes = Z * Eigen::MatrixXd(L.transpose().solve(X));

  // Rigid modes: ω below the threshold.
  const double w_max = std::sqrt(w2.cwiseAbs().maxCoeff());
  const double w_zero = zero_threshold_hz > 0.0 ? 2.0 * std::numbers::pi * zero_threshold_hz
                                                : kRigidFrequencyFraction * w_max;
  modes.zero_threshold_hz = w_zero / (2.0 * std::numbers::pi);
  std::vector<Eigen::Index> elastic;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double f = std::sqrt(std::abs(w2(i))) / (2.0 * std::numbers::pi);
    if (std::abs(w2(i)) <= w_zero * w_zero) {
      ++modes.rigid_modes;
      modes.largest_rigid_hz = std::max(modes.largest_rigid_hz, f);
      continue;
    }
    if (w2(i) < 0.0) ++modes.unstable_modes;
    modes.undamped_hz(i) = w2(i) < 0.0 ? -f : f;
    modes.frequencies_hz(i) = modes.undamped_hz(i);
    elastic.push_back(i);
  }
  // Damped natural frequencies and damping ratios of the elastic modes, then ascending order.
  Eigen::MatrixXd X_e(n, static_cast<Eigen::Index>(elastic.size()));
  for (std::size_t k = 0; k < elastic.size(); ++k) X_e.col(static_cast<Eigen::Index>(k)) = X.col(elastic[k]);
  damp_elastic_modes(X_e.transpose() * K_t * X_e, X_e.transpose() * C_t * X_e, w2, elastic, modes);
  return sorted_by_frequency(modes);
}

}  // namespace limber::multibody
