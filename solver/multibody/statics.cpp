#include "multibody/statics.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "core/minimum_norm.h"
#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

constexpr double kDifferenceStep = 1e-6;  // ε of the central differences [m, rad, kg^½ m]
constexpr int kEquilibrationPasses = 8;   // Ruiz passes: row and column norms within ~1 %
constexpr int kLineSearchHalvings = 12;
// A load along a free motion is real, not rounding, above this fraction of the forces, and
// when it holds this share of the residual (the rest converges, a real one stays).
constexpr double kFreeLoadFraction = 1e-6;
constexpr double kFreeLoadShare = 0.5;
// Below this fraction of σ_max a singular value is zero to rounding (the differences' noise,
// ~1e-10 of an entry, equilibrated), however the loads push: a motion with no stiffness.
constexpr double kZeroStiffness = 1e-13;

// The residual of the equilibrium at (q, λ): force part Q − G_iᵀλ (nv), then g_i (nc).
class EquilibriumResidual {
 public:
  EquilibriumResidual(const Model& model, const ConstraintPartition& partition, const State& start)
      : model_(model), rows_(partition.independent), ws_(model), state_(start) {
    state_.v = Eigen::VectorXd::Zero(model.nv);
  }

  int nv() const { return model_.nv; }
  int nc() const { return static_cast<int>(rows_.size()); }
  const State& state() const { return state_; }
  void set_q(const Eigen::VectorXd& q) { state_.q = q; }

  // Evaluates at the current q: Q, G_i and g_i.
  void evaluate() {
    generalized_forces(model_, state_, ws_);
    evaluate_constraints(model_, state_, Stage::kPosition, ws_);
    G_.resize(nc(), nv());
    g_.resize(nc());
    for (int k = 0; k < nc(); ++k) {
      G_.row(k) = ws_.G.row(rows_[static_cast<std::size_t>(k)]);
      g_(k) = ws_.g(rows_[static_cast<std::size_t>(k)]);
    }
  }
  const Eigen::VectorXd& Q() const { return ws_.Q; }
  const Eigen::MatrixXd& G() const { return G_; }
  const Eigen::VectorXd& g() const { return g_; }
  Eigen::VectorXd force(const Eigen::VectorXd& lambda) const { return ws_.Q - G_.transpose() * lambda; }

  // q ⊕ ξ, body by body.
  Eigen::VectorXd moved(const Eigen::VectorXd& q, const Eigen::VectorXd& xi) const {
    Eigen::VectorXd out = q;
    for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
      integrate_body_coordinates(model_, static_cast<int>(b), q, xi, out);
    }
    return out;
  }

  // ∂(Q − G_iᵀλ)/∂ξ at q by central differences; leaves the evaluation at q.
  Eigen::MatrixXd force_derivative(const Eigen::VectorXd& lambda) {
    const Eigen::VectorXd q = state_.q;
    Eigen::MatrixXd K(nv(), nv());
    Eigen::VectorXd xi = Eigen::VectorXd::Zero(nv());
    for (int j = 0; j < nv(); ++j) {
      xi(j) = kDifferenceStep;
      state_.q = moved(q, xi);
      evaluate();
      const Eigen::VectorXd plus = force(lambda);
      xi(j) = -kDifferenceStep;
      state_.q = moved(q, xi);
      evaluate();
      K.col(j) = (plus - force(lambda)) / (2.0 * kDifferenceStep);
      xi(j) = 0.0;
    }
    state_.q = q;
    evaluate();
    return K;
  }

 private:
  const Model& model_;
  std::vector<int> rows_;
  Workspace ws_;
  State state_;
  Eigen::MatrixXd G_;
  Eigen::VectorXd g_;
};

// Row and column scalings D_r, D_c with D_r A D_c of unit max-norm rows and columns (Ruiz).
void equilibrate(const Eigen::MatrixXd& A, Eigen::VectorXd& D_r, Eigen::VectorXd& D_c) {
  D_r = Eigen::VectorXd::Ones(A.rows());
  D_c = Eigen::VectorXd::Ones(A.cols());
  Eigen::MatrixXd S = A;
  for (int pass = 0; pass < kEquilibrationPasses; ++pass) {
    for (Eigen::Index i = 0; i < S.rows(); ++i) {
      const double m = S.row(i).cwiseAbs().maxCoeff();
      if (m > 0.0) S.row(i) /= std::sqrt(m), D_r(i) /= std::sqrt(m);
    }
    for (Eigen::Index j = 0; j < S.cols(); ++j) {
      const double m = S.col(j).cwiseAbs().maxCoeff();
      if (m > 0.0) S.col(j) /= std::sqrt(m), D_c(j) /= std::sqrt(m);
    }
  }
}

// Whether ξ moves every moving body, two or more, together as one rigid body: one angular
// velocity ω (ground axes), the same u = ṙ_b − ω × r_b for every frame, no elastic rates.
bool moves_as_one_rigid_body(const Model& model, const State& state, const Eigen::VectorXd& xi) {
  if (model.bodies.size() < 3) return false;  // ground and one body: name the body
  const double tolerance = 1e-6 * xi.cwiseAbs().maxCoeff();
  bool first = true;
  Eigen::Vector3d w0, u0;
  for (const Body& body : model.bodies) {
    if (body.nv == 0) continue;
    const Eigen::Matrix3d R_WB = rotation_matrix(state.q.segment<4>(body.q_offset + 3));
    const Eigen::Vector3d w = R_WB * xi.segment<3>(body.v_offset + 3);
    const Eigen::Vector3d u = xi.segment<3>(body.v_offset) - w.cross(state.q.segment<3>(body.q_offset));
    if (body.nv > 6 && xi.segment(body.v_offset + 6, body.nv - 6).cwiseAbs().maxCoeff() > tolerance) return false;
    if (first) {
      w0 = w, u0 = u, first = false;
    } else if ((w - w0).cwiseAbs().maxCoeff() > tolerance || (u - u0).cwiseAbs().maxCoeff() > tolerance) {
      return false;
    }
  }
  return true;
}

// "bus translates along [0 0 1] and turns about [1 0 0]; panel ..." for a motion ξ (nv), or
// "the whole mechanism moves as one rigid body" (a floating system's six).
std::string describe_motion(const Model& model, const State& state, const Eigen::VectorXd& xi) {
  if (moves_as_one_rigid_body(model, state, xi)) return "the whole mechanism moves as one rigid body";
  const double largest = xi.cwiseAbs().maxCoeff();
  std::string text;
  for (const Body& body : model.bodies) {
    if (body.nv == 0) continue;
    const Eigen::VectorXd part = xi.segment(body.v_offset, body.nv);
    if (part.cwiseAbs().maxCoeff() < 0.1 * largest) continue;
    const Eigen::Vector3d r = part.head<3>();
    const Eigen::Matrix3d R_WB = rotation_matrix(state.q.segment<4>(body.q_offset + 3));
    const Eigen::Vector3d w = R_WB * part.segment<3>(3);
    std::string what;
    if (r.norm() >= 0.1 * part.cwiseAbs().maxCoeff()) {
      what = fmt::format("translates along [{:.3g} {:.3g} {:.3g}]", r.x() / r.norm(), r.y() / r.norm(),
                         r.z() / r.norm());
    }
    if (w.norm() >= 0.1 * part.cwiseAbs().maxCoeff()) {
      what += fmt::format("{}turns about [{:.3g} {:.3g} {:.3g}] (ground axes)", what.empty() ? "" : " and ",
                          w.x() / w.norm(), w.y() / w.norm(), w.z() / w.norm());
    }
    if (what.empty()) what = "deforms";
    text += fmt::format("{}{} {}", text.empty() ? "" : "; ", body.name, what);
  }
  return text;
}

// Negative eigenvalues of the stiffness −∂r/∂ξ on the motions the joints allow (G_i z = 0):
// Sylvester's law of inertia makes any basis of that null space do.
int count_unstable_directions(const Eigen::MatrixXd& K_force, const Eigen::MatrixXd& G) {
  const Eigen::MatrixXd K = -0.5 * (K_force + K_force.transpose());
  Eigen::MatrixXd Z;
  if (G.rows() == 0) {
    Z = Eigen::MatrixXd::Identity(K.rows(), K.cols());
  } else {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
    svd.setThreshold(kRedundancyThreshold);
    Z = svd.matrixV().rightCols(G.cols() - svd.rank());
  }
  if (Z.cols() == 0) return 0;
  const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Z.transpose() * K * Z,
                                                                            Eigen::EigenvaluesOnly).eigenvalues();
  const double scale = std::max(eig.cwiseAbs().maxCoeff(), 1e-300);
  return static_cast<int>((eig.array() < -1e-8 * scale).count());
}

}  // namespace

const char* to_string(StaticsStatus status) {
  switch (status) {
    case StaticsStatus::kOk: return "ok";
    case StaticsStatus::kNotConverged: return "not_converged";
    case StaticsStatus::kFreeMotionUnderLoad: return "free_motion_under_load";
  }
  return "?";
}

StaticsResult solve_statics(const Model& model, const ConstraintPartition& partition,
                            const State& start, const StaticsOptions& options) {
  EquilibriumResidual residual(model, partition, start);
  const int nv = residual.nv(), nc = residual.nc();
  StaticsResult result;
  residual.evaluate();
  // Multipliers that balance the forces as well as the joints can: Newton starts near them.
  Eigen::VectorXd lambda = nc > 0 ? minimum_norm_solve(residual.G().transpose(), residual.Q(),
                                                       kRedundancyThreshold)
                                  : Eigen::VectorXd();
  const auto stacked = [&](const Eigen::VectorXd& force) {
    Eigen::VectorXd F(nv + nc);
    F << force, residual.g();
    return F;
  };
  const auto record = [&](const Eigen::VectorXd& force) {
    result.force_scale = std::max({result.force_scale, residual.Q().cwiseAbs().maxCoeff(),
                                   (residual.G().transpose() * lambda).cwiseAbs().maxCoeff()});
    result.force_residual = force.cwiseAbs().maxCoeff();
    result.constraint_residual = nc > 0 ? residual.g().cwiseAbs().maxCoeff() : 0.0;
  };
  Eigen::VectorXd force = residual.force(lambda);
  record(force);
  for (result.iterations = 0;; ++result.iterations) {
    // The Newton matrix [∂r/∂ξ  −G_iᵀ; G_i  0], equilibrated, and its SVD.
    const Eigen::MatrixXd K_force = residual.force_derivative(lambda);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nv + nc, nv + nc);
    J.topLeftCorner(nv, nv) = K_force;
    J.topRightCorner(nv, nc) = -residual.G().transpose();
    J.bottomLeftCorner(nc, nv) = residual.G();
    Eigen::VectorXd D_r, D_c;
    equilibrate(J, D_r, D_c);
    const Eigen::MatrixXd J_s = D_r.asDiagonal() * J * D_c.asDiagonal();
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(J_s, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::VectorXd& sigma = svd.singularValues();
    const double cut = kFreeMotionThreshold * (sigma.size() > 0 ? sigma(0) : 0.0);
    const Eigen::VectorXd F = stacked(force);
    const Eigen::VectorXd b = -(D_r.asDiagonal() * F);

    // Free motions: what load acts along each (the left vector's generalized force). A loaded
    // one whose singular value is not zero to rounding is a soft direction: solved along.
    result.free_motions.clear();
    const double allowed = kFreeLoadFraction * result.force_scale;
    std::vector<bool> solve_along(static_cast<std::size_t>(sigma.size()), false);
    for (Eigen::Index i = 0; i < sigma.size(); ++i) {
      solve_along[static_cast<std::size_t>(i)] = sigma(i) > cut;
      if (sigma(i) > cut) continue;
      const Eigen::VectorXd w = D_r.asDiagonal() * svd.matrixU().col(i);
      const Eigen::VectorXd m = D_c.asDiagonal() * svd.matrixV().col(i);
      const double w_scale = w.head(nv).cwiseAbs().maxCoeff();
      const double load = w_scale > 0.0 ? std::abs(w.dot(F)) / w_scale : 0.0;
      const Eigen::VectorXd motion = m.head(nv);
      if (motion.cwiseAbs().maxCoeff() == 0.0) continue;  // a dependent multiplier, not a motion
      // A real load along the motion is what is left of the residual once Newton has balanced
      // the rest; a computed null vector's error δ only shows δ ‖F‖ of it.
      const bool loaded = load > allowed && load >= kFreeLoadShare * result.force_residual;
      if (loaded && sigma(i) > kZeroStiffness * sigma(0)) {
        solve_along[static_cast<std::size_t>(i)] = true;
        continue;
      }
      result.free_motions.push_back({describe_motion(model, residual.state(), motion), load});
      if (loaded) {
        result.status = StaticsStatus::kFreeMotionUnderLoad;
        result.state = residual.state();
        result.lambda = lambda;
        result.message = fmt::format(
            "static equilibrium: a load meets no stiffness: {} freely, and the applied loads "
            "push along that motion (generalized force {:.3g}); hold it with a joint, a spring or "
            "a driver, or remove the load",
            result.free_motions.back().description, load);
        return result;
      }
    }
    if (result.force_residual <= options.force_tolerance * result.force_scale &&
        result.constraint_residual <= options.constraint_tolerance) {
      result.unstable_directions = count_unstable_directions(K_force, residual.G());
      break;
    }
    if (result.iterations == options.max_iterations) {
      result.status = StaticsStatus::kNotConverged;
      result.message = fmt::format(
          "static equilibrium not found in {} Newton iterations: force residual {:.3g} of the "
          "largest force {:.3g}, constraint residual {:.3g}; the loads may exceed what the "
          "mechanism can carry (a snap-through), or the start is far from any equilibrium",
          options.max_iterations, result.force_residual, result.force_scale, result.constraint_residual);
      break;
    }

    // The minimum-norm Newton step: free motions stay where they are.
    Eigen::VectorXd y = Eigen::VectorXd::Zero(nv + nc);
    for (Eigen::Index i = 0; i < sigma.size(); ++i) {
      if (solve_along[static_cast<std::size_t>(i)]) y += svd.matrixV().col(i) * (svd.matrixU().col(i).dot(b) / sigma(i));
    }
    const Eigen::VectorXd step = D_c.asDiagonal() * y;

    // Backtracking on the scaled residual norm.
    const Eigen::VectorXd q0 = residual.state().q;
    const Eigen::VectorXd lambda0 = lambda;
    const double merit0 = b.norm();
    double alpha = 1.0;
    for (int halving = 0;; ++halving) {
      residual.set_q(residual.moved(q0, alpha * step.head(nv)));
      lambda = lambda0 + alpha * step.tail(nc);
      residual.evaluate();
      force = residual.force(lambda);
      const double merit = (D_r.asDiagonal() * stacked(force)).norm();
      if (merit <= (1.0 - 1e-4 * alpha) * merit0 || halving == kLineSearchHalvings) break;
      alpha *= 0.5;
    }
    record(force);
  }
  result.state = residual.state();
  result.lambda = lambda;
  return result;
}

}  // namespace limber::multibody
