#include "multibody/statics.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "core/error.h"
#include "core/minimum_norm.h"
#include "multibody/body.h"
#include "multibody/constraints.h"
#include "multibody/dynamics.h"
#include "multibody/nonlinear_body.h"
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
// The force residual's floor with nonlinear bodies, as a share of BeamStructure::force_roundoff
// (100 ε max|K_l| (size + max|X|)): an element's axial force is EA/l times a length difference,
// whose rounding stalls Newton there (measured ≈ 1e-7 N on a 1 m, 20-element steel beam, whose
// force_roundoff is 3.7e-5 N), whatever the loads; below it no iterate is better than another.
constexpr double kBeamRoundoffShare = 0.1;

// The residual of the equilibrium at (q, λ) and load factor s: force part
// s (Q − Q_b) + Q_b − G_iᵀλ (nv), then g_i (nc). Q_b, the beams of nonlinear bodies, is the
// structure and is never scaled; s < 1 only while loads are stepped onto a nonlinear body.
class EquilibriumResidual {
 public:
  EquilibriumResidual(const Model& model, const ConstraintPartition& partition, const State& start)
      : model_(model), rows_(partition.independent), ws_(model), state_(start) {
    state_.v = Eigen::VectorXd::Zero(model.nv);
    Q_beams_ = Eigen::VectorXd::Zero(model.nv);
    for (const NonlinearBody& body : model.nonlinear_bodies) {
      force_floor_ = std::max(force_floor_, kBeamRoundoffShare * body.structure->force_roundoff);
    }
  }

  int nv() const { return model_.nv; }
  int nc() const { return static_cast<int>(rows_.size()); }
  const State& state() const { return state_; }
  void set_q(const Eigen::VectorXd& q) { state_.q = q; }
  double load_factor() const { return load_factor_; }
  void set_load_factor(double s) { load_factor_ = s; }

  // Evaluates at the current q: Q (scaled as above), G_i and g_i.
  void evaluate() {
    generalized_forces(model_, state_, ws_);
    Q_ = ws_.Q;
    if (!model_.nonlinear_bodies.empty()) {
      Q_beams_.setZero();
      add_nonlinear_body_forces(model_, state_.q, state_.v, Q_beams_);
      Q_ = load_factor_ * (ws_.Q - Q_beams_) + Q_beams_;
    }
    evaluate_constraints(model_, state_, Stage::kPosition, ws_);
    G_.resize(nc(), nv());
    g_.resize(nc());
    for (int k = 0; k < nc(); ++k) {
      G_.row(k) = ws_.G.row(rows_[static_cast<std::size_t>(k)]);
      g_(k) = ws_.g(rows_[static_cast<std::size_t>(k)]);
    }
  }
  const Eigen::VectorXd& Q() const { return Q_; }
  double force_floor() const { return force_floor_; }
  const Eigen::MatrixXd& G() const { return G_; }
  const Eigen::VectorXd& g() const { return g_; }
  Eigen::VectorXd force(const Eigen::VectorXd& lambda) const { return Q_ - G_.transpose() * lambda; }

  // q ⊕ ξ, body by body.
  Eigen::VectorXd moved(const Eigen::VectorXd& q, const Eigen::VectorXd& xi) const {
    Eigen::VectorXd out = q;
    for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
      integrate_body_coordinates(model_, static_cast<int>(b), q, xi, out);
    }
    return out;
  }

  // ∂(Q − G_iᵀλ)/∂ξ at q by central differences, the beams' coupled stiffness with the rest;
  // leaves the evaluation at q.
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
  double load_factor_ = 1.0;
  double force_floor_ = 0.0;  // [N, N·m] (kBeamRoundoffShare)
  Eigen::VectorXd Q_, Q_beams_;
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

// The Newton matrix [∂r/∂ξ  −G_iᵀ; G_i  0] at the residual's evaluation, equilibrated, and its SVD.
struct NewtonMatrix {
  Eigen::MatrixXd K_force;  // ∂(Q − G_iᵀλ)/∂ξ
  Eigen::VectorXd D_r, D_c;
  Eigen::BDCSVD<Eigen::MatrixXd> svd;
};

NewtonMatrix newton_matrix(EquilibriumResidual& residual, const Eigen::VectorXd& lambda) {
  const int nv = residual.nv(), nc = residual.nc();
  NewtonMatrix matrix;
  matrix.K_force = residual.force_derivative(lambda);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nv + nc, nv + nc);
  J.topLeftCorner(nv, nv) = matrix.K_force;
  J.topRightCorner(nv, nc) = -residual.G().transpose();
  J.bottomLeftCorner(nc, nv) = residual.G();
  equilibrate(J, matrix.D_r, matrix.D_c);
  matrix.svd.compute(matrix.D_r.asDiagonal() * J * matrix.D_c.asDiagonal(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  return matrix;
}

// Newton's method on (q, λ) at one load factor, recording its progress in `result`.
class NewtonIteration {
 public:
  NewtonIteration(const Model& model, EquilibriumResidual& residual, const StaticsOptions& options,
                  StaticsResult& result)
      : model_(model), residual_(residual), options_(options), result_(result),
        full_steps_(!model.nonlinear_bodies.empty()) {}

  const Eigen::VectorXd& lambda() const { return lambda_; }

  // Iterates to the equilibrium at load factor s from the residual's q; on failure
  // result.message says why. Returns the status (also left in result.status).
  StaticsStatus solve(double s) {
    residual_.set_load_factor(s);
    residual_.evaluate();
    // Multipliers that balance the forces as well as the joints can: Newton starts near them.
    lambda_ = residual_.nc() > 0 ? minimum_norm_solve(residual_.G().transpose(), residual_.Q(), kRedundancyThreshold)
                                 : Eigen::VectorXd();
    force_ = residual_.force(lambda_);
    record();
    for (int iteration = 0;; ++iteration) {
      const NewtonMatrix matrix = newton_matrix(residual_, lambda_);
      const Eigen::VectorXd b = -(matrix.D_r.asDiagonal() * stacked(force_));
      std::vector<bool> solve_along;
      if (!classify_free_motions(matrix, solve_along)) return result_.status;
      if (result_.force_residual <= std::max(options_.force_tolerance * result_.force_scale, residual_.force_floor()) &&
          result_.constraint_residual <= options_.constraint_tolerance) {
        result_.unstable_directions = count_unstable_directions(matrix.K_force, residual_.G());
        return result_.status = StaticsStatus::kOk;
      }
      if (iteration == options_.max_iterations) {
        result_.message = fmt::format(
            "static equilibrium not found in {} Newton iterations: force residual {:.3g} of the "
            "largest force {:.3g}, constraint residual {:.3g}; the loads may exceed what the "
            "mechanism can carry (a snap-through), or the start is far from any equilibrium",
            options_.max_iterations, result_.force_residual, result_.force_scale, result_.constraint_residual);
        return result_.status = StaticsStatus::kNotConverged;
      }
      // The minimum-norm Newton step: free motions stay where they are.
      const Eigen::VectorXd& sigma = matrix.svd.singularValues();
      Eigen::VectorXd y = Eigen::VectorXd::Zero(sigma.size());
      for (Eigen::Index i = 0; i < sigma.size(); ++i) {
        if (solve_along[static_cast<std::size_t>(i)]) {
          y += matrix.svd.matrixV().col(i) * (matrix.svd.matrixU().col(i).dot(b) / sigma(i));
        }
      }
      line_search(matrix, matrix.D_c.asDiagonal() * y, b.norm());
      ++result_.iterations;
    }
  }

 private:
  Eigen::VectorXd stacked(const Eigen::VectorXd& force) const {
    Eigen::VectorXd F(residual_.nv() + residual_.nc());
    F << force, residual_.g();
    return F;
  }

  void record() {
    result_.force_scale = std::max({result_.force_scale, residual_.Q().cwiseAbs().maxCoeff(),
                                    (residual_.G().transpose() * lambda_).cwiseAbs().maxCoeff()});
    result_.force_residual = force_.cwiseAbs().maxCoeff();
    result_.constraint_residual = residual_.nc() > 0 ? residual_.g().cwiseAbs().maxCoeff() : 0.0;
  }

  // Free motions: what load acts along each (the left vector's generalized force). A loaded one
  // whose singular value is not zero to rounding is a soft direction: solved along. Returns
  // false (result filled) when a load pushes along a motion with no stiffness.
  bool classify_free_motions(const NewtonMatrix& matrix, std::vector<bool>& solve_along) {
    const Eigen::VectorXd& sigma = matrix.svd.singularValues();
    const double cut = kFreeMotionThreshold * (sigma.size() > 0 ? sigma(0) : 0.0);
    const Eigen::VectorXd F = stacked(force_);
    const double allowed = kFreeLoadFraction * result_.force_scale;
    result_.free_motions.clear();
    solve_along.assign(static_cast<std::size_t>(sigma.size()), false);
    for (Eigen::Index i = 0; i < sigma.size(); ++i) {
      solve_along[static_cast<std::size_t>(i)] = sigma(i) > cut;
      if (sigma(i) > cut) continue;
      const Eigen::VectorXd w = matrix.D_r.asDiagonal() * matrix.svd.matrixU().col(i);
      const Eigen::VectorXd motion = (matrix.D_c.asDiagonal() * matrix.svd.matrixV().col(i)).head(residual_.nv());
      const double w_scale = w.head(residual_.nv()).cwiseAbs().maxCoeff();
      const double load = w_scale > 0.0 ? std::abs(w.dot(F)) / w_scale : 0.0;
      if (motion.cwiseAbs().maxCoeff() == 0.0) continue;  // a dependent multiplier, not a motion
      // A real load along the motion is what is left of the residual once Newton has balanced
      // the rest; a computed null vector's error δ only shows δ ‖F‖ of it.
      const bool loaded = load > allowed && load >= kFreeLoadShare * result_.force_residual;
      if (loaded && sigma(i) > kZeroStiffness * sigma(0)) {
        solve_along[static_cast<std::size_t>(i)] = true;
        continue;
      }
      result_.free_motions.push_back({describe_motion(model_, residual_.state(), motion), load});
      if (loaded) {
        result_.status = StaticsStatus::kFreeMotionUnderLoad;
        result_.message = fmt::format(
            "static equilibrium: a load meets no stiffness: {} freely, and the applied loads "
            "push along that motion (generalized force {:.3g}); hold it with a joint, a spring or "
            "a driver, or remove the load",
            result_.free_motions.back().description, load);
        return false;
      }
    }
    return true;
  }

  // Backtracking on the scaled residual norm along (Δξ, Δλ) = step from merit0 = ‖b‖.
  void line_search(const NewtonMatrix& matrix, const Eigen::VectorXd& step, double merit0) {
    const int nv = residual_.nv(), nc = residual_.nc();
    const Eigen::VectorXd q0 = residual_.state().q;
    const Eigen::VectorXd lambda0 = lambda_;
    double alpha = 1.0;
    for (int halving = 0;; ++halving) {
      residual_.set_q(residual_.moved(q0, alpha * step.head(nv)));
      lambda_ = lambda0 + alpha * step.tail(nc);
      residual_.evaluate();
      force_ = residual_.force(lambda_);
      const double merit = (matrix.D_r.asDiagonal() * stacked(force_)).norm();
      if (full_steps_ || merit <= (1.0 - 1e-4 * alpha) * merit0 || halving == kLineSearchHalvings) break;
      alpha *= 0.5;
    }
    record();
  }

  const Model& model_;
  EquilibriumResidual& residual_;
  const StaticsOptions& options_;
  StaticsResult& result_;
  Eigen::VectorXd lambda_, force_;
  // Full Newton steps with a nonlinear body (the load increments globalise instead, as in
  // nonlinear_beam/static_solver.h): backtracking on the residual's norm stalled on a
  // tip-loaded cantilever (the norm grew for 50 iterations of ever shorter steps; the beams'
  // axial forces, EA/l ~ 1e9 N/m, dominate it).
  bool full_steps_ = false;
};

// With a nonlinear body: the loads (every force but the beams') stepped on in increments of
// 1/load_increments, a failed increment halved from the last equilibrium (load control, as
// nonlinear_beam/static_solver.h; Crisfield 1991, §9.2).
void step_loads(EquilibriumResidual& residual, NewtonIteration& newton, const StaticsOptions& options,
                StaticsResult& result) {
  double reached = 0.0, increment = 1.0 / options.load_increments;
  for (int bisections = 0;;) {
    const double target = std::min(1.0, reached + increment);
    const Eigen::VectorXd q0 = residual.state().q;
    if (newton.solve(target) == StaticsStatus::kOk) {
      if (target == 1.0) return;
      reached = target;
      continue;
    }
    if (result.status == StaticsStatus::kFreeMotionUnderLoad || bisections == options.max_bisections) {
      result.message = fmt::format("at {:.4g} of the loads (stepped onto the nonlinear bodies; {:.4g} held, "
                                   "after {} halvings of the step): {}",
                                   target, reached, bisections, result.message);
      return;
    }
    residual.set_q(q0);
    result.status = StaticsStatus::kOk;
    increment *= 0.5;
    ++bisections;
  }
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
  LIMBER_DEMAND(options.load_increments >= 1 && options.max_bisections >= 0);
  EquilibriumResidual residual(model, partition, start);
  StaticsResult result;
  NewtonIteration newton(model, residual, options, result);
  if (model.nonlinear_bodies.empty()) {
    newton.solve(1.0);
  } else {
    step_loads(residual, newton, options, result);
  }
  result.state = residual.state();
  result.lambda = newton.lambda();
  return result;
}

}  // namespace limber::multibody
